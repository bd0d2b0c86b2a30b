// The viewer's actions (what the key table's entries do), the HUD text, screenshots, the live
// comparison with standard flooding, and the outputs written on exit.

#include <app/Viewer.h>

#include <jfa/Plan.h>

#include <base/OutputFiles.h>
#include <base/Text.h>
#include <renderer/io/TextureImage.h>
#include <renderer/run/Capture.h>
#include <scene/CameraPath.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace fl::app {

namespace {

constexpr float kLightStep = 0.0872665f; // 5 degrees per key press

template <typename T>
std::size_t indexOf(std::span<const T> all, T value) {
    const auto it = std::find(all.begin(), all.end(), value);
    return it == all.end() ? 0 : static_cast<std::size_t>(it - all.begin());
}

template <typename T>
T cycle(std::span<const T> all, T value, int delta) {
    const auto n = static_cast<long>(all.size());
    const long i = (static_cast<long>(indexOf(all, value)) + delta + n) % n;
    return all[static_cast<std::size_t>(i)];
}

} // namespace

void Viewer::act(Action a) {
    if (a == Action::None || actOnOverlay(a) || actOnView(a)) return;
    RenderSettings s = renderer_->settings();
    if (!changeSettings(a, s)) return;
    renderer_->setSettings(s);
    std::cout << "method " << s.method << ", shadow map " << providerName(s.shadow.provider) << " "
              << s.shadow.size << "^2, JFA passes " << s.options.text(floodPassesOption()) << "\n";
}

bool Viewer::changeSettings(Action a, RenderSettings& s) {
    const int maxPasses = jfa::jfaMaxPasses(s.shadow.size);
    switch (a) {
    case Action::NextMethod:
    case Action::PrevMethod: {
        const std::vector<std::string> methods = cycledMethods();
        s.method = cycle(std::span<const std::string>(methods), s.method,
                         a == Action::NextMethod ? 1 : -1);
    }
        stats_.reset();
        openingNote_.clear(); // the user chose: the note about the opening method is stale
        return true;
    case Action::ToggleProvider:
        s.shadow.provider = s.shadow.provider == ShadowMapProvider::Uniform
                                ? ShadowMapProvider::Tsm
                                : ShadowMapProvider::Uniform;
        return true;
    case Action::NextFloodRegion: {
        const std::vector<std::string> regions = optionChoices(floodRegionOption());
        s.options.set(floodRegionOption().flag, cycle(std::span<const std::string>(regions),
                                                      s.options.text(floodRegionOption()), 1));
        return true;
    }
    case Action::ShadowMapSmaller:
        s.shadow.size = std::max(256, s.shadow.size / 2);
        if (s.options.integer(floodPassesOption()) != kAutoPasses) // auto adapts by itself
            s.options.set(floodPassesOption().flag, std::min(s.options.integer(floodPassesOption()),
                                                             jfa::jfaMaxPasses(s.shadow.size)));
        return true;
    case Action::ShadowMapLarger:
        s.shadow.size = std::min(4096, s.shadow.size * 2);
        return true;
    case Action::FewerPasses: {
        // From auto, one fewer than the passes auto chose last frame.
        int now = s.options.integer(floodPassesOption());
        if (now == kAutoPasses) now = renderer_->flood() ? renderer_->flood()->passes : maxPasses;
        s.options.set(floodPassesOption().flag, std::max(1, now - 1));
        return true;
    }
    case Action::MorePasses: {
        // Past the most the map allows comes auto again.
        const int now = s.options.integer(floodPassesOption());
        if (now == kAutoPasses || now >= maxPasses)
            s.options.set(floodPassesOption().flag, std::string(floodPassesOption().word));
        else
            s.options.set(floodPassesOption().flag, now + 1);
        return true;
    }
    default:
        return false;
    }
}

