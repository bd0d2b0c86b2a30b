// The main job without a display: the default scene with every method of the table beside the
// ground truth, one labelled picture (name, RMSE against the ground truth, frame time / hard) and
// each method's PNG/EXR beside it. The ground truth is the ray-traced one (exact visibility); the
// shadow-map ground truth is scored like the methods, which shows its own error.

#include <app/Commands.h>

#include <renderer/context/EglContext.h>
#include <renderer/metrics/Metrics.h>
#include <renderer/metrics/ShadowStats.h>
#include <renderer/passes/HudPass.h>
#include <renderer/run/Capture.h>

#include <base/Stats.h>
#include <base/Text.h>

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <iostream>

namespace fl::app {

namespace {

// The default scene's own light is nearly a point (its penumbrae are under a texel); the
// overview shows soft shadows, so without --light-radius it uses the radius the goldens use.
constexpr float kOverviewLightRadius = 1.5f;
// Timed frames per method after one warm-up frame (the median is reported); the ground truths,
// hundreds of maps or rays per pixel per frame, are timed on one frame after their warm-up.
constexpr int kTimedFrames = 3;
constexpr int kColumns = 4;

struct Result {
    std::string name;
    FrameImages frame;
    double medianMs = 0.0;
    double rmse = 0.0;
};

} // namespace

int renderOverview(SceneOptions o, int width, int height, const std::filesystem::path& outDir,
                   const std::string& stem) {
    if (!o.lightRadius) o.lightRadius = kOverviewLightRadius;
    o.strictMethodOptions = false; // every method runs, each reads its own options
    const Scene scene = loadScene(o);
    const CameraView camera = initialCamera(scene, o, width, height);
    auto context = EglContext::create();
    const gl::ShaderLibrary shaders = makeShaderLibrary(o);
    std::cout << "context: " << context->description() << "\n"
              << "scene: " << scene.source << " (" << scene.triangleCount()
              << " triangles), light radius " << *o.lightRadius << ", " << width << "x" << height
              << ", every method of the table against the ground truth\n"
              << setupLine(scene, makeRenderSettings(o), width, height) << "\n";
    std::vector<Result> results;
    for (const MethodDescriptor& m : methodTable()) {
        RenderSettings settings = makeRenderSettings(o);
        settings.method = std::string(m.name);
        checkMethodOptions(settings, width, height);
        Renderer renderer(shaders, scene, settings);
        renderer.resize(width, height);
        renderer.render(camera); // warm-up: first-use allocations and shader compiles
        std::vector<double> ms;
        for (int i = 0; i < (m.truth.empty() ? kTimedFrames : 1); ++i) {
            renderer.render(camera);
            ms.push_back(renderer.timer().frameMs());
        }
        results.push_back({std::string(m.name), readFrame(renderer), median(ms), 0.0});
        std::cout << "  " << m.name << ": " << fixed(results.back().medianMs, 1) << " ms\n"
                  << std::flush;
    }
    const auto byName = [&](std::string_view name) -> const Result& {
        return *std::find_if(results.begin(), results.end(),
                             [&](const Result& r) { return r.name == name; });
    };
    // Every figure against the exact answer: the ray-traced ground truth (the shadow-map one
    // is scored like the methods, which shows its own error).
    const Result& truth = byName(groundTruth(kExactTruth).name);
    const double hardMs = std::max(byName(cheapestMethod().name).medianMs, 1e-9);

    // Every image is made before anything is written; each file is written under a temporary
    // name and renamed.
    std::vector<ByteImage> tiles;
    std::cout << std::left << std::setw(12) << "method" << std::right << std::setw(10) << "RMSE"
              << std::setw(12) << "ms" << std::setw(10) << "x hard"
              << "\n";
    for (Result& r : results) {
        r.rmse =
            compareWithReference(r.frame.visibility, truth.frame.visibility, truth.frame.receivers)
                .rmse;
        const double ratio = r.medianMs / hardMs;
        std::cout << std::left << std::setw(12) << r.name << std::right << std::setw(10)
                  << fixed(r.rmse, 4) << std::setw(12) << fixed(r.medianMs, 1) << std::setw(10)
                  << fixed(ratio, 2) << "\n";
        ByteImage tile = toSrgb8(r.frame.color);
        const std::vector<std::string> label = {
            r.name, &r == &truth ? std::string("ground truth") : "RMSE " + fixed(r.rmse, 4),
            "time " + fixed(ratio, 2) + "x hard"};
        HudStyle style;
        style.margin = 3;
        rasterizeHud(layoutHud(label, style), tile);
        tiles.push_back(std::move(tile));
    }
    std::vector<std::filesystem::path> written;
    for (const Result& r : results) {
        const CapturePaths p = writeFrame(r.frame, outDir, stem + "." + r.name);
        written.insert(written.end(), {p.png, p.visibilityPng, p.exr});
    }
    const std::filesystem::path picture = outDir / (stem + ".png");
    writePng(picture, tileGrid(tiles, kColumns));
    written.push_back(picture);
    for (const std::filesystem::path& p : written) std::cout << "wrote " << p.string() << "\n";
    std::cout << "overview: " << picture.string()
              << " (each method's name, RMSE against the ground truth over receivers, frame "
                 "time / hard)\n";
    return 0;
}

} // namespace fl::app
