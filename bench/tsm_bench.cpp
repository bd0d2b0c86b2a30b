// TSM vs uniform shadow map on a scripted walkthrough (renderer/scene/CameraPath.h) at equal
// shadow-map resolution, both measured side by side in one process:
//  - texel footprint (screen pixels per shadow texel) median and p95, over all receivers and
//    near the viewer (nearest 25% by view depth), median over the frames;
//  - flicker: share of receivers whose hard visibility changed since the previous frame's map
//    (same world point), mean and max over the frames, and as a share of shadow-edge pixels;
//  - frame time (the hard method's frame, no diagnostics) with each provider, interleaved frame by
//    frame along the same path, min and median, and TSM / uniform.
// Both loops are the frame loop of capture/compare (renderer/run/FrameRunner.h).
// The TSM lane takes the stability options (--tsm-quantize, --tsm-snap, --tsm-hysteresis, the
// table of ShadowMapPass.h); --with-tsm-off adds a third lane, TSM with all of them 0 (the
// paper's fit), so that a stable TSM is measured against it in the same run, frames interleaved.

#include <renderer/Renderer.h>
#include <renderer/context/EglContext.h>
#include <renderer/gltf/GltfLoader.h>
#include <renderer/io/Capture.h>
#include <renderer/metrics/ShadowStats.h>
#include <renderer/run/FrameRunner.h>
#include <renderer/scene/CameraPath.h>
#include <renderer/scene/SceneGenerator.h>

#include <base/Stats.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iomanip>
#include <iostream>

namespace {

double maxOf(const std::vector<double>& v) {
    return *std::max_element(v.begin(), v.end());
}
double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

// Share of receivers with a 4-neighbour receiver of different hard visibility (shadow edges).
double edgeShare(const fl::FloatImage& d) {
    std::size_t receivers = 0, edges = 0;
    for (int y = 0; y < d.height; ++y)
        for (int x = 0; x < d.width; ++x) {
            if (!(d.at(x, y, 0) > 0.0f)) continue;
            ++receivers;
            const bool v = d.at(x, y, 2) >= 0.5f;
            bool edge = false;
            for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                const int nx = x + dx, ny = y + dy;
                if (nx < 0 || ny < 0 || nx >= d.width || ny >= d.height) continue;
                if (d.at(nx, ny, 0) > 0.0f && (d.at(nx, ny, 2) >= 0.5f) != v) edge = true;
            }
            edges += edge;
        }
    return receivers ? static_cast<double>(edges) / static_cast<double>(receivers) : 0.0;
}