bool Viewer::actOnOverlay(Action a) {
    switch (a) {
    case Action::NextVariant: {
        const auto n = static_cast<int>(OverlayRenderer::variantNames().size());
        if (n > 0) overlayControls_.variant = (overlayControls_.variant + 1) % n;
        return true;
    }
    case Action::NextOverlay:
    case Action::PrevOverlay:
        overlayMode_ = cycle(allOverlayModes(), overlayMode_, a == Action::NextOverlay ? 1 : -1);
        return true;
    case Action::StepBack:
    case Action::StepForward: {
        const int d = a == Action::StepForward ? 1 : -1;
        if (overlayMode_ == OverlayMode::Delaunay) {
            const auto n = static_cast<int>(OverlayRenderer::delaunayStageNames().size());
            overlayControls_.delaunayStep =
                std::clamp(overlayControls_.delaunayStep + d, 0, std::max(n - 1, 0));
        } else {
            // Flood passes: -1 shows the finished flood; the overlay clamps a count past the
            // plan's end to "all passes", so stepping back from -1 starts at the last one.
            int& p = overlayControls_.floodPass;
            if (d > 0)
                p = p < 0 ? 0 : p + 1;
            else
                p = p < 0 ? (1 << 20) : std::max(0, p - 1);
        }
        return true;
    }
    case Action::NewPoints:
        overlayControls_.regenerate = true; // the overlay picks a new seed and clears clicks
        return true;
    default:
        return false;
    }
}

bool Viewer::actOnView(Action a) {
    switch (a) {
    case Action::Quit:
        glfwSetWindowShouldClose(window_->handle(), GLFW_TRUE);
        return true;
    case Action::ToggleHelp:
        showHelp_ = !showHelp_;
        return true;
    case Action::ToggleHud:
        showHud_ = !showHud_;
        return true;
    case Action::Screenshot:
        pendingScreenshots_.push_back("");
        return true;
    case Action::Stats:
        statsRequested_ = true;
        return true;
    case Action::ToggleCameraMode:
        controller_->toggleMode();
        return true;
    case Action::ResetView:
        controller_->reset();
        return true;
    case Action::LightLeft:
    case Action::LightRight:
        moveLight(a == Action::LightLeft ? -kLightStep : kLightStep, 0.0f);
        return true;
    case Action::LightUp:
    case Action::LightDown:
        moveLight(0.0f, a == Action::LightUp ? kLightStep : -kLightStep);
        return true;
    case Action::NextCamera:
        nextCamera();
        return true;
    case Action::LightSmaller:
    case Action::LightLarger:
        scaleLight(a == Action::LightLarger ? 1.25f : 0.8f);
        return true;
    case Action::PlayPause:
        animationPlaying_ = !animationPlaying_;
        return true;
    case Action::AnimationBack:
    case Action::AnimationForward:
        animationPlaying_ = false;
        animationStep_ += a == Action::AnimationForward ? 1 : -1;
        return true;
    case Action::AnimationSlower:
    case Action::AnimationFaster:
        animationSpeed_ = std::clamp(animationSpeed_ * (a == Action::AnimationFaster ? 2.0 : 0.5),
                                     1.0 / 64.0, 64.0);
        return true;
    default:
        return false;
    }
}

void Viewer::moveLight(float dAzimuth, float dElevation) {
    Light l = renderer_->light();
    const glm::vec3 c = scene_.bounds.center();
    // Point/spot lights move on a sphere around the scene centre; a directional light turns.
    const glm::vec3 offset = l.type == Light::Type::Directional
                                 ? -l.direction * std::max(scene_.bounds.radius(), 1e-3f)
                                 : l.position - c;
    const float r = glm::length(offset);
    if (r <= 0.0f) return;
    float elevation = std::asin(std::clamp(offset.y / r, -1.0f, 1.0f));
    float azimuth = std::atan2(offset.x, offset.z);
    elevation = std::clamp(elevation + dElevation, 0.0872665f, 1.5533f); // 5..89 degrees
    azimuth += dAzimuth;
    const glm::vec3 dir(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                        std::cos(elevation) * std::cos(azimuth));
    l.direction = -dir;
    if (l.type != Light::Type::Directional) l.position = c + dir * r;
    renderer_->setLight(l);
    stats_.reset();
}

