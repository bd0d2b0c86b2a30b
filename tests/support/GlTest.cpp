#include "GlTest.h"

#include <renderer/Renderer.h>
#include <renderer/run/Capture.h>

#include <jfa_gl/GlKernel.h>

#include <cstdlib>
#include <stdexcept>

namespace fl::test {

std::unique_ptr<EglContext> GlTest::context_;

void GlTest::SetUpTestSuite() {
    // Tests measure today's shaders, not a cache of yesterday's (also set by the ctest presets).
    ::setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
    if (!context_) context_ = EglContext::create(true);
}

EglContext& GlTest::context() {
    SetUpTestSuite();
    return *context_;
}

void GlTest::SetUp() {
    context().makeCurrent();
    // Errors left by an earlier test must not be blamed on this one.
    try {
        gl::throwIfErrors("before test");
    } catch (const gl::GlError&) {
    }
}

void GlTest::TearDown() {
    try {
        gl::throwIfErrors("test");
    } catch (const gl::GlError& e) {
        ADD_FAILURE() << e.what();
    }
}

const gl::ShaderLibrary& testShaders() {
    // Destroyed at exit before the context (constructed after it), which is then still current.
    static const gl::ShaderLibrary shaders;
    return shaders;
}

bool project(const CameraView& cam, int w, int h, glm::vec3 p, int& x, int& y) {
    const glm::vec4 clip = cam.proj * cam.view * glm::vec4(p, 1.0f);
    if (clip.w <= 0.0f) return false;
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    x = static_cast<int>((ndc.x * 0.5f + 0.5f) * static_cast<float>(w));
    y = static_cast<int>((0.5f - ndc.y * 0.5f) * static_cast<float>(h));
    return x >= 0 && y >= 0 && x < w && y < h;
}

FrameImages renderFrame(const Scene& scene, const CameraView& camera, std::string_view method,
                        int mapSize, int size) {
    const gl::ShaderLibrary& shaders = testShaders();
    RenderSettings settings;
    settings.shadow.size = mapSize;
    settings.method = std::string(method);
    Renderer r(shaders, scene, settings);
    r.resize(size, size);
    r.render(camera);
    return readFrame(r);
}

FloodRun renderFlood(const gl::ShaderLibrary& shaders, const Scene& scene, const CameraView& camera,
                     const RenderSettings& settings, int width, int height) {
    Renderer r(shaders, scene, settings);
    r.resize(width, height);
    r.render(camera);
    const FloodFrame* flood = r.flood();
    if (!flood || !flood->flooded || !flood->kernel)
        throw std::invalid_argument("renderFlood: " + settings.method + " does not flood");
    return {readFloodGrid(*flood, *flood->flooded), flood->kernel->lastRunBanded(),
            flood->kernel->activeShare()};
}

std::array<FloodRun, 2> renderBandAndFull(const gl::ShaderLibrary& shaders, const Scene& scene,
                                          const CameraView& camera, RenderSettings settings,
                                          int width, int height) {
    std::array<FloodRun, 2> out;
    for (int i = 0; i < 2; ++i) {
        settings.options.set(floodRegionOption().flag, i == 0 ? "band" : "full");
        out[static_cast<std::size_t>(i)] =
            renderFlood(shaders, scene, camera, settings, width, height);
    }
    return out;
}

} // namespace fl::test
