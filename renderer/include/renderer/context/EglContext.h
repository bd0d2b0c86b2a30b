#pragma once
// Headless GL 4.5 core context through EGL: EGL_EXT_platform_device first, then
// EGL_MESA_platform_surfaceless. Rendering goes into FBOs (there is no default framebuffer).
// FLOODLIGHT_EGL_DEVICE=N chooses the N-th enumerated device instead (no fallback).

#include <renderer/context/GlContext.h>

#include <gpu/Gl.h>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fl {

/// The environment variable that chooses the EGL device by index.
inline constexpr const char* kEglDeviceVariable = "FLOODLIGHT_EGL_DEVICE";

/// A device the user named that does not exist, or a value that is not an index: a usage error
/// (commands exit 2), its message listing the devices found.
class EglDeviceError : public gl::GlError {
  public:
    using gl::GlError::GlError;
};

/// The device index FLOODLIGHT_EGL_DEVICE names, or nullopt when unset; throws EglDeviceError for
/// a value that is not an index.
std::optional<std::size_t> chosenEglDevice();

struct EglDeviceInfo {
    std::size_t index;
    std::string renderer; // GL_RENDERER, or why no GL 4.5 core context opens on it
};
/// Every enumerated EGL device with its renderer string (opens a context on each: slow).
std::vector<EglDeviceInfo> listEglDevices();

class EglContext final : public GlContext {
  public:
    /// Creates the context and makes it current; throws fl::gl::GlError with every attempt's
    /// failure reason if no platform gives a GL 4.5 core context, EglDeviceError when
    /// FLOODLIGHT_EGL_DEVICE names no device.
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
