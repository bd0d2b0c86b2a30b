#pragma once
// Fixture for *_gltest.cpp: one headless EGL context per test program; any GL error recorded by
// the debug callback during a test fails that test.

#include <gpu/Gl.h>
#include <jfa/Grid.h>
#include <renderer/context/EglContext.h>

#include <glm/vec3.hpp>
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <string_view>

namespace fl {
struct CameraView;
struct FrameImages;
struct RenderSettings;
struct Scene;
namespace gl {
class ShaderLibrary;
}
} // namespace fl

namespace fl::test {

class GlTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite();
    void SetUp() override;
    void TearDown() override;
    /// The shared context (created on first use).
    static EglContext& context();

  private:
    static std::unique_ptr<EglContext> context_;
};

/// The shader library of the test program's context, shared by every test in it: its pool keeps
/// the programs a test's many renderers build (compiling is most of a GL test's time on llvmpipe).
/// Only for GlTest's context (a program of one context is not valid in another).
const gl::ShaderLibrary& testShaders();

/// Pixel (x, y from the top) where world point p lands in a w x h frame, or false if off-screen.
bool project(const CameraView& cam, int w, int h, glm::vec3 p, int& x, int& y);

/// One frame of `scene` from `camera` with `method` at size x size pixels and a mapSize² shadow
/// map (the method's other settings at their defaults), read back.
FrameImages renderFrame(const Scene& scene, const CameraView& camera, std::string_view method,
                        int mapSize, int size);

/// A flooding method's frame: its flooded grid, read back, and its band.
struct FloodRun {
    jfa::Grid grid;
    bool banded = false;      // the kernel ran over a band
    double activeShare = 1.0; // of the grid's texels
};

/// One frame of `scene` from `camera` with `settings` (a flooding method) at width x height.
FloodRun renderFlood(const gl::ShaderLibrary& shaders, const Scene& scene, const CameraView& camera,
                     const RenderSettings& settings, int width, int height);

/// renderFlood with `--flood-region band`, then with `full`: the pair band-limited flooding
/// must make equal.
std::array<FloodRun, 2> renderBandAndFull(const gl::ShaderLibrary& shaders, const Scene& scene,
                                          const CameraView& camera, RenderSettings settings,
                                          int width, int height);

} // namespace fl::test
