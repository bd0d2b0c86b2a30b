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
#include <renderer/run/FrameRunner.h>
#include <scene/GltfLoader.h>
#include <scene/Pose.h>
#include <scene/SceneGenerator.h>

#include <BenchSupport.h>
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

// The command line: the scene, the frame, the method with any option of the table, the clock.
struct Options {
    std::string scenePath;
    std::size_t triangles = 0;
    int width = 512, height = 512, shadowMap = 1024, frames = 20, warmup = 3;
    std::string method = "hard";
    std::optional<float> lightRadius;
    std::string shaderDir;
    std::string animation = "all";
    double time = 0.0, fps = 0.0;
    bool bake = false;
    fl::bench::MethodFlags methodFlags;
};

void addOptions(CLI::App& app, Options& o) {
    app.add_option("--scene", o.scenePath, "glTF scene (default: generated, see --triangles)");
    app.add_option("--triangles", o.triangles,
                   "Generate the default-style scene with this many triangles");
    app.add_option("--width", o.width)->check(CLI::Range(1, 8192))->capture_default_str();
    app.add_option("--height", o.height)->check(CLI::Range(1, 8192))->capture_default_str();
    app.add_option("--shadow-map-size", o.shadowMap)
        ->check(CLI::Range(16, 8192))
        ->capture_default_str();
    app.add_option("--frames", o.frames)->check(CLI::Range(1, 100000))->capture_default_str();
    app.add_option("--warmup", o.warmup)->check(CLI::Range(0, 1000))->capture_default_str();
    app.add_option("--method", o.method, "Shadow method (" + fl::methodNames() + ")")
        ->capture_default_str();
    app.add_option("--light-radius", o.lightRadius, "Disk light radius (default: the scene's)");
    // Every method option of the table (--jfa-passes, --flood-region, --pcss-preset, ...), as the
    // app registers them; values are checked by the table's own rules.
    o.methodFlags.add(app);
    app.add_option("--animation", o.animation,
                   "Animations that play: all, none, or one by name or index")
        ->capture_default_str();
    app.add_option("--time", o.time, "Seconds into the animations at the first frame")
        ->check(CLI::Range(0.0, fl::kMaxAnimationTime))
        ->capture_default_str();
    app.add_option("--animate", o.fps,
                   "Advance the time by 1/FPS seconds each frame, looping over the longest "
                   "animation (0: every frame at --time)")
        ->check(CLI::Range(0.0, 10000.0))
        ->capture_default_str();
    app.add_flag("--static", o.bake,
                 "Bake the pose at --time into plain meshes and render that static scene");
    app.add_option("--shader-dir", o.shaderDir,
                   "Load shaders from this folder instead of the binary (to time shader edits)");
}

// The scene the options ask for, with the animations that play (none once baked).
fl::Scene benchScene(const Options& o, std::vector<int>& playing) {
    fl::Scene scene = !o.scenePath.empty()
                          ? fl::loadGltf(o.scenePath)
                          : fl::generateScene({o.triangles ? o.triangles : 6320, 1});
    if (o.lightRadius && scene.light) scene.light->radius = *o.lightRadius;
    playing = fl::chooseAnimations(scene, o.animation);
    if (o.bake) {
        scene = baked(scene, fl::evaluatePose(scene, playing, o.time));
        playing.clear(); // the baked scene has no animations left
    }
    return scene;
}

// The scene's clock: frame k at --time + k / --animate, wrapped into the longest clip as the
// viewer plays it; pose() times the CPU's share (evaluating the pose, uploading its joints).
struct PoseClock {
    fl::Renderer& renderer;
    double time, fps, duration;
    bool animated;
    std::vector<double> poseMs;

    [[nodiscard]] double timeAt(int k) const {
        double t = time + (fps > 0.0 ? k / fps : 0.0);
        if (duration > 0.0 && t > duration) t = std::fmod(t, duration);
        return t;
    }
    void pose(int k) {
        if (!animated) return;
        const auto start = std::chrono::steady_clock::now();
        renderer.setTime(timeAt(k), timeAt(std::max(k - 1, 0)));
        poseMs.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
    }
};

