#include <app/Viewer.h>

#include <app/Commands.h>

#include <base/Process.h>
#include <base/Text.h>
#include <gpu/LiveObjects.h>
#include <renderer/io/TextureImage.h>
#include <renderer/run/Capture.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <iostream>
#include <utility>

namespace fl::app {

namespace {

Viewer& self(GLFWwindow* w) {
    return *static_cast<Viewer*>(glfwGetWindowUserPointer(w));
}

float verticalFov(const CameraView& v) {
    return 2.0f * std::atan(1.0f / v.proj[1][1]);
}

} // namespace

std::vector<std::string> cycledMethods() {
    std::vector<std::string> out;
    for (const MethodDescriptor& m : methodTable())
        if (m.cycles) out.emplace_back(m.name);
    return out;
}

Viewer::Viewer(const ViewerOptions& options) : options_(options), showHud_(options.hud) {
    if (!options_.script.empty()) {
        try {
            script_.emplace(readInputScript(options_.script));
        } catch (const std::runtime_error& e) {
            throw InputError(e.what());
        }
    }
    scene_ = loadScene(options_.scene);
    const CameraView initial =
        initialCamera(scene_, options_.scene, options_.width, options_.height);
    if (const CameraSpec spec = makeCameraSpec(options_.scene); spec.kind == CameraSpec::Kind::Gltf)
        cameraIndex_ = spec.gltfIndex;
    else if (spec.kind == CameraSpec::Kind::Default && !scene_.cameras.empty())
        cameraIndex_ = 0;
    try {
        window_ = GlfwWindow::create({options_.width, options_.height, "Floodlight", true});
    } catch (const gl::GlError& e) {
        throw NoWindow(e.what());
    }
    std::cout << "context: " << window_->description() << "\n"
              << "scene: " << scene_.source << " (" << scene_.triangleCount() << " triangles)\n"
              << "press H in the window for the key bindings\n";
    shaders_ = makeShaderLibrary(options_.scene);
    renderer_ = std::make_unique<Renderer>(shaders_, scene_, makeRenderSettings(options_.scene));
    applyAnimation(*renderer_, scene_, options_.scene);
    std::cout << setupLine(scene_, renderer_->settings(), options_.width, options_.height) << "\n";
    animationTime_ = options_.scene.time;
    controller_ =
        std::make_unique<CameraController>(initial, scene_.bounds.radius(), verticalFov(initial));
    if (options_.autoMethod) chooseOpeningMethod(initial);
    hud_ = std::make_unique<HudPass>(shaders_);
    overlay_ = std::make_unique<OverlayRenderer>(shaders_);
    installCallbacks();
}

Viewer::~Viewer() = default;

void Viewer::chooseOpeningMethod(const CameraView& view) {
    RenderSettings s = renderer_->settings();
    s.method = "jfa-e";
    renderer_->setSettings(s);
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_->handle(), &w, &h);
    renderer_->resize(std::max(w, 1), std::max(h, 1));
    renderer_->render(view); // warm-up: allocations and shader compiles
    renderer_->render(view);
    const double ms = renderer_->timer().frameMs();
    if (ms <= kInteractiveMs) {
        openingNote_ = "opened on jfa-e: " + fixed(ms, 0) + " ms/frame here (M: other methods)";
    } else {
        s.method = std::string(cheapestMethod().name); // the fastest there is
        renderer_->setSettings(s);
        openingNote_ = "opened on " + s.method + ": jfa-e takes " + fixed(ms, 0) +
                       " ms/frame here (> " + fixed(kInteractiveMs, 0) + " ms; M switches)";
    }
    std::cout << openingNote_ << "\n";
}

void Viewer::installCallbacks() {
    GLFWwindow* w = window_->handle();
    glfwSetWindowUserPointer(w, this);
    glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int, int action, int mods) {
        if (action != GLFW_RELEASE) self(win).onKey(key, mods, action == GLFW_REPEAT);
    });
    glfwSetCursorPosCallback(w, [](GLFWwindow* win, double x, double y) {
        const bool left = glfwGetMouseButton(win, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        const bool right = glfwGetMouseButton(win, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                           glfwGetMouseButton(win, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
        self(win).onCursor(x, y, left, right);
    });
    glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int button, int action, int) {
        if (button != GLFW_MOUSE_BUTTON_LEFT || action != GLFW_PRESS) return;
        double x = 0.0, y = 0.0;
        glfwGetCursorPos(win, &x, &y);
        self(win).onLeftClick(x, y);
    });
    glfwSetScrollCallback(w, [](GLFWwindow* win, double, double dy) { self(win).onScroll(dy); });
    glfwSetDropCallback(w, [](GLFWwindow* win, int count, const char** paths) {
        for (int i = 0; i < count; ++i) self(win).onDrop(paths[i]);
    });
}

void Viewer::onKey(int key, int mods, bool repeat) {
    const Action a = actionFor(key, mods);
    // Auto-repeat only for the continuous adjustments (light position); toggles fire once.
    const bool repeats = a == Action::LightLeft || a == Action::LightRight ||
                         a == Action::LightUp || a == Action::LightDown;
    if (a != Action::None && (!repeat || repeats)) act(a);
}

