#pragma once
// Orbit and fly camera; the viewer (Viewer.cpp) feeds it mouse and held-key input.

#include <renderer/Renderer.h>
#include <scene/CameraPath.h>

#include <functional>

struct GLFWwindow;

namespace fl::app {

class CameraController {
  public:
    enum class Mode { Orbit, Fly };

    /// Starts from `initial` (its eye and view direction); `sceneRadius` scales speeds.
    CameraController(const CameraView& initial, float sceneRadius, float yfov);

    /// Applies held keys (fly mode) for `dt` seconds.
    void update(GLFWwindow* window, float dt);
    /// The same with held keys reported by `held(GLFW key)` (the window's keys, or a script's).
    void update(const std::function<bool(int)>& held, float dt);
    /// The view for the current pose at `aspect`.
    [[nodiscard]] CameraView view(float aspect) const;
    void reset();
    void toggleMode();
    [[nodiscard]] Mode mode() const { return mode_; }
    /// The current eye and the point it looks at (for recording camera paths).
    [[nodiscard]] CameraKey pose() const;
    [[nodiscard]] float yfov() const { return yfov_; }
    /// Fly speed multiplier (the wheel changes it in fly mode).
    [[nodiscard]] float flySpeed() const { return flySpeed_; }

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
    float flySpeed_ = 1.0f;
    CameraView initial_;
    double prevX_ = 0.0, prevY_ = 0.0;
    bool havePrevious_ = false;
};

} // namespace fl::app
