#include <renderer/passes/ShadingPass.h>

namespace fl {

namespace {

// The light as shading.frag.glsl and blended.frag.glsl read it (light.glsl).
struct ShadingLightUniforms {
    gl::Uniform<glm::vec3> position{"uLightPosition"};
    gl::Uniform<glm::vec3> direction{"uLightDirection"};
    gl::Uniform<int> directional{"uLightDirectional"};
    gl::Uniform<glm::vec3> colour{"uLightColor"};
};
constexpr ShadingLightUniforms kShadingLight;
constexpr gl::Uniform<glm::mat4> kBlendedViewProj{"uViewProj"};

void bindShadingLight(gl::Program& program) {
    program.bindUniforms({&kShadingLight.position, &kShadingLight.direction,
                          &kShadingLight.directional, &kShadingLight.colour});
}

void setShadingLight(const gl::Program& program, const Light& light) {
    program.set(kShadingLight.position, light.position);
    program.set(kShadingLight.direction, light.direction);
    program.set(kShadingLight.directional, light.type == Light::Type::Directional ? 1 : 0);
    program.set(kShadingLight.colour, light.color);
}

} // namespace

ShadingPass::ShadingPass(const gl::ShaderLibrary& shaders)
    : program_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                            {GL_FRAGMENT_SHADER, "shading.frag.glsl"}})),
      blended_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "forward.vert.glsl"},
                                            {GL_FRAGMENT_SHADER, "blended.frag.glsl"}})),
      emptyVao_(gl::VertexArray::create()) {
    bindShadingLight(program_);
    SurfacePositions::bindUniforms(program_);
    bindShadingLight(blended_);
    blended_.bindUniforms({&kBlendedViewProj});
}

void ShadingPass::resize(int width, int height) {
    if (color_ && color_.width() == width && color_.height() == height) return;
    color_ = gl::Texture(GL_RGBA16F, width, height);
    fbo_ = gl::Framebuffer::forColor(color_, "shading pass");
    blendFbo_ = {};
    blendDepth_ = 0;
}

void ShadingPass::drawBlended(const Inputs& in) {
    if (!blendFbo_ || blendDepth_ != in.surfaces.depth.id()) {
        blendFbo_ = gl::Framebuffer::withTargets({&color_}, &in.surfaces.depth, "blended pass");
        blendDepth_ = in.surfaces.depth.id();
    }
    glBindFramebuffer(GL_FRAMEBUFFER, blendFbo_.id());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER); // the surfaces' depth is reversed Z (SurfacesPass)
    glDepthMask(GL_FALSE);   // the eye's surfaces stay what step 2 wrote
    glEnable(GL_BLEND);
    // "Over" for the colour; the colour target's alpha (1 = something drawn) becomes 1 under a
    // blended surface too, as the sky's 0 means "nothing here".
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_CULL_FACE);
    blended_.set(kBlendedViewProj, in.surfaces.viewProj);
    setShadingLight(blended_, in.light);
    withReversedDepth([&] {
        in.scene.draw(blended_, GpuScene::Uniforms::Material, GpuScene::Surfaces::Blended);
    });
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
}

ShadingPass::Outputs ShadingPass::execute(const Inputs& in) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, color_.width(), color_.height());
    glDisable(GL_DEPTH_TEST);
    setShadingLight(program_, in.light);
    {
        gl::BindScope scope;
        in.surfaces.positions().bind(scope, program_, gl::bind::SurfacesDepth);
        scope.texture(gl::bind::SurfacesNormals, in.surfaces.normals.id())
            .texture(gl::bind::SurfacesBaseColor, in.surfaces.baseColor.id())
            .texture(gl::bind::Visibility, in.visibility.id());
        gl::drawFullscreenTriangle(program_, emptyVao_);
    }
    if (in.scene.hasBlended()) drawBlended(in);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return {color_};
}

PresentPass::PresentPass(const gl::ShaderLibrary& shaders)
    : program_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                            {GL_FRAGMENT_SHADER, "present.frag.glsl"}})),
      emptyVao_(gl::VertexArray::create()) {}

void PresentPass::execute(const gl::Texture& color, int framebufferWidth, int framebufferHeight) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, framebufferWidth, framebufferHeight);
    glDisable(GL_DEPTH_TEST);
    gl::BindScope scope;
    scope.texture(gl::bind::PresentColor, color.id());
    gl::drawFullscreenTriangle(program_, emptyVao_);
}

} // namespace fl
