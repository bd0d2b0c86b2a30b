// The baselines beside the JFA methods on the default scene, side by side in one process: per
// method the frame time (min/median over timed frames, methods interleaved frame by frame) and
// its ratio to hard shadows, and the visibility error against both ground truths (RMSE over
// receivers and over penumbra pixels, max |d|): the shadow-map one ("maps") and the ray-traced
// one ("raytrace", exact). With --sampling-error the maps ground truth's own sampling error: N
// against 2N samples.

#include <base/Stats.h>
#include <renderer/Renderer.h>
#include <renderer/context/EglContext.h>
#include <renderer/io/TextureImage.h>
#include <renderer/run/Capture.h>
#include <renderer/run/FrameRunner.h>
#include <renderer/soft/ReferenceShadow.h>
#include <renderer/soft/ShadowRayInputs.h>
#include <scene/GltfLoader.h>

#include <BenchSupport.h>
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

struct Options {
    int size = 512, shadowMap = 1024, frames = 10, referenceFrames = 2, samples = 256,
        referenceMap = 2048, raySamples = 256;
    float radius = 1.5f;
    bool samplingError = false;
    std::string terminatorOffset = "on";
};

void addOptions(CLI::App& app, Options& o) {
    fl::bench::addFrameSizeOptions(app, o.size, o.shadowMap);
    app.add_option("--light-radius", o.radius)->capture_default_str();
    app.add_option("--frames", o.frames, "Timed frames per method")
        ->check(CLI::Range(1, 10000))
        ->capture_default_str();
    app.add_option("--reference-frames", o.referenceFrames, "Timed frames of each ground truth")
        ->check(CLI::Range(1, 10000))
        ->capture_default_str();
    app.add_option("--reference-samples", o.samples)
        ->check(CLI::Range(1, 65536))
        ->capture_default_str();
    app.add_option("--reference-map-size", o.referenceMap)->capture_default_str();
    app.add_option("--raytrace-samples", o.raySamples, "Shadow rays per pixel of the exact truth")
        ->check(CLI::Range(1, 16384))
        ->capture_default_str();
    app.add_option("--terminator-offset", o.terminatorOffset,
                   "The ray-traced truth's rays leave the smooth surface (on) or the flat "
                   "triangle (off)")
        ->check(CLI::IsMember({"on", "off"}))
        ->capture_default_str();
    app.add_flag("--sampling-error", o.samplingError,
                 "Also render the ground truth with 2N samples and report N vs 2N");
}

// The methods' renderers, then the ground truths'; returns how many are methods.
struct Entries {
    const Options& o;
    const fl::gl::ShaderLibrary& shaders;
    const fl::Scene& scene;
    std::vector<Entry> all;
    std::size_t methods = 0;

    void add(std::string label, const fl::MethodDescriptor& m, std::string_view flag = {},
             const std::string& value = {}) {
        fl::RenderSettings s;
        s.shadow.size = o.shadowMap;
        s.method = std::string(m.name);
        s.options.set("--reference-samples", o.samples);
        s.options.set("--reference-map-size", o.referenceMap);
        s.options.set("--raytrace-samples", o.raySamples);
        s.options.set("--terminator-offset", o.terminatorOffset);
        if (!flag.empty()) s.options.set(flag, value);
        Entry e{std::move(label), s, std::make_unique<fl::Renderer>(shaders, scene, s), {}};
        e.renderer->resize(o.size, o.size);
        all.push_back(std::move(e));
    }

    // Every method of the table at its defaults, but the standard-flooding references
    // (flood-l, flood-e: the JFA methods' own yardsticks) and the ground truths; a method with a
    // swept option once per value (bench/support: sweptMethods). The ground truths last, timed
    // on fewer frames.
    void addAll() {
        for (const fl::bench::MethodEntry& e : fl::bench::sweptMethods(false))
            add(e.label, *e.method, e.flag, e.value);
        methods = all.size();
        for (const fl::MethodDescriptor& m : fl::methodTable())
            if (!m.truth.empty()) add(std::string(m.truth), m);
    }

