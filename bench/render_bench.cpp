// Frame and per-pass times of the renderer on a scene, with peak memory and the bytes of render
// targets and images each pass writes (computed from their formats: fl::writtenBytes): hard shadows
// by default, any shadow method with --method (e.g. the JFA-L / JFA-E flood time against the scene
// size, thesis Fig. 5.10). Prints min and median over --frames frames after --warmup frames, all in
// one process/context. Animated scenes play --animation from --time, advanced by 1/--animate
// seconds each frame (the cost of skinning); --static bakes that pose into plain meshes first
// (the same picture with no skinning at all, the baseline it is compared with).

#include <base/Stats.h>
#include <renderer/Renderer.h>
#include <renderer/context/EglContext.h>
#include <renderer/gltf/GltfLoader.h>
#include <renderer/run/FrameRunner.h>
#include <renderer/scene/Pose.h>
#include <renderer/scene/SceneGenerator.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sys/resource.h>

namespace {

long peakRssKiB() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss; // KiB on Linux
}

/// `scene` frozen in `pose`: every posed instance (skinned or morphed) gets a mesh of its own
/// with its vertices in world space, and the skins, morph targets, nodes and animations go. The
/// GL passes then draw it as any static scene (uniform branches, no joints, no uploads).
fl::Scene baked(const fl::Scene& scene, const fl::Pose& pose) {
    fl::Scene out = scene;
    for (std::size_t i = 0; i < out.instances.size(); ++i) {
        fl::Instance& inst = out.instances[i];
        const fl::Mesh& mesh = scene.meshes.at(static_cast<std::size_t>(inst.mesh));
        if (fl::isSkinned(inst, mesh) || !mesh.targets.empty()) {
            fl::Mesh m = mesh;
            fl::posedVertices(scene, pose, i, m.positions, &m.normals);
            m.joints.clear();
            m.weights.clear();
            m.targets.clear();
            m.morphWeights.clear();
            inst.mesh = static_cast<int>(out.meshes.size());
            inst.world = glm::mat4(1.0f);
            out.meshes.push_back(std::move(m));
        } else {
            inst.world = pose.instanceWorld.at(i);
        }
        inst.node = -1;
        inst.skin = -1;
    }
    for (fl::Mesh& m : out.meshes) { // meshes only the baked instances used keep no rig either
        m.joints.clear();
        m.weights.clear();
        m.targets.clear();
        m.morphWeights.clear();
    }
    out.nodes.clear();
    out.skins.clear();
    out.animations.clear();
    out.computeBounds();
    return out;
}

