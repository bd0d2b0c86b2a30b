// TSM vs uniform shadow map on a scripted walkthrough (scene/CameraPath.h) at equal
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
#include <renderer/io/TextureImage.h>
#include <renderer/metrics/ShadowStats.h>
#include <renderer/run/Capture.h>
#include <renderer/run/FrameRunner.h>
#include <scene/CameraPath.h>
#include <scene/GltfLoader.h>
#include <scene/SceneGenerator.h>

#include <base/Stats.h>

#include <BenchSupport.h>
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

struct Options {
    std::string scenePath;
    int size = 512, shadowMap = 1024, frames = 120, timedFrames = 20, saveEvery = 0;
    std::string saveDir;
    fl::geom::TrapezoidParams tsm;
    bool withOff = false;
};

void addOptions(CLI::App& app, Options& o) {
    app.add_option("--scene", o.scenePath, "glTF scene (default: assets/default.glb)");
    fl::bench::addFrameSizeOptions(app, o.size, o.shadowMap);
    app.add_option("--frames", o.frames, "Walkthrough frames measured")
        ->check(CLI::Range(2, 100000))
        ->capture_default_str();
    app.add_option("--timed-frames", o.timedFrames, "Frames timed per provider (interleaved)")
        ->check(CLI::Range(1, 100000))
        ->capture_default_str();
    app.add_option("--save", o.saveDir,
                   "Write uniform | TSM side-by-side PNGs of every --save-every-th frame here");
    app.add_option("--save-every", o.saveEvery, "Frame interval for --save (0 = only the first)")
        ->check(CLI::NonNegativeNumber);
    for (const fl::TsmOption& t : fl::tsmOptions())
        app.add_option(std::string(t.flag), o.tsm.*t.field, std::string(t.help))
            ->check(CLI::Range(t.min, t.max))
            ->capture_default_str();
    app.add_flag(
        "--with-tsm-off", o.withOff,
        "Also measure TSM with every stability option 0 (the paper's fit) in a third lane");
}

// Lanes: uniform, TSM with the options given, and (--with-tsm-off) TSM without them; every
// lane renders hard shadows with diagnostics (footprint, flicker).
std::vector<std::unique_ptr<fl::Renderer>> makeRenderers(const Options& o,
                                                         const fl::gl::ShaderLibrary& shaders,
                                                         const fl::Scene& scene, int lanes) {
    std::vector<std::unique_ptr<fl::Renderer>> renderers;
    for (int k = 0; k < lanes; ++k) {
        fl::RenderSettings s;
        s.shadow.size = o.shadowMap;
        s.shadow.provider = k ? fl::ShadowMapProvider::Tsm : fl::ShadowMapProvider::Uniform;
        if (k == 1) s.shadow.tsm = o.tsm;
        if (k == 2)
            for (const fl::TsmOption& t : fl::tsmOptions()) s.shadow.tsm.*t.field = 0.0f;
        s.diagnostics = true;
        renderers.push_back(std::make_unique<fl::Renderer>(shaders, scene, s));
        renderers.back()->resize(o.size, o.size);
    }
    return renderers;
}

// One walkthrough frame's figures for every lane, and (--save) the side-by-side picture.
void measureFrame(const Options& o, int i,
                  const std::vector<std::unique_ptr<fl::Renderer>>& renderers,
                  std::vector<Series>& series) {
    std::vector<fl::ByteImage> pictures;
    const bool save = !o.saveDir.empty() && (o.saveEvery > 0 ? i % o.saveEvery == 0 : i == 0);
    for (std::size_t k = 0; k < renderers.size(); ++k) {
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
        std::filesystem::create_directories(o.saveDir);
        char name[64];
        std::snprintf(name, sizeof name, "walk_%04d.uniform-vs-tsm.png", i);
        fl::writePng(std::filesystem::path(o.saveDir) / name, fl::sideBySide(pictures));
    }
}

