#include <renderer/passes/ShadowDiagnosticsPass.h>

namespace fl {

namespace {
// shadow_diagnostics.frag.glsl's own uniforms.
constexpr struct {
    gl::Uniform<glm::mat4> view{"uView"};
    gl::Uniform<float> shadowMapSize{"uShadowMapSize"};
    gl::Uniform<int> hasPrevious{"uHasPrevious"};
    gl::Uniform<glm::mat4> previousLightViewProj{"uPreviousLightViewProj"};
    gl::Uniform<glm::mat4> previousWarp{"uPreviousShadowWarp"};
    gl::Uniform<glm::vec3> lightPosition{"uLightPosition"};
    gl::Uniform<glm::vec3> lightDirection{"uLightDirection"};
    gl::Uniform<int> lightDirectional{"uLightDirectional"};
    gl::Uniform<glm::mat4> invViewProj{"uInvViewProj"};
    gl::Uniform<glm::vec2> viewportSize{"uViewportSize"};
} kDiagnostics;
} // namespace

ShadowDiagnosticsPass::ShadowDiagnosticsPass(const gl::ShaderLibrary& shaders)
    : program_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                            {GL_FRAGMENT_SHADER, "shadow_diagnostics.frag.glsl"}})),
      emptyVao_(gl::VertexArray::create()) {
    const auto& u = kDiagnostics;
    program_.bindUniforms({&u.view, &u.shadowMapSize, &u.hasPrevious, &u.previousLightViewProj,
                           &u.previousWarp, &u.lightPosition, &u.lightDirection,
                           &u.lightDirectional, &u.invViewProj, &u.viewportSize});
    bindShadowMapUniforms(program_);
    SurfacePositions::bindUniforms(program_);
}

void ShadowDiagnosticsPass::resize(int width, int height) {
    width_ = width;
    height_ = height;
    // Frames without diagnostics never allocate the output (a 16-byte-a-pixel target); one that
    // asks makes it at this size (execute).
    if (output_ && (output_.width() != width || output_.height() != height)) {
        fbo_ = {};
        output_ = {};
    }
}

ShadowDiagnosticsPass::Outputs ShadowDiagnosticsPass::execute(const Inputs& in) {
    if (!output_) {
        output_ = gl::Texture(GL_RGBA32F, width_, height_);
        fbo_ = gl::Framebuffer::forColor(output_, "shadow diagnostics");
    }
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
    glDisable(GL_DEPTH_TEST);
    const auto& u = kDiagnostics;
    program_.set(u.view, in.camera.view);
    program_.set(u.shadowMapSize, static_cast<float>(mapSize));
    program_.set(u.hasPrevious, hasPrevious_ ? 1 : 0);
    program_.set(u.previousLightViewProj, previousLightViewProj_);
    program_.set(u.previousWarp, previousWarp_);
    program_.set(u.lightPosition, in.light.position);
    program_.set(u.lightDirection, in.light.direction);
    program_.set(u.lightDirectional, in.light.type == Light::Type::Directional ? 1 : 0);
    gl::BindScope scope;
    bindShadowMap(scope, program_, in.shadow);
    scope.texture(gl::bind::PreviousShadowMap, previousMap_.id());
    in.surfaces.positions().bind(scope, program_, gl::bind::DiagnosticsSurfacesDepth);
    scope.texture(gl::bind::DiagnosticsSurfacesNormals, in.surfaces.normals.id());
    program_.set(u.invViewProj, glm::inverse(in.camera.proj * in.camera.view));
    program_.set(u.viewportSize, glm::vec2(output_.width(), output_.height()));
    gl::drawFullscreenTriangle(program_, emptyVao_);
    scope.release();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    glCopyImageSubData(in.shadow.depth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, previousMap_.id(),
                       GL_TEXTURE_2D, 0, 0, 0, 0, mapSize, mapSize, 1);
    previousLightViewProj_ = in.shadow.lightViewProj;
    previousWarp_ = in.shadow.warp;
    hasPrevious_ = true;
    return {output_};
}

} // namespace fl
