// `floodlight compare`: a soft-shadow method against its standard-flooding reference over a
// walkthrough (thesis Fig. 5.4 / 5.8): one CSV row per frame, a JSON summary, and the frame with
// the largest difference side by side (method | reference | difference) as PNG and EXR.

#include <app/Commands.h>

#include <base/OutputFiles.h>

#include <base/InputFile.h>
#include <renderer/passes/Phases.h>
#include <renderer/run/FrameRunner.h>

#include <renderer/context/EglContext.h>
#include <renderer/metrics/ShadowStats.h>
#include <renderer/metrics/SoftStats.h>
#include <renderer/run/Capture.h>
#include <scene/CameraPath.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iomanip>
#include <iostream>

namespace fl::app {

namespace {

struct CompareRequest {
    SceneOptions scene;
    std::string path = "default"; // "default" or a camera-path JSON file
    std::string method = "jfa-l";
    std::string out = "captures/compare";
    int frames = 60;
    int width = 512, height = 512;
    double animationFps = 0.0; // --animation-fps: frame i posed at --time + i / fps (0: still)
};

// frames.csv: per frame the |dI| statistics, then each lane's time per phase (the phases either
// renderer's timer reported, in the order they ran) and per frame, then each lane's flood: the
// passes it ran and the share of texels its band covered.
CsvTable compareCsv(const std::vector<SoftStats>& stats, const std::vector<Lane>& lanes) {
    const std::vector<std::string> phases = phaseNames({&lanes[0].times, &lanes[1].times});
    std::vector<std::string> columns = {
        "frame",      "penumbra_reference", "penumbra_method", "dI_lt_0.05", "dI_0.05_0.1",
        "dI_0.1_0.2", "dI_ge_0.2",          "parity_percent",  "max_dI",     "mean_dI"};
    for (const Lane& lane : lanes)
        for (const std::string& p : phases)
            columns.push_back(lane.label + "_" + csvName(p) + "_ms");
    for (const Lane& lane : lanes) columns.push_back(lane.label + "_frame_ms");
    for (const Lane& lane : lanes) {
        columns.push_back(lane.label + "_jfa_passes");
        columns.push_back(lane.label + "_active_share");
    }
    CsvTable csv(columns);
    for (std::size_t i = 0; i < stats.size(); ++i) {
        const SoftStats& s = stats[i];
        csv << i << s.penumbraReference << s.penumbraMethod;
        for (double d : s.deltaBuckets) csv << 100.0 * d;
        csv << 100.0 * s.parityShare << s.maxDelta << s.meanDelta;
        for (const Lane& lane : lanes)
            for (const std::string& p : phases) csv << lane.times.phaseMs(i, p);
        for (const Lane& lane : lanes) csv << lane.times.frameMs().at(i);
        for (const Lane& lane : lanes) {
            if (const std::optional<FloodSample>& f = lane.times.flood(i))
                csv << f->passes << f->activeShare;
            else
                csv.blank().blank();
        }
        csv.endRow();
    }
    return csv;
}

// The method's standard-flooding reference, or one clear error naming the methods with one.
std::string referenceOrThrow(const std::string& method) {
    if (const std::optional<std::string> reference = referenceOf(method)) return *reference;
    const std::string valid =
        methodNamesWhere([](const MethodDescriptor& d) { return !d.reference.empty(); });
    throw InputError("--method " + method + ": no standard-flooding reference for it (" + valid +
                     " have one)");
}

// The walkthrough: --path's file, or the default swing around the scene's first view.
CameraPath comparePath(const CompareRequest& r, const Scene& scene) {
    if (r.path != "default") {
        try {
            return readCameraPath(r.path, "--path");
        } catch (const std::runtime_error& e) {
            throw InputError(e.what());
        }
    }
    return defaultWalkthrough(initialCamera(scene, r.scene, r.width, r.height), scene.bounds);
}

// Every frame's statistics and the worst frame's pictures.
struct CompareFrames {
    std::vector<SoftStats> all;
    int worst = -1;
    double worstScore = -1.0;
    FrameImages worstMethod, worstReference;

