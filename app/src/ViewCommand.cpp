#include <app/Commands.h>
#include <app/Viewer.h>

#include <base/InputFile.h>

namespace fl::app {

int runViewer(const SceneOptions& o, int width, int height, int frames,
              const std::string& screenshot, bool autoMethod) {
    Viewer viewer({.scene = o,
                   .width = width,
                   .height = height,
                   .frames = frames,
                   .screenshot = screenshot,
                   .autoMethod = autoMethod});
    return viewer.run();
}

Runner addViewCommand(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "view", "Open a scene in an interactive window (press H in it for the key bindings)");
    auto s = std::make_shared<ViewerOptions>();
    auto captureDir = std::make_shared<std::string>("captures");
    auto noHud = std::make_shared<bool>(false);
    s->scene.strictMethodOptions = false; // the window switches methods: each takes its own
    addSceneOptions(*cmd, s->scene, false);
    addSizeOptions(*cmd, s->width, s->height);
    cmd->add_option("--frames", s->frames,
                    "Close after this many frames (0 = run until closed; at most 10000000)")
        ->check(integer(0, 10'000'000));
    cmd->add_option("--screenshot", s->screenshot, "With --frames: save the last frame as PNG")
        ->check(outputFile());
    cmd->add_option("--script", s->script,
                    "Replay input events from FILE (see app/include/app/InputScript.h; at most " +
                        std::to_string(kTextInputLimitMiB) + " MiB), then close")
        ->check(CLI::ExistingFile);
    cmd->add_option("--screenshot-dir", *captureDir,
                    "Folder for screenshots (P / F12 / script), default captures/")
        ->check(outputFolder());
    cmd->add_option("--record", s->record,
                    "On exit, write the camera path walked as JSON (replay: floodlight capture)")
        ->check(outputFile());
    cmd->add_option("--record-every", s->recordEvery, "Frames between recorded camera keys")
        ->check(integer(1, 1'000'000));
    cmd->add_option("--fps-log", s->fpsLog, "On exit, write one CSV row of timings per frame")
        ->check(outputFile());
    cmd->add_option("--stats-every", s->statsEvery,
                    "Least frames between live comparisons with standard flooding, spaced further "
                    "to add at most ~10% frame time (0 = only on G)")
        ->check(integer(0, 1'000'000));
    cmd->add_flag("--no-hud", *noHud, "Start with the HUD hidden (F1 shows it)");
    return [s, captureDir, noHud] {
        s->captureDir = *captureDir;
        s->hud = !*noHud;
        // One line that says what to do instead: render headless, or give the window
        // a virtual display.
        const std::string instead =
            "; use `floodlight render` (headless), or run the window under a virtual display: "
            "xvfb-run -a floodlight view ...";
        if (!displayAvailable())
            throw InputError("no display to open a window on (neither DISPLAY nor "
                             "WAYLAND_DISPLAY is set)" +
                             instead);
        try {
            Viewer viewer(*s);
            return viewer.run();
        } catch (const NoWindow& e) {
            throw InputError(std::string(e.what()) + instead);
        }
    };
}

} // namespace fl::app