void Viewer::onCursor(double x, double y, bool left, bool right) {
    if (!left && !right)
        controller_->releaseCursor();
    else
        controller_->onCursor(x, y, left, right);
}

void Viewer::onLeftClick(double x, double y) {
    if (overlayMode_ != OverlayMode::VoronoiPlayground) return;
    int w = 0, h = 0;
    glfwGetWindowSize(window_->handle(), &w, &h);
    if (w <= 0 || h <= 0) return;
    // OverlayControls wants window fractions with y up; GLFW's cursor has y down.
    overlayControls_.clickedSites.emplace_back(static_cast<float>(x) / static_cast<float>(w),
                                               1.0f -
                                                   static_cast<float>(y) / static_cast<float>(h));
}

void Viewer::onScroll(double dy) {
    controller_->onScroll(dy);
}

bool Viewer::held(int key) const {
    if (script_ && script_->held(key, tick_)) return true;
    return glfwGetKey(window_->handle(), key) == GLFW_PRESS;
}

void Viewer::applyScriptEvent(const ScriptEvent& e) {
    using K = ScriptEvent::Kind;
    switch (e.kind) {
    case K::Key:
        onKey(e.key, e.mods, false);
        break;
    case K::Drag:
        controller_->releaseCursor();
        for (int i = 0; i <= e.steps; ++i) {
            const glm::vec2 p = glm::mix(e.from, e.to, float(i) / float(e.steps));
            onCursor(p.x, p.y, !e.rightButton, e.rightButton);
        }
        controller_->releaseCursor();
        break;
    case K::Click:
        onLeftClick(e.from.x, e.from.y);
        break;
    case K::Scroll:
        onScroll(e.scroll);
        break;
    case K::Resize:
        // Xvfb has no window manager to honour iconify, so a 0 size is also simulated: the loop
        // then sees a 0 x 0 framebuffer exactly as when a real window is minimised.
        scriptMinimised_ = e.size.x == 0 || e.size.y == 0;
        if (scriptMinimised_) {
            glfwIconifyWindow(window_->handle());
        } else {
            glfwRestoreWindow(window_->handle());
            glfwSetWindowSize(window_->handle(), e.size.x, e.size.y);
        }
        break;
    case K::Screenshot:
        pendingScreenshots_.push_back(e.text);
        break;
    case K::Drop:
        onDrop(e.text);
        break;
    case K::Quit:
        quit_ = true;
        break;
    case K::Stats: {
        // Before this frame renders: what the frames so far left behind.
        const gl::ObjectCounts live = gl::countLiveObjects();
        std::cout << "stats" << (e.text.empty() ? "" : " " + e.text) << ": frame " << tick_
                  << ", resident " << residentKiB() << " KiB, GL objects " << live.total() << " ("
                  << live.text() << "), HUD " << rateText() << ", light radius "
                  << renderer_->light().radius << "\n"
                  << std::flush;
        break;
    }
    case K::Hold:
    case K::Wait:
        break; // the player pauses; Hold's key is reported by held()
    }
}

void Viewer::loadDropped(const std::string& path) {
    SceneOptions o = options_.scene;
    o.scene = path;
    o.camera = "default"; // the command line's camera index may not exist in the new scene
    o.eye.clear();
    o.target.clear();
    try {
        Scene scene = loadScene(o);
        const glm::ivec2 size = glm::max(window_->framebufferSize(), glm::ivec2(1));
        const CameraView initial = initialCamera(scene, o, size.x, size.y);
        // A renderer keeps a reference to its scene (the ray tracer and the animation read it),
        // so the new scene takes scene_'s place before the renderer that draws it is built; if
        // that fails, the old scene goes back under the old renderer.
        Scene previous = std::exchange(scene_, std::move(scene));
        try {
            auto renderer = std::make_unique<Renderer>(shaders_, scene_, renderer_->settings());
            applyAnimation(*renderer, scene_, o);
            renderer_ = std::move(renderer);
            animationTime_ = 0.0;
        } catch (...) {
            scene_ = std::move(previous);
            throw;
        }
        rendererSize_ = glm::ivec2(0);
        cameraIndex_ = -1; // a file opens on the auto frame
        controller_ = std::make_unique<CameraController>(initial, scene_.bounds.radius(),
                                                         verticalFov(initial));
        stats_.reset();
        recorded_.clear(); // a recorded path belongs to one scene
        setMessage("opened " + path, false);
        std::cout << "scene: " << scene_.source << " (" << scene_.triangleCount()
                  << " triangles)\n";
    } catch (const std::exception& e) {
        std::cerr << "error: cannot open " << path << ": " << e.what() << "\n";
        setMessage("! cannot open " + path + ": " + e.what() + " (scene kept)", true);
    }
}