    Entry& truth(std::string_view kind) {
        for (std::size_t i = methods; i < all.size(); ++i)
            if (all[i].label == kind) return all[i];
        throw std::logic_error("no ground truth " + std::string(kind));
    }
};

// The frame loop of capture/compare (renderer/run/FrameRunner.h): two warm-up frames each, then
// timed frames with the methods interleaved frame by frame; the ground truths, the slow ones, in
// a second loop with fewer frames. Returns the lanes in the entries' order.
std::vector<fl::Lane> timeEntries(const Options& o, const fl::Scene& scene,
                                  const fl::CameraView& cam, Entries& entries) {
    std::vector<fl::Lane> lanes, truthLanes;
    for (std::size_t i = 0; i < entries.all.size(); ++i)
        (i < entries.methods ? lanes : truthLanes)
            .push_back({entries.all[i].label, entries.all[i].renderer.get(), {}});
    fl::FrameRunner runner(o.frames + o.referenceFrames);
    const auto plan = [&](int n, int warmup) {
        return fl::FramePlan{.scene = &scene,
                             .camera = cam,
                             .frames = n,
                             .width = o.size,
                             .height = o.size,
                             .warmup = warmup,
                             .readBack = false};
    };
    runner.run(plan(o.frames, 2), lanes);
    runner.run(plan(o.referenceFrames, 1), truthLanes);
    runner.finish();
    for (fl::Lane& l : truthLanes) lanes.push_back(std::move(l));
    for (Entry& e : entries.all) e.visibility = fl::readTexture(e.renderer->visibility(), 1);
    return lanes;
}

// Where the two ground truths differed most: receivers (the smooth shading normal faces the
// light) whose triangle faces away from the light's centre ("terminator": with
// --terminator-offset off the ray tracer's rays leave the flat triangle, which blocks them;
// shadow maps light it through their depth bias), and the rest. Returns the "facing" mask.
fl::FloatImage printTerminatorSplit(const fl::FloatImage& mask, const Entry& reference,
                                    const Entry& exact) {
    fl::FloatImage terminator = mask, facing = mask;
    // The ray tracer's own receivers (GL row order; the images here are top row first).
    const std::vector<fl::rt::Receiver> receivers =
        fl::surfaceReceivers(exact.renderer->surfaces());
    const glm::vec3 c = exact.renderer->disk().center;
    const int w = mask.width, h = mask.height;
    for (std::size_t i = 0; i < mask.data.size(); ++i) {
        const std::size_t x = i % static_cast<std::size_t>(w), y = i / static_cast<std::size_t>(w);
        const fl::rt::Receiver& r =
            receivers[(static_cast<std::size_t>(h) - 1 - y) * static_cast<std::size_t>(w) + x];
        const bool away = glm::dot(r.normal, c - r.position) <= 0.0f;
        terminator.data[i] = mask.data[i] > 0.5f && away ? 1.0f : 0.0f;
        facing.data[i] = mask.data[i] > 0.5f && !away ? 1.0f : 0.0f;
    }
    const fl::VisibilityDifference t =
        fl::visibilityDifference(reference.visibility, exact.visibility, terminator);
    const fl::VisibilityDifference f =
        fl::visibilityDifference(reference.visibility, exact.visibility, facing);
    std::printf("maps vs raytrace: triangle facing the light: %zu receivers, RMSE %.4f; "
                "facing away (terminator): %zu receivers, RMSE %.4f\n",
                f.pixels, f.rmse, t.pixels, t.rmse);
    return facing;
}

