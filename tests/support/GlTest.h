#pragma once
// Fixture for *_gltest.cpp: one headless EGL context per test program; any GL error recorded by
// the debug callback during a test fails that test.

#include <gpu/Gl.h>
#include <renderer/context/EglContext.h>

#include <gtest/gtest.h>

#include <memory>

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

} // namespace fl::test