// Every lane's figures, then the ratios to uniform (and to tsm-off).
void printReport(const Options& o, const std::vector<std::string>& names,
                 const std::vector<Series>& series, const std::vector<fl::Lane>& timed,
                 const std::vector<std::unique_ptr<fl::Renderer>>& renderers) {
    std::cout << std::fixed << std::setprecision(3);
    for (std::size_t k = 0; k < names.size(); ++k) {
        const Series& s = series[k];
        std::cout << names[k] << ":\n"
                  << "  footprint (px/texel), median over frames: all median "
                  << fl::median(s.fpMed) << " p95 " << fl::median(s.fpP95) << "; near median "
                  << fl::median(s.nearMed) << " p95 " << fl::median(s.nearP95) << "\n"
                  << "  flicker (share of receivers flipping per frame): mean "
                  << 100 * mean(s.flicker) << "% max " << 100 * maxOf(s.flicker)
                  << "%; per shadow-edge pixel: mean " << 100 * mean(s.flickerPerEdge) << "% max "
                  << 100 * maxOf(s.flickerPerEdge) << "%\n"
                  << "  frame (hard shadows, no diagnostics): min "
                  << fl::minimum(timed[k].times.frameMs()) << " ms, median "
                  << timed[k].times.medianFrameMs() << " ms (" << renderers[k]->timer().modeName()
                  << ")\n";
        if (k > 0)
            std::cout << "  frames with the uniform fallback blended in: " << s.degenerateFrames
                      << " of " << o.frames
                      << "; frames that kept the previous fit: " << s.heldFrames << "\n";
    }
    std::cout << "ratios uniform / tsm footprint near the viewer: median "
              << fl::median(series[0].nearMed) / fl::median(series[1].nearMed) << ", p95 "
              << fl::median(series[0].nearP95) / fl::median(series[1].nearP95) << "\n";
    const auto ratio = [&](std::size_t a, std::size_t b) {
        return std::make_pair(fl::minimum(timed[a].times.frameMs()) /
                                  fl::minimum(timed[b].times.frameMs()),
                              timed[a].times.medianFrameMs() / timed[b].times.medianFrameMs());
    };
    for (std::size_t k = 1; k < names.size(); ++k) {
        const auto [min, median] = ratio(k, 0);
        std::cout << names[k] << " / uniform frame time: min " << min << ", median " << median
                  << "\n";
    }
    if (o.withOff) {
        const auto [min, median] = ratio(1, 2);
        std::cout << "tsm / tsm-off frame time: min " << min << ", median " << median << "\n";
    }
}

int runBench(const Options& o) {
    const fl::Scene scene = fl::bench::loadBenchScene(o.scenePath);
    auto ctx = fl::EglContext::create(false);
    const fl::gl::ShaderLibrary shaders;
    const fl::CameraPath path =
        fl::defaultWalkthrough(fl::makeCameraView(scene, {}, 1.0f), scene.bounds);
    std::vector<std::string> names{"uniform", "tsm"};
    if (o.withOff) names.emplace_back("tsm-off");
    const std::vector<std::unique_ptr<fl::Renderer>> renderers =
        makeRenderers(o, shaders, scene, static_cast<int>(names.size()));
    std::vector<Series> series(names.size());
    std::vector<fl::Lane> lanes = fl::bench::lanesOf(names, renderers);
    fl::FrameRunner runner(o.frames + o.timedFrames);
    fl::FramePlan plan{.scene = &scene,
                       .camera = path,
                       .frames = o.frames,
                       .width = o.size,
                       .height = o.size,
                       .readBack = false};
    runner.run(plan, lanes, [&](int i, std::vector<fl::FrameImages>&) {
        measureFrame(o, i, renderers, series);
    });
    // Timing without diagnostics, providers interleaved frame by frame over the same path,
    // after two warm-up frames.
    for (const auto& r : renderers) {
        fl::RenderSettings s = r->settings();
        s.diagnostics = false;
        r->setSettings(s);
    }
    std::vector<fl::Lane> timed = fl::bench::lanesOf(names, renderers);
    plan.frames = o.timedFrames;
    plan.warmup = 2;
    runner.run(plan, timed);
    runner.finish();
    std::cout << "context: " << ctx->description() << "\n"
              << "scene: " << scene.source << ", " << scene.triangleCount() << " triangles\n"
              << "walkthrough: " << o.frames << " frames at " << o.size << "x" << o.size
              << ", shadow map " << o.shadowMap << "^2 (every lane)\n"
              << "tsm lane:";
    for (const fl::TsmOption& t : fl::tsmOptions())
        std::cout << " " << t.flag << " " << o.tsm.*t.field;
    std::cout << "\n";
    printReport(o, names, series, timed, renderers);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"tsm_bench: TSM vs uniform shadow map along a walkthrough, side by side"};
    Options o;
    addOptions(app, o);
    return fl::bench::parseAndRun(app, argc, argv, [&] { return runBench(o); });
}
