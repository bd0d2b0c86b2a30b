#pragma once
// Orbit and fly camera driven by GLFW input.

#include <renderer/Renderer.h>

struct GLFWwindow;

namespace fl::app {

class CameraController {
  public:
    enum class Mode { Orbit, Fly };

    /// Starts from `initial` (its eye and view direction); `sceneRadius` scales speeds.
    CameraController(const CameraView& initial, float sceneRadius, float yfov);

    /// Installs the GLFW callbacks (the window's user pointer is set to this controller).
    void attach(GLFWwindow* window);
    /// Applies held keys (fly mode) for `dt` seconds.
    void update(GLFWwindow* window, float dt);
    /// The view for the current pose at `aspect`.
    [[nodiscard]] CameraView view(float aspect) const;
    void reset();
    void toggleMode();
    [[nodiscard]] Mode mode() const { return mode_; }

    // Input events (also used by tests without a window).
    void onCursor(double x, double y, bool rotate, bool pan);
    void onScroll(double dy);
    void releaseCursor() { havePrevious_ = false; }

  private:
    void lookFrom(glm::vec3 eye, glm::vec3 forward);
    [[nodiscard]] glm::vec3 forward() const;

    Mode mode_ = Mode::Orbit;
    glm::vec3 target_{0.0f};
    float distance_ = 1.0f;
    float yaw_ = 0.0f, pitch_ = 0.0f; // radians; forward = (cos p sin y, sin p, -cos p cos y)
    float radius_;
    float yfov_;
    float near_, far_;
    CameraView initial_;
    double prevX_ = 0.0, prevY_ = 0.0;
    bool havePrevious_ = false;
};

} // namespace fl::app