std::string Viewer::rateText() const {
    return fixed(fps_ > 0.0 ? 1000.0 / fps_ : 0.0, 1) + " ms/frame, " + fixed(fps_, 1) + " FPS";
}

void Viewer::nextCamera() {
    const int n = static_cast<int>(scene_.cameras.size());
    cameraIndex_ = cameraIndex_ + 1 >= n ? -1 : cameraIndex_ + 1;
    SceneOptions o = options_.scene;
    o.eye.clear();
    o.target.clear();
    o.camera = cameraIndex_ < 0 ? "auto" : std::to_string(cameraIndex_);
    o.time = animationTime_;
    const glm::ivec2 size = glm::max(window_->framebufferSize(), glm::ivec2(1));
    const CameraView v = initialCamera(scene_, o, size.x, size.y);
    controller_ = std::make_unique<CameraController>(v, scene_.bounds.radius(), verticalFov(v));
    const Camera* own = cameraIndex_ < 0 ? nullptr : &scene_.cameras[std::size_t(cameraIndex_)];
    setMessage(own ? "camera " + std::to_string(cameraIndex_) + " of " + std::to_string(n) +
                         (own->name.empty() ? "" : " (" + own->name + ")")
               : n == 0 ? std::string("camera auto (the scene has no cameras of its own)")
                        : "camera auto (C: the scene's " + std::to_string(n) + " camera(s))",
               false);
}

void Viewer::scaleLight(float factor) {
    Light l = renderer_->light();
    // --light-size's range, 0 to 1 of the model's radius (a point light is --light-radius 0).
    const float r = std::max(scene_.modelBounds.radius(), 1e-3f);
    l.radius = std::clamp(l.radius * factor, 1e-3f * r, r);
    renderer_->setLight(l);
    stats_.reset();
}

void Viewer::setMessage(const std::string& text, bool error) {
    message_ = text;
    messageUntil_ = glfwGetTime() + (error ? 10.0 : 4.0);
}

void Viewer::renderWithStats(const CameraView& view) {
    // The reference first, so that the method's frame is the one presented.
    const RenderSettings method = renderer_->settings();
    RenderSettings reference = method;
    reference.method = *referenceOf(method.method);
    renderer_->setSettings(reference);
    renderer_->render(view);
    const double referenceMs = renderer_->timer().frameMs();
    const FloatImage flood = readTexture(renderer_->visibility(), 1);
    renderer_->setSettings(method);
    renderer_->render(view);
    // Standard flooding costs 2^n / n times the JFA passes (10x at 6 passes): space the periodic
    // comparisons so that they add at most ~10% to the frame time on average (on llvmpipe a
    // 1024^2 flood-l frame takes tens of seconds, so there they come far apart; G still works).
    const double methodMs = std::max(renderer_->timer().frameMs(), 1e-3);
    nextStatsFrame_ =
        rendered_ + std::max(options_.statsEvery,
                             static_cast<int>(std::min(1e6, 10.0 * referenceMs / methodMs)));
    stats_ = compareSoftShadows(readTexture(renderer_->visibility(), 1), flood);
    statsMethod_ = method.method;
    statsFrame_ = rendered_;
    if (statsRequested_) // asked for with G: also on stdout (the periodic ones only in the HUD)
        std::cout << method.method << " vs " << reference.method << ": parity differs "
                  << fixed(100.0 * stats_->parityShare, 3) << "% of pixels, |dI|<0.05 "
                  << fixed(100.0 * stats_->deltaBuckets[0], 2) << "% of penumbra pixels, max |dI| "
                  << fixed(stats_->maxDelta, 3) << "\n";
    statsRequested_ = false;
}

