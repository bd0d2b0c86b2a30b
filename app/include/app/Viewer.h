#pragma once
// The interactive window (`floodlight view`): state, the frame loop and the input handling. Keys
// come from ViewerInput's table, scripted input from InputScript; both go through the same
// handlers, so a script exercises exactly what a user's keys do.

#include <app/CameraController.h>
#include <app/Common.h>
#include <app/InputScript.h>
#include <app/ViewerInput.h>
#include <renderer/run/FrameRunner.h>

#include <renderer/Renderer.h>
#include <renderer/context/GlfwWindow.h>
#include <renderer/metrics/SoftStats.h>
#include <renderer/overlays/Overlay.h>
#include <renderer/passes/HudPass.h>

#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fl::app {

struct ViewerOptions {
    SceneOptions scene;
    int width = 1024, height = 768;
    int frames = 0;         // > 0: close after this many rendered frames
    std::string screenshot; // with frames: PNG of the last window frame (legacy option)
    std::string script;     // --script FILE (closes the window when it ends)
    std::filesystem::path captureDir = "captures";
    std::string record;   // --record FILE: camera path JSON written on exit
    int recordEvery = 15; // frames between recorded keys
    std::string fpsLog;   // --fps-log FILE: one CSV row per rendered frame
    bool hud = true;
    int statsEvery = 30; // frames between live flood comparisons (0 = only on G)
    /// Open on jfa-e when this machine renders it interactively (kInteractiveMs at the window's
    /// size, measured at start), else on hard shadows; the HUD says which and why.
    bool autoMethod = false;
};

/// The frame time up to which a method counts as interactive (10 FPS).
inline constexpr double kInteractiveMs = 100.0;

class Viewer {
  public:
    /// Opens the window and loads the scene; throws NoWindow or InputError.
    explicit Viewer(const ViewerOptions& options);
    ~Viewer();
    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;
    /// Runs until closed (Esc, window close, --frames, end of --script); returns the exit code.
    int run();

    // Input entry points (GLFW callbacks and script events).
    void onKey(int key, int mods, bool repeat);
    void onCursor(double x, double y, bool left, bool right);
    void onLeftClick(double x, double y);
    void onScroll(double dy);
    void onDrop(const std::string& path) { pendingDrops_.push_back(path); }

  private:
    void installCallbacks();
    /// autoMethod: measures jfa-e at the window size and keeps it or falls back to hard.
    void chooseOpeningMethod(const CameraView& view);
    void applyScriptEvent(const ScriptEvent& e);
    void loadDropped(const std::string& path);
    void act(Action a);
    /// The actions that change the renderer's settings (method, map, passes, region): true when
    /// `a` is one of them, with `s` changed.
    bool changeSettings(Action a, RenderSettings& s);
    /// The overlays' actions (mode, variant, step, new points): true when `a` is one of them.
    bool actOnOverlay(Action a);
    /// The window's, camera's, light's and animation's actions: true when `a` is one of them.
    bool actOnView(Action a);
    void renderFrame(glm::ivec2 size, float dt);
    /// Advances the animation clock by dt (when playing; looping over the longest animation)
    /// and poses the renderer's scene there.
    void advanceAnimation(float dt);
    /// The HUD line of the animation clock (empty for a scene that does not move).
    [[nodiscard]] std::string animationLine() const;
    void renderWithStats(const CameraView& view);
    [[nodiscard]] std::vector<std::string> hudLines(const std::vector<std::string>& overlay) const;
    void screenshot(const std::string& name, glm::ivec2 size);
    void moveLight(float dAzimuth, float dElevation);
    void scaleLight(float factor);
    /// "M ms/frame, F FPS": the wall clock's rate as the HUD shows it (and a script's stats).
    [[nodiscard]] std::string rateText() const;
    /// C: the auto frame, then the scene's own cameras in turn, then the auto frame again.
    void nextCamera();
    void setMessage(const std::string& text, bool error);
    void recordPose(bool force);
    void writeOutputs();
    [[nodiscard]] std::string expandName(const std::string& name) const;
    [[nodiscard]] bool held(int key) const;

    ViewerOptions options_;
    std::unique_ptr<GlfwWindow> window_;
    gl::ShaderLibrary shaders_;
    Scene scene_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<CameraController> controller_;
    std::unique_ptr<HudPass> hud_;
    std::unique_ptr<OverlayRenderer> overlay_;
    OverlayMode overlayMode_ = OverlayMode::None;
    OverlayControls overlayControls_;
    bool showHelp_ = false, showHud_ = true;
    std::string message_;
    std::string openingNote_; // autoMethod: which method the window opened on, and why
    double messageUntil_ = 0.0;
    std::optional<SoftStats> stats_;
    std::string statsMethod_;
    int statsFrame_ = 0, nextStatsFrame_ = 0;
    bool statsRequested_ = false;
    std::optional<ScriptPlayer> script_;
    bool scriptMinimised_ = false;
    std::vector<std::string> pendingDrops_, pendingScreenshots_;
    bool lostScreenshots_ = false; // a quit found screenshots it could not take (exit 1)
    std::vector<CameraKey> recorded_;
    std::string fpsRows_;
    glm::ivec2 rendererSize_{0};
    int tick_ = 0, rendered_ = 0, captureCounter_ = 0;
    double fps_ = 0.0;
    std::deque<double> frameEnds_; // wall-clock ends of the last half second's frames
    // The animation clock (scene/Pose.h): seconds, speed factor, playing or paused;
    // `animationStep_` is a pending step of paused frames (J / K).
    double animationTime_ = 0.0, animationSpeed_ = 1.0;
    int cameraIndex_ = -1; // the scene camera in view (C), -1 for the auto frame
    bool animationPlaying_ = true;
    int animationStep_ = 0;
    bool quit_ = false;
};

/// The standard-flooding reference of a JFA method (jfa-l -> flood-l, jfa-e -> flood-e).
/// The window's method list: the table's rows that cycle.
std::vector<std::string> cycledMethods();

} // namespace fl::app
