#include <renderer/io/TextureImage.h>
#include <renderer/passes/SurfaceDecode.h>
#include <renderer/passes/SurfacesPass.h>

#include <cstring>
#include <functional>

namespace fl {

namespace {

// shaders/surface_decode.glsl's matrix (SurfacePositions::bind).
constexpr gl::Uniform<glm::mat4> kSurfaceInverseViewProj{"uSurfaceInverseViewProj"};

// The surfaces pass's own uniforms (forward.vert.glsl, surfaces.*.glsl).
constexpr struct {
    gl::Uniform<glm::mat4> viewProj{"uViewProj"};
    gl::Uniform<glm::mat4> previousViewProj{"uPreviousViewProj"}; // FL_MOTION only
    gl::Uniform<glm::vec2> viewport{"uViewport"};
    gl::Uniform<glm::vec3> lightPosition{"uLightPosition"};
    gl::Uniform<glm::vec3> lightDirection{"uLightDirection"};
    gl::Uniform<int> lightDirectional{"uLightDirectional"};
} kSurfaces;

gl::Program buildProgram(const gl::ShaderLibrary& shaders, bool motion) {
    gl::Program program = gl::Program::build(shaders,
                                             {{GL_VERTEX_SHADER, "forward.vert.glsl"},
                                              {GL_GEOMETRY_SHADER, "surfaces.geom.glsl"},
                                              {GL_FRAGMENT_SHADER, "surfaces.frag.glsl"}},
                                             motion ? std::vector<std::string>{"FL_MOTION 1"}
                                                    : std::vector<std::string>{});
    const auto& u = kSurfaces;
    program.bindUniforms({&u.viewProj, &u.previousViewProj, &u.viewport, &u.lightPosition,
                          &u.lightDirection, &u.lightDirectional});
    return program;
}

} // namespace

void SurfacePositions::bind(gl::BindScope& scope, const gl::Program& program,
                            gl::TextureUnit unit) const {
    scope.texture(unit, depth.id());
    program.set(kSurfaceInverseViewProj, inverseViewProj);
}

void SurfacePositions::bindUniforms(gl::Program& program) {
    program.bindUniforms({&kSurfaceInverseViewProj});
}

FloatImage SurfacePositions::read() const {
    const int w = width(), h = height();
    std::vector<float> raw(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    glGetTextureImage(depth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                      static_cast<GLsizei>(raw.size() * sizeof(float)), raw.data());
    gl::throwIfErrors("surface depth read-back");
    FloatImage out{w, h, 4, std::vector<float>(raw.size() * 4)};
    for (int y = 0; y < h; ++y) // GL row y is file row h - 1 - y
        for (int x = 0; x < w; ++x) {
            const glm::vec4 p = surface::position(raw[static_cast<std::size_t>(y) * w + x], {x, y},
                                                  {w, h}, inverseViewProj);
            std::memcpy(&out.data[(static_cast<std::size_t>(h - 1 - y) * w + x) * 4], &p[0],
                        sizeof(float) * 4);
        }
    return out;
}

FloatImage SurfacesPass::Outputs::readNormals(Normal which) const {
    FloatImage img = readTexture(normals, 4);
    const std::size_t first = which == Normal::Shading ? 0 : 2;
    for (std::size_t i = 0; i < img.data.size(); i += 4) {
        const glm::vec3 n = surface::octDecode({img.data[i + first], img.data[i + first + 1]});
        img.data[i] = n.x;
        img.data[i + 1] = n.y;
        img.data[i + 2] = n.z;
        img.data[i + 3] = 0.0f;
    }
    return img;
}

SurfacesPass::SurfacesPass(const gl::ShaderLibrary& shaders)
    : programs_{buildProgram(shaders, false), buildProgram(shaders, true)} {}

void SurfacesPass::resize(int width, int height) {
    if (depth_ && depth_.width() == width && depth_.height() == height) return;
    normals_ = gl::Texture(GL_RGBA16_SNORM, width, height);
    baseColor_ = gl::Texture(GL_RGBA8, width, height);
    receivers_ = gl::Texture(GL_R8, width, height);
    lift_ = gl::Texture(GL_R32F, width, height);
    motion_ = gl::Texture(GL_RGBA32F, width, height);
    depth_ = gl::Texture(GL_DEPTH_COMPONENT32F, width, height);
    fbos_[0] = gl::Framebuffer::withTargets({&normals_, &baseColor_, &receivers_, &lift_}, &depth_,
                                            "surfaces pass");
    fbos_[1] = gl::Framebuffer::withTargets({&normals_, &baseColor_, &receivers_, &lift_, &motion_},
                                            &depth_, "surfaces pass with motion");
}

SurfacesPass::Outputs SurfacesPass::outputs() const {
    return {depth_,         normals_,
            baseColor_,     receivers_,
            lift_,          motionWritten_ ? &motion_ : nullptr,
            viewProj_,      inverseViewProj_,
            depth_.width(), depth_.height()};
}

void SurfacesPass::Outputs::bindLookup(gl::BindScope& scope) const {
    scope.texture(gl::bind::SurfacesLift, lift.id());
    scope.texture(gl::bind::LookupNormals, normals.id());
}

std::int64_t SurfacesPass::Outputs::bytes() const {
    std::int64_t sum = 0;
    for (const gl::Texture* t : {&depth, &normals, &baseColor, &receivers, &lift, motion})
        if (t) sum += gl::textureBytes(*t);
    return sum;
}

void withReversedDepth(const std::function<void()>& draw) {
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    draw();
    glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
}

SurfacesPass::Outputs SurfacesPass::execute(const Inputs& in) {
    motionWritten_ = in.previousCamera != nullptr;
    const gl::Framebuffer& fbo = fbos_[motionWritten_ ? 1 : 0];
    gl::Program& program = programs_[motionWritten_ ? 1 : 0];
    viewProj_ = surface::reversedViewProj(in.camera.proj, in.camera.view);
    inverseViewProj_ = surface::inverseReversedViewProj(in.camera.proj, in.camera.view);
    // Only what the depth test cannot mark: the receiver flag (read as a whole image by the
    // metrics) and the motion target (read by them without the depth).
    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 2, none);
    if (motionWritten_) glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 4, none);
    glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &surface::kBackgroundDepth);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, depth_.width(), depth_.height());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER); // reversed Z: nearer is larger
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE); // glTF doubleSided and open meshes: both faces are visible
    const auto& u = kSurfaces;
    program.set(u.viewProj, viewProj_);
    if (in.previousCamera)
        program.set(u.previousViewProj, in.previousCamera->proj * in.previousCamera->view);
    program.set(u.viewport, glm::vec2(depth_.width(), depth_.height()));
    program.set(u.lightPosition, in.light.position);
    program.set(u.lightDirection, in.light.direction);
    program.set(u.lightDirectional, in.light.type == Light::Type::Directional ? 1 : 0);
    // Blended surfaces are drawn over the shaded image (ShadingPass, step 4b), not here.
    withReversedDepth(
        [&] { in.scene.draw(program, GpuScene::Uniforms::Material, GpuScene::Surfaces::Solid); });
    glDepthFunc(GL_LESS);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return outputs();
}

} // namespace fl
