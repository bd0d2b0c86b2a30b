#pragma once
// Step 2 of a frame: forward shading from the camera with the hard shadow-map test. Writes linear
// colour, the light's visibility (1 lit, 0 shadowed) and the light-facing receiver mask per pixel.

#include <gpu/Gl.h>
#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>
#include <renderer/GpuScene.h>
#include <renderer/Scene.h>
#include <renderer/passes/ShadowMapPass.h>
#include <renderer/soft/DiskLight.h>

namespace fl {

/// What the camera sees with: matrices and eye position.
struct CameraView {
    glm::mat4 view{1.0f};
    glm::mat4 proj{1.0f};
    glm::vec3 eye{0.0f};
};

class ForwardPass {
  public:
    explicit ForwardPass(const ShaderLibrary& shaders);
    /// (Re)allocates the colour, visibility, receiver and depth targets.
    void resize(int width, int height);

    struct Inputs {
        const GpuScene& scene;
        const CameraView& camera;
        const Light& light;
        const ShadowMapPass::Outputs& shadow;
        /// JFA-L / flood-L: the penumbra map (nullptr: hard shadows) and the disk light.
        const gl::Texture* penumbraMap = nullptr;
        const DiskLight* disk = nullptr;
        /// JFA-E / flood-E: the per-pixel visibility of this frame (R32F, the frame's size).
        const gl::Texture* eyeVisibility = nullptr;
    };
    struct Outputs {
        const gl::Texture& color;      // RGBA16F linear; alpha 0 where nothing was drawn
        const gl::Texture& visibility; // R32F in [0,1]; 1 for background
        const gl::Texture& receivers;  // R8: 1 where a surface faces the light, 0 elsewhere
    };
    Outputs execute(const Inputs& in);

  private:
    gl::Program program_;         // hard shadows
    gl::Program penumbraProgram_; // visibility from a penumbra map (SOFT_PENUMBRA_MAP)
    gl::Program eyeProgram_;      // visibility from an eye-space texture (SOFT_EYE_VISIBILITY)
    gl::Texture color_, visibility_, receivers_, depth_;
    gl::Framebuffer fbo_;
};

/// Step 3 in a window: draws a linear colour texture to the default framebuffer, sRGB-encoded.
class PresentPass {
  public:
    explicit PresentPass(const ShaderLibrary& shaders);
    void execute(const gl::Texture& color, int framebufferWidth, int framebufferHeight);

  private:
    gl::Program program_;
    gl::VertexArray emptyVao_;
};

} // namespace fl
