#include <renderer/passes/SurfacesPass.h>

namespace fl {

namespace {
gl::Program buildProgram(const gl::ShaderLibrary& shaders, bool motion) {
    return gl::Program::build(
        shaders,
        {{GL_VERTEX_SHADER, "forward.vert.glsl"}, {GL_FRAGMENT_SHADER, "surfaces.frag.glsl"}},
        motion ? std::vector<std::string>{"FL_MOTION 1"} : std::vector<std::string>{});
}
} // namespace

SurfacesPass::SurfacesPass(const gl::ShaderLibrary& shaders)
    : programs_{buildProgram(shaders, false), buildProgram(shaders, true)} {}

void SurfacesPass::resize(int width, int height) {
    if (position_ && position_.width() == width && position_.height() == height) return;
    position_ = gl::Texture(GL_RGBA32F, width, height);
    normal_ = gl::Texture(GL_RGBA32F, width, height);
    plane_ = gl::Texture(GL_RGBA32F, width, height);
    baseColor_ = gl::Texture(GL_RGBA32F, width, height);
    receivers_ = gl::Texture(GL_R8, width, height);
    motion_ = gl::Texture(GL_RGBA32F, width, height);
    depth_ = gl::Texture(GL_DEPTH_COMPONENT32F, width, height);
    fbos_[0] = gl::Framebuffer::withTargets(
        {&position_, &normal_, &plane_, &baseColor_, &receivers_}, &depth_, "surfaces pass");
    fbos_[1] = gl::Framebuffer::withTargets(
        {&position_, &normal_, &plane_, &baseColor_, &receivers_, &motion_}, &depth_,
        "surfaces pass with motion");
}

SurfacesPass::Outputs SurfacesPass::outputs() const {
    return {position_,
            normal_,
            plane_,
            baseColor_,
            receivers_,
            depth_,
            motionWritten_ ? &motion_ : nullptr,
            position_.width(),
            position_.height()};
}

std::int64_t SurfacesPass::Outputs::bytes() const {
    std::int64_t sum = 0;
    for (const gl::Texture* t :
         {&position, &normal, &plane, &baseColor, &receivers, &depth, motion})
        if (t) sum += gl::textureBytes(*t);
    return sum;
}

SurfacesPass::Outputs SurfacesPass::execute(const Inputs& in) {
    motionWritten_ = in.previousCamera != nullptr;
    const gl::Framebuffer& fbo = fbos_[motionWritten_ ? 1 : 0];
    gl::Program& program = programs_[motionWritten_ ? 1 : 0];
    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float far = 1.0f;
    for (GLint i = 0; i < (motionWritten_ ? 6 : 5); ++i)
        glClearNamedFramebufferfv(fbo.id(), GL_COLOR, i, none);
    glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &far);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, position_.width(), position_.height());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE); // glTF doubleSided and open meshes: both faces are visible
    program.set("uViewProj", in.camera.proj * in.camera.view);
    if (in.previousCamera)
        program.set("uPreviousViewProj", in.previousCamera->proj * in.previousCamera->view);
    program.set("uViewport", glm::vec2(position_.width(), position_.height()));
    program.set("uLightPosition", in.light.position);
    program.set("uLightDirection", in.light.direction);
    program.set("uLightDirectional", in.light.type == Light::Type::Directional ? 1 : 0);
    // Blended surfaces are drawn over the shaded image (ShadingPass, step 4b), not here.
    in.scene.draw(program, GpuScene::Uniforms::Material, GpuScene::Surfaces::Solid);
    glBindTextureUnit(0, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return outputs();
}

} // namespace fl