void Viewer::advanceAnimation(float dt) {
    if (!isAnimated(scene_)) return;
    const double duration = animationDuration(scene_, renderer_->animations());
    const double previous = animationTime_;
    if (animationPlaying_) animationTime_ += static_cast<double>(dt) * animationSpeed_;
    animationTime_ += animationStep_ / 30.0;
    animationStep_ = 0;
    if (duration > 0.0) {
        animationTime_ = std::fmod(animationTime_, duration);
        if (animationTime_ < 0.0) animationTime_ += duration;
    } else {
        animationTime_ = 0.0;
    }
    renderer_->setTime(animationTime_, std::clamp(previous, 0.0, kMaxAnimationTime));
}

std::string Viewer::animationLine() const {
    if (!isAnimated(scene_)) return {};
    const std::vector<int>& playing = renderer_->animations();
    std::string names;
    for (int a : playing)
        names += (names.empty() ? "" : ", ") + scene_.animations[static_cast<std::size_t>(a)].name;
    return "animation " + (playing.empty() ? std::string("none") : names) + "   t " +
           fixed(animationTime_, 2) + " / " + fixed(animationDuration(scene_, playing), 2) +
           " s   x" + fixed(animationSpeed_, 3) + (animationPlaying_ ? "   playing" : "   paused") +
           "   (Space J K 9 0)";
}

std::vector<std::string> Viewer::hudLines(const std::vector<std::string>& overlay) const {
    const RenderSettings& s = renderer_->settings();
    const std::vector<std::string> methods = cycledMethods();
    std::vector<std::string> lines;
    // The passes line shows the passes the flood ran (--full-jfa resolves them per frame).
    const FloodFrame* flood = renderer_->flood();
    const bool autoPasses = s.options.integer(floodPassesOption()) == kAutoPasses;
    std::string passes = "   JFA passes " + (flood ? std::to_string(flood->passes)
                                                   : s.options.text(floodPassesOption()));
    if (flood && autoPasses) passes += " (auto)";
    if (flood && flood->kernel && flood->kernel->lastRunBanded())
        passes += "   " + std::string(jfa::floodRegionName(flood->region)) + " " +
                  std::to_string(int(flood->kernel->activeShare() * 100.0 + 0.5)) + "% of texels";
    else if (flood)
        passes += "   full grid";
    lines.push_back(
        "method " + s.method + " (" +
        std::to_string(indexOf(std::span<const std::string>(methods), s.method) + 1) + "/" +
        std::to_string(methods.size()) + ")   shadow map " +
        std::string(providerName(s.shadow.provider)) + " " + std::to_string(s.shadow.size) + "^2" +
        passes + "   light size " +
        fixed(renderer_->light().radius / std::max(scene_.modelBounds.radius(), 1e-30f), 3) +
        " (radius " + fixed(renderer_->light().radius, 3) + ")");
    // Frames per second and the frame time they imply, both from the wall clock, then the GL
    // frame's own time and its passes: the HUD showed the GL time beside a wall-clock rate, two
    // numbers that did not agree.
    std::string times = rateText() + "; render " + fixed(renderer_->timer().frameMs(), 1) +
                        " ms (" + renderer_->timer().modeName() + "):";
    for (const gl::PassTime& p : renderer_->timer().passes())
        times += " " + p.name + " " + fixed(p.ms, 1);
    lines.push_back(times);
    if (stats_ && statsMethod_ == s.method) {
        lines.push_back("vs " + *referenceOf(s.method) + " (frame " + std::to_string(statsFrame_) +
                        "): parity differs " + fixed(100.0 * stats_->parityShare, 3) +
                        "% of pixels, |dI|<0.05 " + fixed(100.0 * stats_->deltaBuckets[0], 2) +
                        "% of penumbra pixels, max " + fixed(stats_->maxDelta, 3));
    }
    lines.push_back("camera " +
                    std::string(controller_->mode() == CameraController::Mode::Orbit
                                    ? "orbit"
                                    : "fly x" + fixed(controller_->flySpeed(), 2)) +
                    "   overlay " + std::string(overlayName(overlayMode_)));
    if (const std::string a = animationLine(); !a.empty()) lines.push_back(a);
    lines.insert(lines.end(), overlay.begin(), overlay.end());
    if (!message_.empty() && glfwGetTime() < messageUntil_) lines.push_back(message_);
    if (!openingNote_.empty()) lines.push_back(openingNote_);
    if (showHelp_) {
        // The keys in place of the status below the method line: appended, they ran off the
        // bottom of a small window, where H then seemed to do nothing.
        lines.resize(1);
        lines.push_back("");
        const std::vector<std::string> help = helpLines();
        lines.insert(lines.end(), help.begin(), help.end());
    } else {
        lines.push_back("H: help");
    }
    return lines;
}

