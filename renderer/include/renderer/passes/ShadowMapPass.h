#pragma once
// Step 1 of a frame: depth from the light into a square depth texture (uniform shadow map).

#include <gpu/Gl.h>
#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>
#include <renderer/GpuScene.h>

#include <geometry/Framing.h>

namespace fl {

struct ShadowMapSettings {
    int size = 1024;           // texels per side
    float slopeBias = 2.0f;    // glPolygonOffset factor: scales with the depth slope of a triangle
    float constantBias = 2.0f; // glPolygonOffset units: multiples of the smallest depth step
};

class ShadowMapPass {
  public:
    explicit ShadowMapPass(const ShaderLibrary& shaders);
    /// (Re)allocates the depth texture at size x size.
    void resize(int size);

    struct Inputs {
        const GpuScene& scene;
        const geom::ViewVolume& light;
        const ShadowMapSettings& settings;
    };
    struct Outputs {
        const gl::Texture& depth; // DEPTH_COMPONENT32F, compare mode set for sampler2DShadow
        glm::mat4 lightViewProj;
    };
    /// Renders the scene's depth as seen from the light.
    Outputs execute(const Inputs& in);

  private:
    gl::Program program_;
    gl::Texture depth_;
    gl::Framebuffer fbo_;
};

} // namespace fl
