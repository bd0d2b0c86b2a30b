#pragma once
// Step 4's optional part, after shading: per-pixel measurements of the shadow map as the camera
// sees it, for comparing providers (uniform vs TSM).
// - Texel footprint: how many screen pixels one shadow-map texel covers, as a length: with J the
//   Jacobian of screen pixel -> shadow texel at the visible surface, 1 / sqrt(|det J|). Above 1
//   a texel is magnified over several pixels (blocky shadow edges); below 1 texels are wasted.
// - Temporal continuity: the hard-shadow visibility of the same world point with this frame's
//   map and with the previous frame's map. With a static scene and light, any difference is
//   flicker the provider adds as the camera moves (a uniform map never changes, so it adds none).

#include <gpu/Gl.h>
#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>
#include <renderer/passes/ShadowMapPass.h>
#include <renderer/passes/SurfacesPass.h>
#include <renderer/scene/GpuScene.h>

namespace fl {

class ShadowDiagnosticsPass {
  public:
    explicit ShadowDiagnosticsPass(const gl::ShaderLibrary& shaders);
    /// Sets the output's size; the output and the map copy are allocated by the first
    /// execute(), so a renderer that never measures holds neither.
    void resize(int width, int height);
    /// Forgets the previous frame's map (the next frame compares with itself).
    void reset() { hasPrevious_ = false; }

    struct Inputs {
        const SurfacesPass::Outputs& surfaces; // the frame's visible surfaces (step 2)
        const CameraView& camera;
        const Light& light;
        const ShadowMapPass::Outputs& shadow;
    };
    struct Outputs {
        /// RGBA32F per pixel: R texel footprint in screen pixels (0 where no receiver is visible:
        /// a receiver is a surface inside the map that faces the light, N.L > 0), G view depth
        /// (distance along the view axis; 0 for background), B hard visibility with this frame's
        /// map, A with the previous frame's map (= B on the first frame). Always finite.
        const gl::Texture& diagnostics;
    };
    /// Measures this frame, then keeps a copy of the shadow map for the next frame.
    Outputs execute(const Inputs& in);

  private:
    gl::Program program_;
    gl::VertexArray emptyVao_;
    gl::Texture output_, previousMap_;
    gl::Framebuffer fbo_;
    glm::mat4 previousLightViewProj_{1.0f}, previousWarp_{1.0f};
    bool hasPrevious_ = false;
    int width_ = 0, height_ = 0;
};

} // namespace fl