std::string Viewer::expandName(const std::string& name) const {
    auto replace = [](std::string s, const std::string& key, std::string_view value) {
        for (std::size_t at; (at = s.find(key)) != std::string::npos;)
            s.replace(at, key.size(), value);
        return s;
    };
    std::string out = replace(name, "{method}", renderer_->settings().method);
    out = replace(out, "{overlay}", overlayName(overlayMode_));
    return replace(out, "{provider}", providerName(renderer_->settings().shadow.provider));
}

void Viewer::screenshot(const std::string& name, glm::ivec2 size) {
    std::string stem = expandName(name);
    if (stem.empty()) { // the key: the next free numbered name
        do {
            char buf[32];
            std::snprintf(buf, sizeof buf, "capture-%04d-", ++captureCounter_);
            stem = buf + std::string(renderer_->settings().method);
        } while (std::filesystem::exists(options_.captureDir / (stem + ".png")));
    }
    try {
        makeOutputFolder(options_.captureDir, "--screenshot-dir");
        OutputSet files; // the three files of a screenshot appear together (base/OutputFiles.h)
        // The window image first: it is the back buffer, which the frame read-back leaves alone.
        writePng(options_.captureDir / (stem + ".window.png"),
                 readDefaultFramebuffer(size.x, size.y));
        const CapturePaths p = writeFrame(readFrame(*renderer_), options_.captureDir, stem);
        files.commit();
        std::cout << "wrote " << p.png.string() << ", " << p.exr.string() << "\n";
        setMessage("wrote " + p.png.string() + " and .exr", false);
    } catch (const std::exception& e) {
        std::cerr << "error: screenshot " << stem << ": " << e.what() << "\n";
        setMessage(std::string("! screenshot failed: ") + e.what(), true);
    }
}

void Viewer::recordPose(bool force) {
    if (options_.record.empty()) return;
    if (!force && (rendered_ - 1) % std::max(options_.recordEvery, 1) != 0) return;
    const CameraKey k = controller_->pose();
    const float eps = 1e-4f * std::max(scene_.bounds.radius(), 1e-3f);
    // A key only when the camera moved, so standing still records no zero-length segments.
    if (!recorded_.empty() && glm::length(recorded_.back().eye - k.eye) < eps &&
        glm::length(recorded_.back().target - k.target) < eps)
        return;
    recorded_.push_back(k);
}

void Viewer::writeOutputs() {
    if (!options_.record.empty()) {
        std::vector<CameraKey> keys = recorded_;
        if (keys.empty()) keys.push_back(controller_->pose());
        if (keys.size() < 2) keys.push_back(keys.back()); // a camera that never moved
        writeCameraPath(options_.record, CameraPath(keys, glm::degrees(controller_->yfov())));
        std::cout << "recorded " << keys.size() << " camera keys to " << options_.record << "\n";
    }
    if (!options_.fpsLog.empty()) {
        writeTextFile(options_.fpsLog, "frame,method,provider,shadow_size,jfa_passes,overlay,width,"
                                       "height,render_ms,loop_ms,stats\n" +
                                           fpsRows_);
        std::cout << "wrote " << options_.fpsLog << "\n";
    }
}

} // namespace fl::app
