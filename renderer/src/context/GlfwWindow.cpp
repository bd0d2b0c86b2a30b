#include <gpu/Gl.h>
#include <renderer/context/GlfwWindow.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <mutex>

namespace fl {

namespace {

std::mutex g_glfwMutex;
std::string g_lastGlfwError;
int g_windows = 0;

void onGlfwError(int code, const char* text) {
    g_lastGlfwError = "GLFW " + std::to_string(code) + ": " + (text ? text : "");
}

} // namespace

bool displayAvailable() {
    const char* x = std::getenv("DISPLAY");
    const char* w = std::getenv("WAYLAND_DISPLAY");
    return (x && *x) || (w && *w);
}

std::unique_ptr<GlfwWindow> GlfwWindow::create(const Options& options) {
    std::lock_guard lock(g_glfwMutex);
    glfwSetErrorCallback(onGlfwError);
    if (g_windows == 0 && !glfwInit())
        throw gl::GlError("cannot open a window: " + g_lastGlfwError);
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
    glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
    GLFWwindow* w =
        glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
    if (!w) {
        if (g_windows == 0) glfwTerminate();
        throw gl::GlError("cannot open a GL 4.5 core window: " + g_lastGlfwError);
    }
    ++g_windows;
    std::unique_ptr<GlfwWindow> out(new GlfwWindow());
    out->window_ = w;
    glfwMakeContextCurrent(w);
    glfwSwapInterval(0);
    initialiseCurrentGl("GLFW window");
    out->description_ = describeCurrentGl("GLFW window");
    return out;
}

GlfwWindow::~GlfwWindow() {
    std::lock_guard lock(g_glfwMutex);
    if (window_) glfwDestroyWindow(window_);
    if (--g_windows == 0) glfwTerminate();
}

void GlfwWindow::makeCurrent() {
    glfwMakeContextCurrent(window_);
}

glm::ivec2 GlfwWindow::framebufferSize() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {w, h};
}

bool GlfwWindow::shouldClose() const {
    return glfwWindowShouldClose(window_) != 0;
}

void GlfwWindow::swapBuffers() {
    glfwSwapBuffers(window_);
}

} // namespace fl