    // Keeps frame i's statistics, and its pictures if it is the worst so far: most pixels off
    // by 0.1 or more, then the largest mean difference.
    void add(int i, std::vector<FrameImages>& images) {
        const SoftStats s = compareSoftShadows(images[0].visibility, images[1].visibility);
        all.push_back(s);
        const double score =
            (s.deltaBuckets[2] + s.deltaBuckets[3]) * static_cast<double>(s.penumbraEither) +
            s.meanDelta;
        if (score > worstScore) {
            worstScore = score;
            worst = i;
            worstMethod = std::move(images[0]);
            worstReference = std::move(images[1]);
        }
    }
};

// Renders both lanes along the path, frame by frame.
CompareFrames runCompareFrames(const CompareRequest& r, const Scene& scene, CameraPath path,
                               std::vector<Lane>& lanes) {
    CompareFrames frames;
    FrameRunner runner(r.frames);
    FramePlan::Clip clip;
    try {
        clip = FramePlan::Clip::of(scene, r.scene.animation, r.scene.time, r.animationFps);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--") + e.what());
    }
    runner.run({.scene = &scene,
                .camera = std::move(path),
                .frames = r.frames,
                .width = r.width,
                .height = r.height,
                .clip = clip},
               lanes, [&](int i, std::vector<FrameImages>& images) { frames.add(i, images); });
    runner.finish();
    return frames;
}

// summary.json: the run's settings, the means and extremes of the statistics, the phases.
nlohmann::json compareSummary(const CompareRequest& r, const std::string& reference,
                              const RenderSettings& settings, int passes,
                              const CompareFrames& frames, const std::vector<Lane>& lanes) {
    const std::vector<SoftStats>& all = frames.all;
    auto mean = [&](auto get) {
        double sum = 0.0;
        for (const SoftStats& s : all) sum += get(s);
        return all.empty() ? 0.0 : sum / static_cast<double>(all.size());
    };
    nlohmann::json j;
    j["method"] = r.method;
    j["reference"] = reference;
    j["frames"] = r.frames;
    j["width"] = r.width;
    j["height"] = r.height;
    j["shadowMap"] = {{"provider", providerName(settings.shadow.provider)},
                      {"size", settings.shadow.size}};
    if (passes == kAutoPasses)
        j["passes"] = "auto"; // chosen per frame: frames.csv and "flood" below
    else
        j["passes"] = passes;
    j["meanPenumbraPixelsReference"] =
        mean([](const SoftStats& s) { return static_cast<double>(s.penumbraReference); });
    j["meanShareDeltaBelow0.05"] = mean([](const SoftStats& s) { return s.deltaBuckets[0]; });
    j["meanShareDelta0.05to0.1"] = mean([](const SoftStats& s) { return s.deltaBuckets[1]; });
    j["meanShareDelta0.1to0.2"] = mean([](const SoftStats& s) { return s.deltaBuckets[2]; });
    j["meanShareDeltaAtLeast0.2"] = mean([](const SoftStats& s) { return s.deltaBuckets[3]; });
    double maxParity = 0.0, minBelow = 1.0;
    for (const SoftStats& s : all) {
        maxParity = std::max(maxParity, s.parityShare);
        if (s.penumbraEither > 0) minBelow = std::min(minBelow, s.deltaBuckets[0]);
    }
    j["meanParityShare"] = mean([](const SoftStats& s) { return s.parityShare; });
    j["maxParityShare"] = maxParity;
    j["minShareDeltaBelow0.05"] = minBelow;
    j["worstFrame"] = frames.worst;
    nlohmann::json times;
    for (const Lane& lane : lanes)
        for (const std::string& p : phaseNames({&lanes[0].times, &lanes[1].times}))
            times[lane.label + " " + p] = {{"medianMs", lane.times.medianPhaseMs(p)}};
    j["phases"] = times;
    j["floodTimeReferenceOverMethod"] = lanes[1].times.medianPhaseMs(phase::kFlood) /
                                        std::max(lanes[0].times.medianPhaseMs(phase::kFlood), 1e-9);
    for (const Lane& lane : lanes)
        if (const std::optional<FloodSample> f = lane.times.medianFlood())
            j["flood"][lane.label] = {{"medianPasses", f->passes},
                                      {"medianActiveShare", f->activeShare}};
    return j;
}

// The worst frame side by side (method | reference | difference) as PNG, and as an EXR of
// three channels; returns the files' stem.
std::string writeWorstFrame(const std::filesystem::path& dir, const CompareRequest& r,
                            const CompareFrames& frames) {
    const std::string stem = "worst_frame_" + std::to_string(frames.worst);
    const FloatImage& method = frames.worstMethod.visibility;
    const FloatImage& reference = frames.worstReference.visibility;
    writePng(dir / (stem + ".png"),
             sideBySide({visibilityToGrey(method), visibilityToGrey(reference),
                         differencePicture(method, reference)}));
    std::vector<float> diff(method.data.size());
    for (std::size_t k = 0; k < diff.size(); ++k) diff[k] = method.data[k] - reference.data[k];
    writeExr(dir / (stem + ".exr"), r.width, r.height,
             {{"method", method.data}, {"reference", reference.data}, {"difference", diff}});
    return stem;
}

int runCompare(const CompareRequest& r) {
    const std::string& method = r.method;
    const std::string reference = referenceOrThrow(method);
    try { // before any work: a file where the folder goes failed after every frame
        checkOutputFolder(r.out, "--out");
    } catch (const OutputFileError& e) {
        throw InputError(e.what());
    }
    const Scene scene = loadScene(r.scene);
    CameraPath path = comparePath(r, scene);
    auto context = EglContext::create();
    const gl::ShaderLibrary shaders = makeShaderLibrary(r.scene);
    RenderSettings settings = makeRenderSettings(r.scene);
    settings.method = method;
    checkMethodOptions(settings, r.width, r.height);
    const std::string setup = setupLine(scene, settings, r.width, r.height); // the method's
    const int passes = requestedPasses(methodOrThrow(method), settings.options,
                                       settings.shadow.size, r.width, r.height);
    Renderer methodRenderer(shaders, scene, settings);
    settings.method = reference;
    Renderer referenceRenderer(shaders, scene, settings);
    methodRenderer.resize(r.width, r.height);
    referenceRenderer.resize(r.width, r.height);
    std::cout << "context: " << context->description() << "\n"
              << "scene: " << scene.source << " (" << scene.triangleCount() << " triangles)\n"
              << method << " vs " << reference << ", " << r.frames << " frames at " << r.width
              << "x" << r.height << "\n"
              << setup << "\n";

    // Lane labels are also the CSV column and JSON key prefixes ("method_flood_ms").
    std::vector<Lane> lanes = {{"method", &methodRenderer, {}},
                               {"reference", &referenceRenderer, {}}};
    const CompareFrames frames = runCompareFrames(r, scene, std::move(path), lanes);
    const nlohmann::json j = compareSummary(r, reference, settings, passes, frames, lanes);

    // Everything is computed; now write (each file under a temporary name, then renamed).
    const std::filesystem::path dir(r.out);
    writeCsv(dir / "frames.csv", compareCsv(frames.all, lanes));
    writeJson(dir / "summary.json", j);
    const std::string stem = writeWorstFrame(dir, r, frames);
    std::cout << std::fixed << std::setprecision(3)
              << "penumbra pixels (reference, mean per frame): "
              << j["meanPenumbraPixelsReference"].get<double>() << "\n"
              << "|dI| < 0.05: " << 100 * j["meanShareDeltaBelow0.05"].get<double>()
              << "% of penumbra pixels (mean; worst frame "
              << 100 * j["minShareDeltaBelow0.05"].get<double>() << "%)\n"
              << "parity differs: " << 100 * j["meanParityShare"].get<double>()
              << "% of pixels (mean; max " << 100 * j["maxParityShare"].get<double>() << "%)\n"
              << "flood time " << reference << " / " << method << ": "
              << j["floodTimeReferenceOverMethod"].get<double>() << " (medians)\n"
              << "wrote " << (dir / "frames.csv").string() << ", "
              << (dir / "summary.json").string() << ", " << (dir / (stem + ".png")).string() << ", "
              << (dir / (stem + ".exr")).string() << "\n";
    return 0;
}

} // namespace

Runner addCompareCommand(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "compare",
        "A soft-shadow method against its standard-flooding reference over a walkthrough");
    auto s = std::make_shared<CompareRequest>();
    s->scene.method = "jfa-l";
    addSceneOptions(*cmd, s->scene, true);
    addSizeOptions(*cmd, s->width, s->height);
    cmd->add_option("--path", s->path,
                    "Camera path: default (a swing around the scene's camera) or a JSON file "
                    "{\"fov\": deg, \"keys\": [{\"eye\": [x,y,z], \"target\": [x,y,z]}, ...]} "
                    "(at most " +
                        std::to_string(kTextInputLimitMiB) + " MiB)")
        ->capture_default_str();
    cmd->add_option("--frames", s->frames, "Frames along the path")
        ->check(integer(1, 100000))
        ->capture_default_str();
    cmd->add_option("--animation-fps", s->animationFps,
                    "Frames per second of scene time: frame i is posed at --time + i / FPS "
                    "(0: every frame at --time)")
        ->check(number(0.0, 1000.0))
        ->capture_default_str();
    addOutOption(*cmd, s->out, "Output folder");
    return [s] {
        CompareRequest r = *s;
        r.method = r.scene.method;
        return runCompare(r);
    };
}

} // namespace fl::app
