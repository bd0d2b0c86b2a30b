#include "GlTest.h"

#include <renderer/Renderer.h>
#include <renderer/io/Capture.h>

#include <cstdlib>

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

FrameImages renderFrame(const Scene& scene, const CameraView& camera, std::string_view method,
                        int mapSize, int size) {
    const gl::ShaderLibrary shaders;
    RenderSettings settings;
    settings.shadow.size = mapSize;
    settings.method = std::string(method);
    Renderer r(shaders, scene, settings);
    r.resize(size, size);
    r.render(camera);
    return readFrame(r);
}

} // namespace fl::test
