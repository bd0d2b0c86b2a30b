#include <app/CameraController.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace fl::app {

namespace {
constexpr float kMaxPitch = 1.55f; // just under 90°, so lookAt's up vector stays valid
}

CameraController::CameraController(const CameraView& initial, float sceneRadius, float yfov)
    : radius_(std::max(sceneRadius, 1e-3f)), yfov_(yfov), near_(1e-3f * radius_),
      far_(20.0f * radius_), initial_(initial) {
    reset();
}

void CameraController::reset() {
    const glm::mat4 inv = glm::inverse(initial_.view);
    const glm::vec3 eye = glm::vec3(inv[3]);
    const glm::vec3 fwd = -glm::normalize(glm::vec3(inv[2]));
    lookFrom(eye, fwd);
}

void CameraController::lookFrom(glm::vec3 eye, glm::vec3 fwd) {
    pitch_ = std::asin(std::clamp(fwd.y, -1.0f, 1.0f));
    yaw_ = std::atan2(fwd.x, -fwd.z);
    // Orbit around the point one scene radius ahead (or the original target distance).
    distance_ = radius_;
    target_ = eye + fwd * distance_;
}

glm::vec3 CameraController::forward() const {
    return {std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_),
            -std::cos(pitch_) * std::cos(yaw_)};
}

CameraView CameraController::view(float aspect) const {
    const glm::vec3 eye = target_ - forward() * distance_;
    CameraView v;
    v.eye = eye;
    v.view = glm::lookAt(eye, target_, glm::vec3(0.0f, 1.0f, 0.0f));
    v.proj = glm::perspective(yfov_, aspect, near_, far_);
    return v;
}

void CameraController::toggleMode() {
    mode_ = mode_ == Mode::Orbit ? Mode::Fly : Mode::Orbit;
}

void CameraController::onCursor(double x, double y, bool rotate, bool pan) {
    if (!havePrevious_) {
        prevX_ = x;
        prevY_ = y;
        havePrevious_ = true;
        return;
    }
    const float dx = static_cast<float>(x - prevX_);
    const float dy = static_cast<float>(y - prevY_);
    prevX_ = x;
    prevY_ = y;
    if (rotate) {
        const glm::vec3 eye = target_ - forward() * distance_;
        yaw_ += dx * 0.005f;
        pitch_ = std::clamp(pitch_ - dy * 0.005f, -kMaxPitch, kMaxPitch);
        // Orbit turns around the target; fly (mouse look) turns around the eye.
        if (mode_ == Mode::Fly) target_ = eye + forward() * distance_;
    } else if (pan) {
        const glm::vec3 right = glm::normalize(glm::cross(forward(), glm::vec3(0, 1, 0)));
        const glm::vec3 up = glm::cross(right, forward());
        const float scale = distance_ * 0.0015f;
        target_ += (-dx * right + dy * up) * scale;
    }
}

void CameraController::onScroll(double dy) {
    if (mode_ == Mode::Orbit) {
        distance_ = std::clamp(distance_ * std::pow(0.9f, static_cast<float>(dy)), 1e-3f * radius_,
                               10.0f * radius_);
    } else {
        // Fly: the wheel sets the speed (x1.25 per notch) rather than moving.
        flySpeed_ =
            std::clamp(flySpeed_ * std::pow(1.25f, static_cast<float>(dy)), 1.0f / 64.0f, 64.0f);
    }
}

CameraKey CameraController::pose() const {
    return {target_ - forward() * distance_, target_};
}

void CameraController::update(GLFWwindow* window, float dt) {
    update([window](int key) { return glfwGetKey(window, key) == GLFW_PRESS; }, dt);
}

void CameraController::update(const std::function<bool(int)>& held, float dt) {
    if (mode_ != Mode::Fly) return;
    const bool fast = held(GLFW_KEY_LEFT_SHIFT) || held(GLFW_KEY_RIGHT_SHIFT);
    const float speed = radius_ * 0.5f * flySpeed_ * (fast ? 4.0f : 1.0f) * dt;
    const glm::vec3 f = forward();
    const glm::vec3 right = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0)));
    glm::vec3 move(0.0f);
    if (held(GLFW_KEY_W)) move += f;
    if (held(GLFW_KEY_S)) move -= f;
    if (held(GLFW_KEY_D)) move += right;
    if (held(GLFW_KEY_A)) move -= right;
    if (held(GLFW_KEY_E)) move.y += 1.0f;
    if (held(GLFW_KEY_Q)) move.y -= 1.0f;
    target_ += move * speed;
}

} // namespace fl::app
