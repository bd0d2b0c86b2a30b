#include <renderer/passes/ShadowMapPass.h>

namespace fl {

ShadowMapPass::ShadowMapPass(const ShaderLibrary& shaders)
    : program_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "shadow_depth.vert.glsl"},
                                            {GL_FRAGMENT_SHADER, "shadow_depth.frag.glsl"}})) {}

void ShadowMapPass::resize(int size) {
    if (depth_ && depth_.width() == size) return;
    depth_ = gl::Texture(GL_DEPTH_COMPONENT32F, size, size);
    // Hard shadows compare one texel: NEAREST keeps the test binary (LINEAR would give
    // hardware 2x2 PCF, a different method).
    depth_.setSampling(GL_NEAREST, GL_NEAREST);
    glTextureParameteri(depth_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(depth_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    fbo_ = gl::Framebuffer::create();
    fbo_.attach(GL_DEPTH_ATTACHMENT, depth_);
    fbo_.setDrawBuffers(0);
    fbo_.check("shadow map");
}

ShadowMapPass::Outputs ShadowMapPass::execute(const Inputs& in) {
    resize(in.settings.size);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, depth_.width(), depth_.height());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    const float one = 1.0f;
    glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
    // Both faces are drawn: the generated and loaded scenes contain open and double-sided
    // surfaces, and culling either face would let light through them.
    glDisable(GL_CULL_FACE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(in.settings.slopeBias, in.settings.constantBias);
    const glm::mat4 vp = in.light.viewProj();
    program_.set("uLightViewProj", vp);
    in.scene.draw(program_, GpuScene::Uniforms::Geometry);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return {depth_, vp};
}

} // namespace fl
