// The baselines beside the JFA methods on the default scene, side by side in one process: per
// method the frame time (min/median over timed frames, methods interleaved frame by frame) and
// its ratio to hard shadows, and the visibility error against the ground truth (RMSE and max
// |d| over receivers). With --sampling-error the ground truth's own sampling error: N
// against 2N samples.

#include <base/Stats.h>
#include <renderer/Capture.h>
#include <renderer/EglContext.h>
#include <renderer/GltfLoader.h>
#include <renderer/Renderer.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace {

struct Entry {
    std::string label;
    fl::RenderSettings settings;
    std::unique_ptr<fl::Renderer> renderer;
    std::vector<double> ms;
    fl::FloatImage visibility;
};

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"baselines_bench: hard, PCF, PCSS, JFA-L, JFA-E and the ground truth, side by "
                 "side"};
    int size = 512, shadowMap = 1024, frames = 10, referenceFrames = 2, samples = 256,
        referenceMap = 2048;
    float radius = 1.5f;
    bool samplingError = false;
    app.add_option("--size", size, "Frame width and height")->capture_default_str();
    app.add_option("--shadow-map-size", shadowMap)->capture_default_str();
    app.add_option("--light-radius", radius)->capture_default_str();
    app.add_option("--frames", frames, "Timed frames per method")
        ->check(CLI::Range(1, 10000))
        ->capture_default_str();
    app.add_option("--reference-frames", referenceFrames, "Timed frames of the ground truth")
        ->check(CLI::Range(1, 10000))
        ->capture_default_str();
    app.add_option("--reference-samples", samples)
        ->check(CLI::Range(1, 65536))
        ->capture_default_str();
    app.add_option("--reference-map-size", referenceMap)->capture_default_str();
    app.add_flag("--sampling-error", samplingError,
                 "Also render the ground truth with 2N samples and report N vs 2N");
    CLI11_PARSE(app, argc, argv);
    try {
        fl::Scene scene = fl::loadGltf(std::string(FLOODLIGHT_SOURCE_DIR) + "/assets/default.glb");
        if (scene.light) scene.light->radius = radius;
        auto ctx = fl::EglContext::create(false);
        const fl::ShaderLibrary shaders;
        const fl::CameraView cam = fl::makeCameraView(scene, {}, 1.0f);
        std::vector<Entry> entries;
        auto add = [&](std::string label, fl::ShadowMethod m, auto tweak) {
            fl::RenderSettings s;
            s.shadow.size = shadowMap;
            s.method = m;
            s.reference.samples = samples;
            s.reference.mapSize = referenceMap;
            tweak(s);
            Entry e{std::move(label), s, std::make_unique<fl::Renderer>(shaders, scene, s), {}, {}};
            e.renderer->resize(size, size);
            entries.push_back(std::move(e));
        };
        auto none = [](fl::RenderSettings&) {};
        add("hard", fl::ShadowMethod::Hard, none);
        add("pcf 3x3", fl::ShadowMethod::Pcf,
            [](fl::RenderSettings& s) { s.filtered.pcfKernel = 3; });
        add("pcf 5x5", fl::ShadowMethod::Pcf,
            [](fl::RenderSettings& s) { s.filtered.pcfKernel = 5; });
        for (const char* p : {"16/16", "16/24", "32/64"})
            add(std::string("pcss ") + p, fl::ShadowMethod::Pcss,
                [p](fl::RenderSettings& s) { s.filtered.pcss = *fl::parsePcssPreset(p); });
        add("jfa-l", fl::ShadowMethod::JfaL, none);
        add("jfa-e", fl::ShadowMethod::JfaE, none);
        add("reference", fl::ShadowMethod::Reference, none);
        Entry& reference = entries.back();

        // Two warm-up frames each, then interleaved timed frames (the ground truth fewer).
        for (int i = 0; i < frames + 2; ++i)
            for (Entry& e : entries) {
                if (&e == &reference && i >= referenceFrames + 2) continue;
                e.renderer->render(cam);
                if (i >= 2) e.ms.push_back(e.renderer->timer().frameMs());
            }
        for (Entry& e : entries) e.visibility = fl::readTexture(e.renderer->visibility(), 1);
        // Receivers: visible surfaces facing the light (renderer/Metrics.h), the same in every
        // method's frame.
        const fl::FloatImage mask = fl::readTexture(entries.front().renderer->receivers(), 1);

        const double hardMedian = fl::median(entries.front().ms);
        std::printf("default scene %dx%d, map %dx%d, light radius %.2f, reference N=%d at %dx%d\n",
                    size, size, shadowMap, shadowMap, static_cast<double>(radius), samples,
                    referenceMap, referenceMap);
        std::printf("%-12s %10s %10s %8s %8s %10s %8s\n", "method", "min ms", "median ms", "xhard",
                    "frames", "RMSE ref", "max|d|");
        for (const Entry& e : entries) {
            const fl::VisibilityDifference d =
                fl::visibilityDifference(e.visibility, reference.visibility, mask);
            std::printf("%-12s %10.2f %10.2f %8.2f %8zu %10.4f %8.3f\n", e.label.c_str(),
                        fl::minimum(e.ms), fl::median(e.ms), fl::median(e.ms) / hardMedian,
                        e.ms.size(), d.rmse, d.maxAbs);
        }
        if (samplingError) {
            fl::RenderSettings s = reference.settings;
            s.reference.samples = 2 * samples;
            reference.renderer->setSettings(s);
            reference.renderer->render(cam);
            const fl::FloatImage twice = fl::readTexture(reference.renderer->visibility(), 1);
            const fl::VisibilityDifference d =
                fl::visibilityDifference(reference.visibility, twice, mask);
            std::printf("reference sampling error, N=%d vs 2N=%d over %zu receivers: RMSE "
                        "%.5f, max |d| %.4f\n",
                        samples, 2 * samples, d.pixels, d.rmse, d.maxAbs);
        }
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
