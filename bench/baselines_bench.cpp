// The baselines beside the JFA methods on the default scene, side by side in one process: per
// method the frame time (min/median over timed frames, methods interleaved frame by frame) and
// its ratio to hard shadows, and the visibility error against the ground truth (RMSE and max
// |d| over receivers). With --sampling-error the ground truth's own sampling error: N
// against 2N samples.

#include <base/Stats.h>
#include <renderer/Renderer.h>
#include <renderer/context/EglContext.h>
#include <renderer/gltf/GltfLoader.h>
#include <renderer/io/Capture.h>
#include <renderer/run/FrameRunner.h>
#include <renderer/soft/ReferenceShadow.h>

#include <base/Text.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace {

struct Entry {
    std::string label;
    fl::RenderSettings settings;
    std::unique_ptr<fl::Renderer> renderer;
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
        const fl::gl::ShaderLibrary shaders;
        const fl::CameraView cam = fl::makeCameraView(scene, {}, 1.0f);
        std::vector<Entry> entries;
        // The ground truth (timed and compared like the others, but last).
        const fl::MethodDescriptor& groundTruth = fl::methodOrThrow("reference");
        auto add = [&](std::string label, const fl::MethodDescriptor& m, std::string_view flag = {},
                       const std::string& value = {}) {
            fl::RenderSettings s;
            s.shadow.size = shadowMap;
            s.method = std::string(m.name);
            s.options.set("--reference-samples", samples);
            s.options.set("--reference-map-size", referenceMap);
            if (!flag.empty()) s.options.set(flag, value);
            Entry e{std::move(label), s, std::make_unique<fl::Renderer>(shaders, scene, s), {}};
            e.renderer->resize(size, size);
            entries.push_back(std::move(e));
        };
        // Every method of the table at its defaults, but the standard-flooding references
        // (flood-l, flood-e: the JFA methods' own yardsticks) and the ground truth; PCF at two
        // kernels, PCSS at every preset.
        for (const fl::MethodDescriptor& m : fl::methodTable()) {
            bool isReference = &m == &groundTruth;
            for (const fl::MethodDescriptor& other : fl::methodTable())
                isReference = isReference || other.reference == m.name;
            if (isReference) continue;
            const std::string name(m.name);
            if (m.name == "pcf") {
                for (int k : {3, 5})
                    add(fl::cat(name, " ", k, "x", k), m, m.options.front()->flag,
                        std::to_string(k));
            } else if (const fl::MethodOption* preset = m.option("preset")) {
                std::string_view choices = preset->choices;
                while (!choices.empty()) {
                    const std::size_t bar = choices.find('|');
                    const std::string p(choices.substr(0, bar));
                    add(fl::cat(name, " ", p), m, preset->flag, p);
                    choices = bar == std::string_view::npos ? std::string_view{}
                                                            : choices.substr(bar + 1);
                }
            } else {
                add(name, m);
            }
        }
        add(std::string(groundTruth.name), groundTruth);
        Entry& reference = entries.back();

        // The frame loop of capture/compare (renderer/run/FrameRunner.h): two warm-up frames
        // each, then timed frames with the methods interleaved frame by frame; the ground truth,
        // the slow one, in a second loop with fewer frames.
        std::vector<fl::Lane> lanes, referenceLane;
        for (Entry& e : entries)
            (&e == &reference ? referenceLane : lanes).push_back({e.label, e.renderer.get(), {}});
        fl::FrameRunner runner(frames + referenceFrames);
        const auto plan = [&](int n) {
            return fl::FramePlan{.scene = &scene,
                                 .camera = cam,
                                 .frames = n,
                                 .width = size,
                                 .height = size,
                                 .warmup = 2,
                                 .readBack = false};
        };
        runner.run(plan(frames), lanes);
        runner.run(plan(referenceFrames), referenceLane);
        runner.finish();
        lanes.push_back(std::move(referenceLane.front()));
        for (Entry& e : entries) e.visibility = fl::readTexture(e.renderer->visibility(), 1);
        // Receivers: visible surfaces facing the light (renderer/metrics/Metrics.h), the same in
        // every method's frame.
        const fl::FloatImage mask = fl::readTexture(entries.front().renderer->receivers(), 1);

        const double hardMedian = lanes.front().times.medianFrameMs();
        std::printf("default scene %dx%d, map %dx%d, light radius %.2f, reference N=%d at %dx%d\n",
                    size, size, shadowMap, shadowMap, static_cast<double>(radius), samples,
                    referenceMap, referenceMap);
        std::printf("%-12s %10s %10s %8s %8s %10s %8s\n", "method", "min ms", "median ms", "xhard",
                    "frames", "RMSE ref", "max|d|");
        for (std::size_t i = 0; i < entries.size(); ++i) {
            const Entry& e = entries[i];
            const fl::PhaseTimes& t = lanes[i].times;
            const fl::VisibilityDifference d =
                fl::visibilityDifference(e.visibility, reference.visibility, mask);
            std::printf("%-12s %10.2f %10.2f %8.2f %8zu %10.4f %8.3f\n", e.label.c_str(),
                        fl::minimum(t.frameMs()), t.medianFrameMs(), t.medianFrameMs() / hardMedian,
                        t.frames(), d.rmse, d.maxAbs);
        }
        if (samplingError) {
            fl::RenderSettings s = reference.settings;
            s.options.set("--reference-samples", 2 * samples);
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
