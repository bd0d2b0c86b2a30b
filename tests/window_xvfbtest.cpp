// The window path (GLFW, run under Xvfb by ctest): same renderer, same pixels as headless EGL;
// minimise and resize to tiny sizes are survived.

#include "ImageCompare.h"
#include "TestPaths.h"
#include "TestScenes.h"

#include <renderer/Renderer.h>
#include <renderer/context/EglContext.h>
#include <renderer/context/GlfwWindow.h>
#include <renderer/io/TextureImage.h>
#include <renderer/run/Capture.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <gtest/gtest.h>

namespace fl::test {
namespace {

constexpr int kW = 160, kH = 120;

Scene testScene() {
    return groundAndBox(4.0f, {-1, 0.5f, -1}, {1, 2, 1}, {0.6f, -1, 0.3f});
}

ByteImage renderHeadless(const Scene& scene) {
    auto ctx = EglContext::create();
    const gl::ShaderLibrary shaders;
    Renderer r(shaders, scene, {});
    r.resize(kW, kH);
    r.render(makeCameraView(scene, {}, float(kW) / kH));
    return toSrgb8(readFrame(r).color);
}

TEST(Window, RendersTheSamePixelsAsHeadless) {
    const Scene scene = testScene();
    const ByteImage headless = renderHeadless(scene);

    auto window = GlfwWindow::create({kW, kH, "floodlight test", true});
    const glm::ivec2 fb = window->framebufferSize();
    ASSERT_EQ(fb, glm::ivec2(kW, kH));
    const gl::ShaderLibrary shaders;
    Renderer r(shaders, scene, {});
    r.resize(fb.x, fb.y);
    ByteImage shown;
    for (int frame = 0; frame < 3; ++frame) {
        glfwPollEvents();
        r.render(makeCameraView(scene, {}, float(kW) / kH));
        r.present(fb.x, fb.y);
        if (frame == 2) shown = readDefaultFramebuffer(fb.x, fb.y);
        window->swapBuffers();
    }
    EXPECT_NO_THROW(gl::throwIfErrors("window frames"));
    // The window encodes sRGB in a shader, the headless path on the CPU; both use the same
    // formula, so they may differ by one 8-bit step from float rounding, nowhere by more.
    const Tolerance tol{.maxAbs = 1, .meanAbs = 0.5, .pixelThreshold = 1, .maxPercentOver = 0.0};
    const CompareResult c = compareImages(shown, headless, tol);
    EXPECT_TRUE(c.pass) << c.report;
    if (!c.pass) {
        writePng(outputDir("window") / "window.png", shown);
        writePng(outputDir("window") / "headless.png", headless);
    }
}

TEST(Window, SurvivesMinimiseAndTinySizes) {
    const Scene scene = testScene();
    auto window = GlfwWindow::create({kW, kH, "floodlight test", true});
    const gl::ShaderLibrary shaders;
    Renderer r(shaders, scene, {});
    auto frame = [&] {
        glfwPollEvents();
        const glm::ivec2 fb = window->framebufferSize();
        if (fb.x <= 0 || fb.y <= 0) return false; // minimised: the viewer skips the frame
        r.resize(fb.x, fb.y);
        r.render(makeCameraView(scene, {}, float(fb.x) / float(fb.y)));
        r.present(fb.x, fb.y);
        window->swapBuffers();
        return true;
    };
    EXPECT_TRUE(frame());
    glfwIconifyWindow(window->handle());
    for (int i = 0; i < 3; ++i) frame();
    glfwRestoreWindow(window->handle());
    glfwSetWindowSize(window->handle(), 1, 1);
    for (int i = 0; i < 3; ++i) frame();
    glfwSetWindowSize(window->handle(), kW, kH);
    for (int i = 0; i < 5 && window->framebufferSize() != glm::ivec2(kW, kH); ++i)
        glfwWaitEventsTimeout(0.1);
    EXPECT_TRUE(frame());
    EXPECT_NO_THROW(gl::throwIfErrors("after minimise/resize"));
}

} // namespace
} // namespace fl::test
