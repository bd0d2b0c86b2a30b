#pragma once
// An interactive window with a GL 4.5 core context (GLFW). The renderer draws into its own FBOs
// and the window only presents the result.

#include <renderer/context/GlContext.h>

#include <memory>
#include <string>

struct GLFWwindow;

namespace fl {

class GlfwWindow final : public GlContext {
  public:
    struct Options {
        int width = 1024;
        int height = 768;
        std::string title = "Floodlight";
        bool visible = true;
    };
    /// Opens the window and makes its context current; throws fl::gl::GlError with GLFW's
    /// reason (e.g. no display) on failure.
    static std::unique_ptr<GlfwWindow> create(const Options& options);
    ~GlfwWindow() override;

    void makeCurrent() override;
    [[nodiscard]] std::string description() const override { return description_; }

    [[nodiscard]] GLFWwindow* handle() const { return window_; }
    /// Framebuffer size in pixels; (0, 0) while minimised.
    [[nodiscard]] glm::ivec2 framebufferSize() const;
    [[nodiscard]] bool shouldClose() const;
    void swapBuffers();

  private:
    GlfwWindow() = default;
    GLFWwindow* window_ = nullptr;
    std::string description_;
};

/// True if a display server seems reachable (DISPLAY or WAYLAND_DISPLAY set).
bool displayAvailable();

} // namespace fl
