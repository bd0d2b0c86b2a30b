#pragma once
// Headless GL 4.5 core context through EGL: EGL_EXT_platform_device first, then
// EGL_MESA_platform_surfaceless. Rendering goes into FBOs (there is no default framebuffer).

#include <renderer/context/GlContext.h>

#include <memory>

namespace fl {

class EglContext final : public GlContext {
  public:
    /// Creates the context and makes it current; throws fl::gl::GlError with every attempt's
    /// failure reason if no platform gives a GL 4.5 core context.
    static std::unique_ptr<EglContext> create(bool debug = true);
    ~EglContext() override;

    void makeCurrent() override;
    [[nodiscard]] std::string description() const override { return description_; }

  private:
    EglContext() = default;
    void* display_ = nullptr;
    void* context_ = nullptr;
    std::string description_;
};

} // namespace fl