// One row per entry: times, ratio to hard, errors against both truths. Penumbra pixels:
// receivers whose exact visibility is in (0.02, 0.98) (the capture report's definition, from
// the ray-traced frame). Last column: against the ray-traced truth, the terminator left out.
void printTable(const Entries& entries, const std::vector<fl::Lane>& lanes,
                const fl::FloatImage& mask, const fl::FloatImage& facing, const Entry& reference,
                const Entry& exact) {
    fl::FloatImage penumbra = mask;
    for (std::size_t i = 0; i < penumbra.data.size(); ++i) {
        const float v = exact.visibility.data[i];
        penumbra.data[i] = mask.data[i] > 0.5f && v > 0.02f && v < 0.98f ? 1.0f : 0.0f;
    }
    const double hardMedian = lanes.front().times.medianFrameMs();
    std::printf("%-12s %9s %9s %7s %6s | %9s %9s %7s | %9s %9s %7s %9s\n", "method", "min ms",
                "median ms", "xhard", "frames", "RMSE maps", "penumbra", "max|d|", "RMSE rays",
                "penumbra", "max|d|", "no termin");
    for (std::size_t i = 0; i < entries.all.size(); ++i) {
        const Entry& e = entries.all[i];
        const fl::PhaseTimes& t = lanes[i].times;
        const auto diff = [&](const Entry& truthEntry, const fl::FloatImage& where) {
            return fl::visibilityDifference(e.visibility, truthEntry.visibility, where);
        };
        const fl::VisibilityDifference m = diff(reference, mask), mp = diff(reference, penumbra),
                                       x = diff(exact, mask), xp = diff(exact, penumbra),
                                       xf = diff(exact, facing);
        std::printf("%-12s %9.2f %9.2f %7.2f %6zu | %9.4f %9.4f %7.3f | %9.4f %9.4f %7.3f %9.4f\n",
                    e.label.c_str(), fl::minimum(t.frameMs()), t.medianFrameMs(),
                    t.medianFrameMs() / hardMedian, t.frames(), m.rmse, mp.rmse, m.maxAbs, x.rmse,
                    xp.rmse, x.maxAbs, xf.rmse);
    }
    std::printf("receivers %zu, penumbra pixels %zu\n",
                fl::visibilityDifference(mask, mask, mask).pixels,
                fl::visibilityDifference(mask, mask, penumbra).pixels);
}

// The maps truth's own sampling error: N against 2N samples.
void printSamplingError(const Options& o, const fl::CameraView& cam, Entry& reference,
                        const fl::FloatImage& mask) {
    fl::RenderSettings s = reference.settings;
    s.options.set("--reference-samples", 2 * o.samples);
    reference.renderer->setSettings(s);
    reference.renderer->render(cam);
    const fl::FloatImage twice = fl::readTexture(reference.renderer->visibility(), 1);
    const fl::VisibilityDifference d = fl::visibilityDifference(reference.visibility, twice, mask);
    std::printf("reference sampling error, N=%d vs 2N=%d over %zu receivers: RMSE "
                "%.5f, max |d| %.4f\n",
                o.samples, 2 * o.samples, d.pixels, d.rmse, d.maxAbs);
}

int runBench(const Options& o) {
    fl::Scene scene = fl::bench::loadBenchScene();
    if (scene.light) scene.light->radius = o.radius;
    auto ctx = fl::EglContext::create(false);
    const fl::gl::ShaderLibrary shaders;
    const fl::CameraView cam = fl::makeCameraView(scene, {}, 1.0f);
    Entries entries{o, shaders, scene, {}, 0};
    entries.addAll();
    Entry& reference = entries.truth("maps");
    Entry& exact = entries.truth(fl::kExactTruth);
    const std::vector<fl::Lane> lanes = timeEntries(o, scene, cam, entries);
    // Receivers: visible surfaces facing the light (renderer/metrics/Metrics.h), the same in
    // every method's frame.
    const fl::FloatImage mask = fl::readTexture(entries.all.front().renderer->receivers(), 1);
    std::printf("default scene %dx%d, map %dx%d, light radius %.2f; ground truths: maps N=%d "
                "at %dx%d, raytrace N=%d (terminator offset %s)\n",
                o.size, o.size, o.shadowMap, o.shadowMap, static_cast<double>(o.radius), o.samples,
                o.referenceMap, o.referenceMap, o.raySamples, o.terminatorOffset.c_str());
    const fl::FloatImage facing = printTerminatorSplit(mask, reference, exact);
    printTable(entries, lanes, mask, facing, reference, exact);
    if (o.samplingError) printSamplingError(o, cam, reference, mask);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"baselines_bench: hard, PCF, PCSS, JFA-L, JFA-E and the ground truth, side by "
                 "side"};
    Options o;
    addOptions(app, o);
    return fl::bench::parseAndRun(app, argc, argv, [&] { return runBench(o); });
}
