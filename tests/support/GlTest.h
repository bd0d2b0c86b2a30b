#pragma once
// Fixture for *_gltest.cpp: one headless EGL context per test program; any GL error recorded by
// the debug callback during a test fails that test.

#include <gpu/Gl.h>
#include <renderer/context/EglContext.h>

#include <gtest/gtest.h>

#include <memory>
#include <string_view>

namespace fl {
struct CameraView;
struct FrameImages;
struct Scene;
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

/// One frame of `scene` from `camera` with `method` at size x size pixels and a mapSize² shadow
/// map (the method's other settings at their defaults), read back.
FrameImages renderFrame(const Scene& scene, const CameraView& camera, std::string_view method,
                        int mapSize, int size);

} // namespace fl::test