int Viewer::run() {
    double last = glfwGetTime();
    while (!quit_ && !window_->shouldClose()) {
        glfwPollEvents();
        if (script_) {
            for (const ScriptEvent& e : script_->due(tick_)) applyScriptEvent(e);
            if (script_->finished(tick_) && pendingScreenshots_.empty()) quit_ = true;
        }
        for (const std::string& path : std::exchange(pendingDrops_, {})) loadDropped(path);
        // A quit waits for the screenshots asked for before it: they are taken from the next
        // frame, so that frame is drawn first (a script's "screenshot NAME" then "quit").
        if ((quit_ && pendingScreenshots_.empty()) ||
            (options_.frames > 0 && rendered_ >= options_.frames))
            break;
        const glm::ivec2 size = scriptMinimised_ ? glm::ivec2(0) : window_->framebufferSize();
        if (quit_ && (size.x <= 0 || size.y <= 0)) { // no frame to take them from
            for (const std::string& name : std::exchange(pendingScreenshots_, {}))
                std::cerr << "error: screenshot " << (name.empty() ? "(key)" : name)
                          << " not written: the window was minimised when it quit\n";
            lostScreenshots_ = true;
            break;
        }
        const double now = glfwGetTime();
        // A script steps time by a fixed 1/30 s so that its fly movements are reproducible.
        const float dt = script_ ? 1.0f / 30.0f : static_cast<float>(now - last);
        last = now;
        ++tick_;
        if (size.x <= 0 || size.y <= 0) { // minimised: nothing to draw until restored
            if (!script_) glfwWaitEventsTimeout(0.1);
            continue;
        }
        renderFrame(size, dt);
    }
    recordPose(true);
    writeOutputs();
    return lostScreenshots_ ? 1 : 0;
}

void Viewer::renderFrame(glm::ivec2 size, float dt) {
    const double start = glfwGetTime();
    controller_->update([this](int key) { return held(key); }, dt);
    advanceAnimation(dt);
    if (size != rendererSize_) {
        renderer_->resize(size.x, size.y);
        rendererSize_ = size;
    }
    const CameraView view =
        controller_->view(static_cast<float>(size.x) / static_cast<float>(size.y));
    if (const bool whole = overlayReadsWholeFlood(overlayMode_);
        whole != renderer_->settings().wholeFlood) {
        RenderSettings s = renderer_->settings();
        s.wholeFlood = whole;
        renderer_->setSettings(s);
    }
    const bool statsFrame =
        referenceOf(renderer_->settings().method) &&
        (statsRequested_ || (options_.statsEvery > 0 && rendered_ >= nextStatsFrame_));
    // Steps 1-4 of the frame (renderer/Renderer.h).
    if (statsFrame)
        renderWithStats(view);
    else
        renderer_->render(view);
    const double renderMs = renderer_->timer().frameMs();
    // Step 6 starts: the colour to the window's framebuffer, for step 5 to draw over.
    renderer_->present(size.x, size.y);
    // Step 5: overlays and HUD.
    std::vector<std::string> overlayLines;
    if (overlayMode_ != OverlayMode::None) {
        try {
            overlayLines =
                overlay_->draw(overlayMode_, *renderer_, view, overlayControls_, size.x, size.y);
        } catch (const std::exception& e) {
            overlayLines.push_back(std::string("! overlay: ") + e.what());
        }
    }
    if (showHud_) hud_->draw(hudLines(overlayLines), size.x, size.y);
    if (options_.frames > 0 && rendered_ + 1 == options_.frames && !options_.screenshot.empty()) {
        writePng(options_.screenshot, readDefaultFramebuffer(size.x, size.y));
        std::cout << "wrote " << options_.screenshot << "\n";
    }
    for (const std::string& name : std::exchange(pendingScreenshots_, {})) screenshot(name, size);
    window_->swapBuffers(); // step 6 ends: the frame is shown
    ++rendered_;
    recordPose(false);
    const double end = glfwGetTime();
    // The rate over the frames that ended in the last half second, updated every frame (from
    // the one frame drawn until there are two): the HUD read "0.0 FPS" until a first half-second
    // window closed, then a window's stale rate.
    frameEnds_.push_back(end);
    while (frameEnds_.size() > 2 && frameEnds_.front() < end - 0.5) frameEnds_.pop_front();
    if (frameEnds_.size() >= 2 && frameEnds_.back() > frameEnds_.front())
        fps_ = double(frameEnds_.size() - 1) / (frameEnds_.back() - frameEnds_.front());
    else if (end > start)
        fps_ = 1.0 / (end - start);
    if (!options_.fpsLog.empty()) {
        const RenderSettings& s = renderer_->settings();
        fpsRows_ += std::to_string(rendered_) + "," + s.method + "," +
                    std::string(providerName(s.shadow.provider)) + "," +
                    std::to_string(s.shadow.size) + "," +
                    (renderer_->flood() ? std::to_string(renderer_->flood()->passes)
                                        : s.options.text(floodPassesOption())) +
                    "," + std::string(overlayName(overlayMode_)) + "," + std::to_string(size.x) +
                    "," + std::to_string(size.y) + "," + std::to_string(renderMs) + "," +
                    std::to_string((end - start) * 1000.0) + "," + (statsFrame ? "1" : "0") + "\n";
    }
}

} // namespace fl::app
