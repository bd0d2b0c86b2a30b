#include "CameraController.h"
#include "Commands.h"

#include <renderer/GlfwWindow.h>
#include <renderer/ImageIO.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <iostream>
#include <sstream>

namespace fl::app {

int runViewer(const SceneOptions& o, int width, int height, int frames,
              const std::string& screenshot) {
    const Scene scene = loadScene(o);
    const CameraView initial = initialCamera(scene, o, width, height);
    std::unique_ptr<GlfwWindow> window;
    try {
        window = GlfwWindow::create({width, height, "Floodlight", true});
    } catch (const gl::GlError& e) {
        throw NoWindow(e.what());
    }
    std::cout << "context: " << window->description() << "\n"
              << "scene: " << scene.source << " (" << scene.triangleCount() << " triangles)\n"
              << "controls: left drag orbit/look, right drag pan, wheel zoom, Tab orbit<->fly, "
                 "WASD/QE fly, Shift fast, R reset, T uniform<->TSM shadow map, Esc quit\n";
    const ShaderLibrary shaders = makeShaderLibrary(o);
    Renderer renderer(shaders, scene, makeRenderSettings(o));
    const float yfov = 2.0f * std::atan(1.0f / initial.proj[1][1]);
    CameraController controller(initial, scene.bounds.radius(), yfov);
    controller.attach(window->handle());

    double last = glfwGetTime(), titleTime = last;
    bool providerKeyDown = false;
    int frame = 0;
    glm::ivec2 size{0};
    while (!window->shouldClose() && (frames <= 0 || frame < frames)) {
        glfwPollEvents();
        size = window->framebufferSize();
        if (size.x <= 0 || size.y <= 0) { // minimised: nothing to draw until restored
            glfwWaitEventsTimeout(0.1);
            continue;
        }
        const double now = glfwGetTime();
        controller.update(window->handle(), static_cast<float>(now - last));
        // T switches the shadow-map provider on the key's press, not while it is held.
        const bool tDown = glfwGetKey(window->handle(), GLFW_KEY_T) == GLFW_PRESS;
        if (tDown && !providerKeyDown) {
            RenderSettings settings = renderer.settings();
            settings.shadow.provider = settings.shadow.provider == ShadowMapProvider::Uniform
                                           ? ShadowMapProvider::Tsm
                                           : ShadowMapProvider::Uniform;
            renderer.setSettings(settings);
            std::cout << "shadow map: " << providerName(settings.shadow.provider) << "\n";
        }
        providerKeyDown = tDown;
        last = now;
        renderer.resize(size.x, size.y);
        renderer.render(controller.view(static_cast<float>(size.x) / static_cast<float>(size.y)));
        renderer.present(size.x, size.y);
        if (frames > 0 && frame + 1 == frames && !screenshot.empty()) {
            writePng(screenshot, readDefaultFramebuffer(size.x, size.y));
            std::cout << "wrote " << screenshot << "\n";
        }
        window->swapBuffers();
        ++frame;
        if (now - titleTime > 0.5) {
            std::ostringstream title;
            title.precision(1);
            title << std::fixed << "Floodlight - "
                  << (controller.mode() == CameraController::Mode::Orbit ? "orbit" : "fly") << " - "
                  << providerName(renderer.settings().shadow.provider) << " shadow map - "
                  << renderer.timer().frameMs() << " ms/frame";
            glfwSetWindowTitle(window->handle(), title.str().c_str());
            titleTime = now;
        }
    }
    return 0;
}

Runner addViewCommand(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("view", "Open a scene in an interactive window");
    struct State {
        SceneOptions scene;
        int width = 1024, height = 768, frames = 0;
        std::string screenshot;
    };
    auto s = std::make_shared<State>();
    addSceneOptions(*cmd, s->scene, false);
    addSizeOptions(*cmd, s->width, s->height);
    cmd->add_option("--frames", s->frames, "Close after this many frames (0 = run until closed)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--screenshot", s->screenshot, "With --frames: save the last frame as PNG");
    return [s] {
        try {
            return runViewer(s->scene, s->width, s->height, s->frames, s->screenshot);
        } catch (const NoWindow& e) {
            throw InputError(std::string("cannot open a window: ") + e.what());
        }
    };
}

} // namespace fl::app