/// One row per phase (by name), then the frame and the CPU pose: min and median ms, and the MB
/// the phase writes in `written` (the last frame's; the same every frame for a held camera).
void printPhaseRows(const fl::PhaseTimes& times,
                    const std::vector<std::pair<std::string, std::int64_t>>& written,
                    const std::vector<double>& poseMs) {
    const auto row = [](const std::string& name, const std::vector<double>& v,
                        std::optional<std::int64_t> bytes) {
        std::cout << "  " << std::left << std::setw(12) << name << " min " << std::right
                  << std::setw(8) << fl::minimum(v) << " ms   median " << std::setw(8)
                  << fl::median(v) << " ms";
        if (bytes) std::cout << "   written " << std::setw(8) << double(*bytes) / 1e6 << " MB";
        std::cout << "\n";
    };
    const auto bytesOf = [&written](const std::string& name) {
        for (const auto& [n, b] : written)
            if (n == name) return b;
        return std::int64_t{0};
    };
    std::int64_t frameBytes = 0;
    for (const auto& [n, b] : written) frameBytes += b;
    // Phases by name (as before this bench used the runner), then the frame.
    std::vector<std::string> names = fl::phaseNames({&times});
    std::sort(names.begin(), names.end());
    for (const std::string& name : names) row(name, times.phaseSeries(name), bytesOf(name));
    row("frame", times.frameMs(), frameBytes);
    if (!poseMs.empty()) row("pose (CPU)", poseMs, std::nullopt);
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"floodlight_bench: frame and pass times (min/median) of a shadow method, and "
                 "peak RSS"};
    std::string scenePath;
    std::size_t triangles = 0;
    int width = 512, height = 512, shadowMap = 1024, frames = 20, warmup = 3;
    std::string method = "hard";
    std::optional<float> lightRadius;
    std::string shaderDir;
    std::string animation = "all";
    double time = 0.0, fps = 0.0;
    bool bake = false;
    app.add_option("--scene", scenePath, "glTF scene (default: generated, see --triangles)");
    app.add_option("--triangles", triangles,
                   "Generate the default-style scene with this many triangles");
    app.add_option("--width", width)->check(CLI::Range(1, 8192))->capture_default_str();
    app.add_option("--height", height)->check(CLI::Range(1, 8192))->capture_default_str();
    app.add_option("--shadow-map-size", shadowMap)
        ->check(CLI::Range(16, 8192))
        ->capture_default_str();
    app.add_option("--frames", frames)->check(CLI::Range(1, 100000))->capture_default_str();
    app.add_option("--warmup", warmup)->check(CLI::Range(0, 1000))->capture_default_str();
    app.add_option("--method", method, "Shadow method (" + fl::methodNames() + ")")
        ->capture_default_str();
    app.add_option("--light-radius", lightRadius, "Disk light radius (default: the scene's)");
    // Every method option of the table (--jfa-passes, --flood-region, --pcss-preset, ...), as the
    // app registers them; values are checked by the table's own rules.
    std::map<std::string, std::string> optionText;
    std::map<std::string, bool> optionFlags;
    for (const fl::MethodOption* o : fl::allMethodOptions()) {
        const std::string flag(o->flag), help(o->help);
        if (o->kind == fl::OptionKind::Flag)
            app.add_flag(flag, optionFlags[flag], help);
        else
            app.add_option(flag, optionText[flag],
                           help + " (default " + std::string(o->defaultValue) + ")");
    }
    app.add_option("--animation", animation,
                   "Animations that play: all, none, or one by name or index")
        ->capture_default_str();
    app.add_option("--time", time, "Seconds into the animations at the first frame")
        ->check(CLI::Range(0.0, fl::kMaxAnimationTime))
        ->capture_default_str();
    app.add_option("--animate", fps,
                   "Advance the time by 1/FPS seconds each frame, looping over the longest "
                   "animation (0: every frame at --time)")
        ->check(CLI::Range(0.0, 10000.0))
        ->capture_default_str();
    app.add_flag("--static", bake,
                 "Bake the pose at --time into plain meshes and render that static scene");
    app.add_option("--shader-dir", shaderDir,
                   "Load shaders from this folder instead of the binary (to time shader edits)");
    CLI11_PARSE(app, argc, argv);
    if (!fl::findMethod(method)) {
        std::cerr << "error: --method: unknown shadow method '" << method
                  << "' (valid: " << fl::methodNames() << ")\n";
        return 2;
    }

    try {
        fl::Scene scene;
        if (!scenePath.empty())
            scene = fl::loadGltf(scenePath);
        else
            scene = fl::generateScene({triangles ? triangles : 6320, 1});
        if (lightRadius && scene.light) scene.light->radius = *lightRadius;
        std::vector<int> playing = fl::chooseAnimations(scene, animation);
        if (bake) {
            scene = baked(scene, fl::evaluatePose(scene, playing, time));
            playing.clear(); // the baked scene has no animations left
        }
        const long rssScene = peakRssKiB();
        auto ctx = fl::EglContext::create(false);
        const fl::gl::ShaderLibrary shaders(
            shaderDir.empty() ? std::nullopt : std::optional<std::filesystem::path>(shaderDir));
        fl::RenderSettings settings;
        settings.shadow.size = shadowMap;
        settings.method = method;
        for (const auto& [flag, value] : optionText)
            if (!app.get_option(flag)->empty()) settings.options.set(flag, value);
        for (const auto& [flag, on] : optionFlags)
            if (on) settings.options.set(flag, true);
        for (const fl::MethodOption* o : fl::allMethodOptions())
            if (settings.options.has(o->flag)) (void)settings.options.text(*o); // validates
        fl::Renderer renderer(shaders, scene, settings);
        renderer.resize(width, height);
        const bool animated = fl::isAnimated(scene);
        const double duration = fl::animationDuration(scene, playing);
        // Frame k's time: --time + k / --animate, wrapped into the longest clip as the viewer
        // plays it.
        const auto timeAt = [&](int k) {
            double t = time + (fps > 0.0 ? k / fps : 0.0);
            if (duration > 0.0 && t > duration) t = std::fmod(t, duration);
            return t;
        };
        std::vector<double> poseMs; // CPU: evaluating the pose and uploading its joints
        const auto pose = [&](int k) {
            if (!animated) return;
            const auto start = std::chrono::steady_clock::now();
            renderer.setTime(timeAt(k), timeAt(std::max(k - 1, 0)));
            poseMs.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
        };
        if (animated) {
            renderer.setAnimations(playing);
            pose(0);
        }
        // The frame loop of capture/compare (renderer/run/FrameRunner.h): one camera held,
        // timed only (no read-back between frames).
        std::vector<fl::Lane> lanes{{method, &renderer, {}}};
        fl::FrameRunner runner(frames);
        runner.run({.scene = &scene,
                    .camera = fl::makeCameraView(
                        scene, {}, static_cast<float>(width) / static_cast<float>(height)),
                    .frames = frames,
                    .width = width,
                    .height = height,
                    .warmup = warmup,
                    .readBack = false},
                   lanes, [&](int frame, std::vector<fl::FrameImages>&) { pose(frame + 1); });
        runner.finish();
        const fl::PhaseTimes& times = lanes.front().times;
        std::set<int> passCounts;
        std::vector<double> activeShare, computedShare;
        for (std::size_t i = 0; i < times.frames(); ++i)
            if (const auto& f = times.flood(i)) {
                passCounts.insert(f->passes);
                activeShare.push_back(f->activeShare);
                computedShare.push_back(f->computedShare);
            }
        std::cout << "context: " << ctx->description() << "\n"
                  << "scene: " << scene.source << ", " << scene.triangleCount() << " triangles\n"
                  << "method: " << method << ", light radius "
                  << (scene.light ? scene.light->radius : 0.0f) << "\n";
        if (animated) {
            std::string names;
            for (int a : playing)
                names += (names.empty() ? "" : ", ") +
                         scene.animations[static_cast<std::size_t>(a)].name;
            std::cout << "animation: " << (names.empty() ? "none (rest pose, skinned)" : names)
                      << ", from t " << time << " s"
                      << (fps > 0.0 ? ", " + std::to_string(fps) + " frames per second"
                                    : std::string(", held"))
                      << "\n";
        } else if (bake) {
            std::cout << "animation: baked at t " << time << " s (static)\n";
        }
        for (const auto& [flag, value] : settings.options.values())
            std::cout << "  " << flag << " " << value << "\n";
        if (!passCounts.empty()) {
            std::cout << "flood passes:";
            for (int p : passCounts) std::cout << " " << p;
            std::cout << "\n";
        }
        if (!activeShare.empty()) {
            std::cout << "active share: min " << fl::minimum(activeShare) << " median "
                      << fl::median(activeShare) << "\n";
            std::cout << "computed share per pass (within the front): min "
                      << fl::minimum(computedShare) << " median " << fl::median(computedShare)
                      << "\n";
        }
        std::cout << "frame " << width << "x" << height << ", shadow map " << shadowMap << "^2, "
                  << frames << " frames after " << warmup
                  << " warm-up, timing: " << renderer.timer().modeName() << "\n"
                  << std::fixed << std::setprecision(2);
        printPhaseRows(times, fl::writtenBytes(renderer), poseMs);
        std::cout << "peak RSS: " << peakRssKiB() / 1024
                  << " MiB (after loading the scene: " << rssScene / 1024 << " MiB)\n";
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
