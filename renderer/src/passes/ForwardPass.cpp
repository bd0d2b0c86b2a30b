#include <renderer/passes/ForwardPass.h>
#include <renderer/soft/PenumbraCriterion.h>

#include <stdexcept>

namespace fl {

ForwardPass::ForwardPass(const ShaderLibrary& shaders)
    : program_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "forward.vert.glsl"},
                                            {GL_FRAGMENT_SHADER, "forward.frag.glsl"}})),
      penumbraProgram_(gl::Program::build(
          shaders,
          {{GL_VERTEX_SHADER, "forward.vert.glsl"}, {GL_FRAGMENT_SHADER, "forward.frag.glsl"}},
          {"SOFT_PENUMBRA_MAP 1"})),
      eyeProgram_(gl::Program::build(
          shaders,
          {{GL_VERTEX_SHADER, "forward.vert.glsl"}, {GL_FRAGMENT_SHADER, "forward.frag.glsl"}},
          {"SOFT_EYE_VISIBILITY 1"})) {}

void ForwardPass::resize(int width, int height) {
    if (color_ && color_.width() == width && color_.height() == height) return;
    color_ = gl::Texture(GL_RGBA16F, width, height);
    visibility_ = gl::Texture(GL_R32F, width, height);
    receivers_ = gl::Texture(GL_R8, width, height);
    depth_ = gl::Texture(GL_DEPTH_COMPONENT32F, width, height);
    fbo_ = gl::Framebuffer::create();
    fbo_.attach(GL_COLOR_ATTACHMENT0, color_);
    fbo_.attach(GL_COLOR_ATTACHMENT1, visibility_);
    fbo_.attach(GL_COLOR_ATTACHMENT2, receivers_);
    fbo_.attach(GL_DEPTH_ATTACHMENT, depth_);
    fbo_.setDrawBuffers(3);
    fbo_.check("forward pass");
}

ForwardPass::Outputs ForwardPass::execute(const Inputs& in) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, color_.width(), color_.height());
    // Sky colour in linear space; alpha 0 marks background for compositing and statistics.
    const float sky[4] = {0.50f, 0.64f, 0.82f, 0.0f};
    const float lit[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float far = 1.0f;
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, sky);
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 1, lit);
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 2, none);
    glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &far);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE); // glTF doubleSided and open meshes: shade both faces

    const bool penumbra = in.penumbraMap != nullptr;
    if (penumbra && in.disk == nullptr)
        throw std::invalid_argument("ForwardPass: a penumbra map needs the disk light");
    const bool eye = in.eyeVisibility != nullptr;
    const gl::Program& program = eye ? eyeProgram_ : penumbra ? penumbraProgram_ : program_;
    program.set("uViewProj", in.camera.proj * in.camera.view);
    program.set("uEye", in.camera.eye);
    program.set("uLightPosition", in.light.position);
    program.set("uLightDirection", in.light.direction);
    program.set("uLightDirectional", in.light.type == Light::Type::Directional ? 1 : 0);
    program.set("uLightColor", in.light.color);
    bindShadowMap(program, in.shadow);
    if (eye) {
        glBindTextureUnit(3, in.eyeVisibility->id());
    } else if (penumbra) {
        setDiskLightUniforms(program, *in.disk);
        glBindTextureUnit(3, in.penumbraMap->id());
    }
    in.scene.draw(program, GpuScene::Uniforms::Material);
    glBindTextureUnit(0, 0);
    glBindTextureUnit(1, 0);
    glBindTextureUnit(3, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return {color_, visibility_, receivers_};
}

PresentPass::PresentPass(const ShaderLibrary& shaders)
    : program_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                            {GL_FRAGMENT_SHADER, "present.frag.glsl"}})),
      emptyVao_(gl::VertexArray::create()) {}

void PresentPass::execute(const gl::Texture& color, int framebufferWidth, int framebufferHeight) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, framebufferWidth, framebufferHeight);
    glDisable(GL_DEPTH_TEST);
    glBindTextureUnit(0, color.id());
    gl::drawFullscreenTriangle(program_, emptyVao_);
    glBindTextureUnit(0, 0);
}

} // namespace fl
