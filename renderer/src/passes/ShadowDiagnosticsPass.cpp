#include <renderer/passes/ShadowDiagnosticsPass.h>

namespace fl {

ShadowDiagnosticsPass::ShadowDiagnosticsPass(const ShaderLibrary& shaders)
    : program_(
          gl::Program::build(shaders, {{GL_VERTEX_SHADER, "forward.vert.glsl"},
                                       {GL_FRAGMENT_SHADER, "shadow_diagnostics.frag.glsl"}})) {}

void ShadowDiagnosticsPass::resize(int width, int height) {
    if (output_ && output_.width() == width && output_.height() == height) return;
    output_ = gl::Texture(GL_RGBA32F, width, height);
    depth_ = gl::Texture(GL_DEPTH_COMPONENT32F, width, height);
    fbo_ = gl::Framebuffer::create();
    fbo_.attach(GL_COLOR_ATTACHMENT0, output_);
    fbo_.attach(GL_DEPTH_ATTACHMENT, depth_);
    fbo_.setDrawBuffers(1);
    fbo_.check("shadow diagnostics");
}

ShadowDiagnosticsPass::Outputs ShadowDiagnosticsPass::execute(const Inputs& in) {
    const int mapSize = in.shadow.depth.width();
    if (!previousMap_ || previousMap_.width() != mapSize) {
        previousMap_ = gl::Texture(GL_DEPTH_COMPONENT32F, mapSize, mapSize);
        previousMap_.setSampling(GL_NEAREST, GL_NEAREST);
        glTextureParameteri(previousMap_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTextureParameteri(previousMap_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        hasPrevious_ = false;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, output_.width(), output_.height());
    const float background[4] = {0.0f, 0.0f, 1.0f, 1.0f};
    const float far = 1.0f;
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, background);
    glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &far);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);

    program_.set("uViewProj", in.camera.proj * in.camera.view);
    program_.set("uView", in.camera.view);
    program_.set("uShadowMapSize", static_cast<float>(mapSize));
    program_.set("uHasPrevious", hasPrevious_ ? 1 : 0);
    program_.set("uPreviousLightViewProj", previousLightViewProj_);
    program_.set("uPreviousShadowWarp", previousWarp_);
    program_.set("uLightPosition", in.light.position);
    program_.set("uLightDirection", in.light.direction);
    program_.set("uLightDirectional", in.light.type == Light::Type::Directional ? 1 : 0);
    bindShadowMap(program_, in.shadow);
    glBindTextureUnit(2, previousMap_.id());
    in.scene.draw(program_, GpuScene::Uniforms::Material); // for uNormalMatrix
    glBindTextureUnit(0, 0);
    glBindTextureUnit(1, 0);
    glBindTextureUnit(2, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    glCopyImageSubData(in.shadow.depth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, previousMap_.id(),
                       GL_TEXTURE_2D, 0, 0, 0, 0, mapSize, mapSize, 1);
    previousLightViewProj_ = in.shadow.lightViewProj;
    previousWarp_ = in.shadow.warp;
    hasPrevious_ = true;
    return {output_};
}

} // namespace fl
