#pragma once
// Step 4 of a frame: shading, shared by every shadow method. A fullscreen pass over the surfaces
// of step 2 applies the method's visibility (step 3), giving linear colour; the visibility itself
// is the method's target (1 on background: every method writes that), not copied here. Step 4b
// draws the scene's alphaMode BLEND surfaces over that colour (not into the visibility: they are
// not among the surfaces a method shades).
// PresentPass is step 6 in a window: the colour to the default framebuffer, sRGB-encoded (the
// caller draws step 5 over it before the buffer swap).

#include <gpu/Gl.h>
#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>
#include <renderer/passes/SurfacesPass.h>
#include <renderer/scene/GpuScene.h>
#include <scene/Scene.h>

namespace fl {

class ShadingPass {
  public:
    explicit ShadingPass(const gl::ShaderLibrary& shaders);
    /// (Re)allocates the colour target.
    void resize(int width, int height);

    struct Inputs {
        const SurfacesPass::Outputs& surfaces;
        const Light& light;
        const gl::Texture& visibility; // the method's, R32F, the frame's size
        const GpuScene& scene;         // for step 4b
        const CameraView& camera;
    };
    struct Outputs {
        const gl::Texture& color; // RGBA16F linear; alpha 0 where nothing was drawn
    };
    Outputs execute(const Inputs& in);

  private:
    /// Step 4b: the blended surfaces over color_, depth-tested against step 2's depth.
    void drawBlended(const Inputs& in);

    gl::Program program_;
    gl::Program blended_;
    gl::VertexArray emptyVao_;
    gl::Texture color_;
    gl::Framebuffer fbo_;
    gl::Framebuffer blendFbo_; // color_ and the surfaces' depth, built when first needed
    GLuint blendDepth_ = 0;    // the depth texture blendFbo_ holds (SurfacesPass may realloc it)
};

class PresentPass {
  public:
    explicit PresentPass(const gl::ShaderLibrary& shaders);
    void execute(const gl::Texture& color, int framebufferWidth, int framebufferHeight);

  private:
    gl::Program program_;
    gl::VertexArray emptyVao_;
};

} // namespace fl