// What ran: the context, scene, method and its options, the clock.
void printHeader(const Options& o, const fl::EglContext& ctx, const fl::Scene& scene,
                 const std::vector<int>& playing, const fl::RenderSettings& settings) {
    std::cout << "context: " << ctx.description() << "\n"
              << "scene: " << scene.source << ", " << scene.triangleCount() << " triangles\n"
              << "method: " << o.method << ", light radius "
              << (scene.light ? scene.light->radius : 0.0f) << "\n";
    if (fl::isAnimated(scene)) {
        std::string names;
        for (int a : playing)
            names +=
                (names.empty() ? "" : ", ") + scene.animations[static_cast<std::size_t>(a)].name;
        std::cout << "animation: " << (names.empty() ? "none (rest pose, skinned)" : names)
                  << ", from t " << o.time << " s"
                  << (o.fps > 0.0 ? ", " + std::to_string(o.fps) + " frames per second"
                                  : std::string(", held"))
                  << "\n";
    } else if (o.bake) {
        std::cout << "animation: baked at t " << o.time << " s (static)\n";
    }
    for (const auto& [flag, value] : settings.options.values())
        std::cout << "  " << flag << " " << value << "\n";
}

// The flood's pass counts and shares over the frames, for the methods that flood.
void printFloodRows(const fl::PhaseTimes& times) {
    std::set<int> passCounts;
    std::vector<double> activeShare, computedShare;
    for (std::size_t i = 0; i < times.frames(); ++i)
        if (const auto& f = times.flood(i)) {
            passCounts.insert(f->passes);
            activeShare.push_back(f->activeShare);
            computedShare.push_back(f->computedShare);
        }
    if (!passCounts.empty()) {
        std::cout << "flood passes:";
        for (int p : passCounts) std::cout << " " << p;
        std::cout << "\n";
    }
    if (!activeShare.empty()) {
        std::cout << "active share: min " << fl::minimum(activeShare) << " median "
                  << fl::median(activeShare) << "\n";
        std::cout << "computed share per pass (within the front): min "
                  << fl::minimum(computedShare) << " median " << fl::median(computedShare) << "\n";
    }
}

int runBench(const Options& o, const CLI::App& app) {
    std::vector<int> playing;
    const fl::Scene scene = benchScene(o, playing);
    const long rssScene = peakRssKiB();
    auto ctx = fl::EglContext::create(false);
    const fl::gl::ShaderLibrary shaders(
        o.shaderDir.empty() ? std::nullopt : std::optional<std::filesystem::path>(o.shaderDir));
    fl::RenderSettings settings;
    settings.shadow.size = o.shadowMap;
    settings.method = o.method;
    o.methodFlags.apply(app, settings.options);
    fl::Renderer renderer(shaders, scene, settings);
    renderer.resize(o.width, o.height);
    PoseClock clock{
        renderer, o.time, o.fps, fl::animationDuration(scene, playing), fl::isAnimated(scene), {}};
    if (clock.animated) {
        renderer.setAnimations(playing);
        clock.pose(0);
    }
    // The frame loop of capture/compare (renderer/run/FrameRunner.h): one camera held,
    // timed only (no read-back between frames).
    std::vector<fl::Lane> lanes{{o.method, &renderer, {}}};
    fl::FrameRunner runner(o.frames);
    runner.run({.scene = &scene,
                .camera = fl::makeCameraView(
                    scene, {}, static_cast<float>(o.width) / static_cast<float>(o.height)),
                .frames = o.frames,
                .width = o.width,
                .height = o.height,
                .warmup = o.warmup,
                .readBack = false},
               lanes, [&](int frame, std::vector<fl::FrameImages>&) { clock.pose(frame + 1); });
    runner.finish();
    const fl::PhaseTimes& times = lanes.front().times;
    printHeader(o, *ctx, scene, playing, settings);
    printFloodRows(times);
    std::cout << "frame " << o.width << "x" << o.height << ", shadow map " << o.shadowMap << "^2, "
              << o.frames << " frames after " << o.warmup
              << " warm-up, timing: " << renderer.timer().modeName() << "\n"
              << std::fixed << std::setprecision(2);
    printPhaseRows(times, fl::writtenBytes(renderer), clock.poseMs);
    std::cout << "peak RSS: " << peakRssKiB() / 1024
              << " MiB (after loading the scene: " << rssScene / 1024 << " MiB)\n";
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"floodlight_bench: frame and pass times (min/median) of a shadow method, and "
                 "peak RSS"};
    Options o;
    addOptions(app, o);
    return fl::bench::parseAndRun(app, argc, argv, [&] {
        if (!fl::findMethod(o.method)) {
            std::cerr << "error: --method: unknown shadow method '" << o.method
                      << "' (valid: " << fl::methodNames() << ")\n";
            return 2;
        }
        return runBench(o, app);
    });
}