struct Series {
    std::vector<double> fpMed, fpP95, nearMed, nearP95, flicker, flickerPerEdge;
    int degenerateFrames = 0, heldFrames = 0;
};

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"tsm_bench: TSM vs uniform shadow map along a walkthrough, side by side"};
    std::string scenePath;
    int size = 512, shadowMap = 1024, frames = 120, timedFrames = 20, saveEvery = 0;
    std::string saveDir;
    app.add_option("--scene", scenePath, "glTF scene (default: assets/default.glb)");
    app.add_option("--size", size, "Frame width and height")->capture_default_str();
    app.add_option("--shadow-map-size", shadowMap)->capture_default_str();
    app.add_option("--frames", frames, "Walkthrough frames measured")
        ->check(CLI::Range(2, 100000))
        ->capture_default_str();
    app.add_option("--timed-frames", timedFrames, "Frames timed per provider (interleaved)")
        ->check(CLI::Range(1, 100000))
        ->capture_default_str();
    app.add_option("--save", saveDir,
                   "Write uniform | TSM side-by-side PNGs of every --save-every-th frame here");
    app.add_option("--save-every", saveEvery, "Frame interval for --save (0 = only the first)")
        ->check(CLI::NonNegativeNumber);
    fl::geom::TrapezoidParams tsm;
    for (const fl::TsmOption& t : fl::tsmOptions())
        app.add_option(std::string(t.flag), tsm.*t.field, std::string(t.help))
            ->check(CLI::Range(t.min, t.max))
            ->capture_default_str();
    bool withOff = false;
    app.add_flag(
        "--with-tsm-off", withOff,
        "Also measure TSM with every stability option 0 (the paper's fit) in a third lane");
    CLI11_PARSE(app, argc, argv);
    try {
        const fl::Scene scene = fl::loadGltf(
            scenePath.empty() ? std::string(FLOODLIGHT_SOURCE_DIR) + "/assets/default.glb"
                              : scenePath);
        auto ctx = fl::EglContext::create(false);
        const fl::gl::ShaderLibrary shaders;
        const fl::CameraPath path =
            fl::defaultWalkthrough(fl::makeCameraView(scene, {}, 1.0f), scene.bounds);
        // Lanes: uniform, TSM with the options given, and (--with-tsm-off) TSM without them.
        std::vector<std::string> names{"uniform", "tsm"};
        if (withOff) names.emplace_back("tsm-off");
        const int laneCount = static_cast<int>(names.size());
        std::vector<std::unique_ptr<fl::Renderer>> renderers;
        for (int k = 0; k < laneCount; ++k) {
            fl::RenderSettings s;
            s.shadow.size = shadowMap;
            s.shadow.provider = k ? fl::ShadowMapProvider::Tsm : fl::ShadowMapProvider::Uniform;
            if (k == 1) s.shadow.tsm = tsm;
            if (k == 2)
                for (const fl::TsmOption& t : fl::tsmOptions()) s.shadow.tsm.*t.field = 0.0f;
            s.diagnostics = true;
            renderers.push_back(std::make_unique<fl::Renderer>(shaders, scene, s));
            renderers.back()->resize(size, size);
        }
        std::vector<Series> series(names.size());
        std::vector<fl::Lane> lanes;
        for (int k = 0; k < laneCount; ++k) lanes.push_back({names[k], renderers[k].get(), {}});
        fl::FrameRunner runner(frames + timedFrames);
        fl::FramePlan plan{.scene = &scene,
                           .camera = path,
                           .frames = frames,
                           .width = size,
                           .height = size,
                           .readBack = false};
        runner.run(plan, lanes, [&](int i, std::vector<fl::FrameImages>&) {
            std::vector<fl::ByteImage> pictures;
            const bool save = !saveDir.empty() && (saveEvery > 0 ? i % saveEvery == 0 : i == 0);
            for (int k = 0; k < laneCount; ++k) {
                if (save && k < 2)
                    pictures.push_back(fl::toSrgb8(fl::readTexture(renderers[k]->color(), 4)));
                const fl::FloatImage d = fl::readTexture(*renderers[k]->diagnostics(), 4);
                const fl::ShadowMapStats st = fl::summarizeShadowDiagnostics(d);
                Series& s = series[k];
                s.fpMed.push_back(st.footprint.median);
                s.fpP95.push_back(st.footprint.p95);
                s.nearMed.push_back(st.footprintNear.median);
                s.nearP95.push_back(st.footprintNear.p95);
                if (const fl::geom::TrapezoidFit* fit = renderers[k]->shadow()->trapezoid) {
                    s.degenerateFrames += fit->degenerate;
                    s.heldFrames += fit->held;
                }
                if (i == 0) continue; // the first frame has no previous map
                s.flicker.push_back(st.flickerShare);
                const double e = edgeShare(d);
                s.flickerPerEdge.push_back(e > 0 ? st.flickerShare / e : 0.0);
            }
            if (pictures.size() == 2) {
                std::filesystem::create_directories(saveDir);
                char name[64];
                std::snprintf(name, sizeof name, "walk_%04d.uniform-vs-tsm.png", i);
                fl::writePng(std::filesystem::path(saveDir) / name, fl::sideBySide(pictures));
            }
        });
        // Timing without diagnostics, providers interleaved frame by frame over the same path,
        // after two warm-up frames.
        for (auto& r : renderers) {
            fl::RenderSettings s = r->settings();
            s.diagnostics = false;
            r->setSettings(s);
        }
        std::vector<fl::Lane> timed;
        for (const fl::Lane& l : lanes) timed.push_back({l.label, l.renderer, {}});
        plan.frames = timedFrames;
        plan.warmup = 2;
        runner.run(plan, timed);
        runner.finish();
        std::cout << "context: " << ctx->description() << "\n"
                  << "scene: " << scene.source << ", " << scene.triangleCount() << " triangles\n"
                  << "walkthrough: " << frames << " frames at " << size << "x" << size
                  << ", shadow map " << shadowMap << "^2 (every lane)\n"
                  << "tsm lane:";
        for (const fl::TsmOption& t : fl::tsmOptions())
            std::cout << " " << t.flag << " " << tsm.*t.field;
        std::cout << "\n" << std::fixed << std::setprecision(3);
        for (int k = 0; k < laneCount; ++k) {
            const Series& s = series[k];
            std::cout << names[k] << ":\n"
                      << "  footprint (px/texel), median over frames: all median "
                      << fl::median(s.fpMed) << " p95 " << fl::median(s.fpP95) << "; near median "
                      << fl::median(s.nearMed) << " p95 " << fl::median(s.nearP95) << "\n"
                      << "  flicker (share of receivers flipping per frame): mean "
                      << 100 * mean(s.flicker) << "% max " << 100 * maxOf(s.flicker)
                      << "%; per shadow-edge pixel: mean " << 100 * mean(s.flickerPerEdge)
                      << "% max " << 100 * maxOf(s.flickerPerEdge) << "%\n"
                      << "  frame (hard shadows, no diagnostics): min "
                      << fl::minimum(timed[k].times.frameMs()) << " ms, median "
                      << timed[k].times.medianFrameMs() << " ms ("
                      << renderers[k]->timer().modeName() << ")\n";
            if (k > 0)
                std::cout << "  frames with the uniform fallback blended in: " << s.degenerateFrames
                          << " of " << frames
                          << "; frames that kept the previous fit: " << s.heldFrames << "\n";
        }
        std::cout << "ratios uniform / tsm footprint near the viewer: median "
                  << fl::median(series[0].nearMed) / fl::median(series[1].nearMed) << ", p95 "
                  << fl::median(series[0].nearP95) / fl::median(series[1].nearP95) << "\n";
        for (int k = 1; k < laneCount; ++k)
            std::cout << names[k] << " / uniform frame time: min "
                      << fl::minimum(timed[k].times.frameMs()) /
                             fl::minimum(timed[0].times.frameMs())
                      << ", median "
                      << timed[k].times.medianFrameMs() / timed[0].times.medianFrameMs() << "\n";
        if (withOff)
            std::cout << "tsm / tsm-off frame time: min "
                      << fl::minimum(timed[1].times.frameMs()) /
                             fl::minimum(timed[2].times.frameMs())
                      << ", median "
                      << timed[1].times.medianFrameMs() / timed[2].times.medianFrameMs() << "\n";
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
