#include <renderer/passes/SurfacesPass.h>

namespace fl {

SurfacesPass::SurfacesPass(const gl::ShaderLibrary& shaders)
    : program_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "forward.vert.glsl"},
                                            {GL_FRAGMENT_SHADER, "surfaces.frag.glsl"}})) {}

void SurfacesPass::resize(int width, int height) {
    if (position_ && position_.width() == width && position_.height() == height) return;
    position_ = gl::Texture(GL_RGBA32F, width, height);
    normal_ = gl::Texture(GL_RGBA32F, width, height);
    plane_ = gl::Texture(GL_RGBA32F, width, height);
    baseColor_ = gl::Texture(GL_RGBA32F, width, height);
    receivers_ = gl::Texture(GL_R8, width, height);
    motion_ = gl::Texture(GL_RGBA32F, width, height);
    depth_ = gl::Texture(GL_DEPTH_COMPONENT32F, width, height);
    fbo_ = gl::Framebuffer::withTargets(
        {&position_, &normal_, &plane_, &baseColor_, &receivers_, &motion_}, &depth_,
        "surfaces pass");
}

SurfacesPass::Outputs SurfacesPass::outputs() const {
    return {position_,         normal_,           plane_, baseColor_, receivers_, depth_, motion_,
            position_.width(), position_.height()};
}

SurfacesPass::Outputs SurfacesPass::execute(const Inputs& in) {
    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float far = 1.0f;
    for (GLint i = 0; i < 6; ++i) glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, i, none);
    glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &far);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, position_.width(), position_.height());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE); // glTF doubleSided and open meshes: both faces are visible
    program_.set("uViewProj", in.camera.proj * in.camera.view);
    program_.set("uPreviousViewProj", in.previousCamera.proj * in.previousCamera.view);
    program_.set("uViewport", glm::vec2(position_.width(), position_.height()));
    program_.set("uLightPosition", in.light.position);
    program_.set("uLightDirection", in.light.direction);
    program_.set("uLightDirectional", in.light.type == Light::Type::Directional ? 1 : 0);
    // Blended surfaces are drawn over the shaded image (ShadingPass, step 4b), not here.
    in.scene.draw(program_, GpuScene::Uniforms::Material, GpuScene::Surfaces::Solid);
    glBindTextureUnit(0, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return outputs();
}

} // namespace fl
