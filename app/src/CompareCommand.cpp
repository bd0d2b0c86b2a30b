// `floodlight compare`: a soft-shadow method against its standard-flooding reference over a
// walkthrough (thesis Fig. 5.4 / 5.8): one CSV row per frame, a JSON summary, and the frame with
// the largest difference side by side (method | reference | difference) as PNG and EXR.

#include "Commands.h"

#include <renderer/CameraPath.h>
#include <renderer/Capture.h>
#include <renderer/EglContext.h>
#include <renderer/ShadowStats.h>
#include <renderer/soft/SoftStats.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <unistd.h>

namespace fl::app {

namespace {

struct CompareRequest {
    SceneOptions scene;
    std::string path = "default"; // "default" or a camera-path JSON file
    std::string method = "jfa-l";
    std::string out = "captures/compare";
    int frames = 60;
    int width = 512, height = 512;
};

// The method's standard-flooding reference, from the method table.
std::string referenceOf(const std::string& method) {
    const MethodDescriptor& m = methodOrThrow(method);
    if (m.reference.empty()) {
        std::string valid;
        for (const MethodDescriptor& d : methodTable())
            if (!d.reference.empty()) valid += (valid.empty() ? "" : ", ") + std::string(d.name);
        throw InputError("--method " + method + ": no standard-flooding reference for it (" +
                         valid + " have one)");
    }
    return std::string(m.reference);
}

double passMs(const Renderer& r, const std::string& name) {
    double ms = 0.0;
    for (const PassTime& p : r.timer().passes())
        if (p.name == name) ms += p.ms;
    return ms;
}

// Every phase either method times, from the table (absent phases read 0).
std::vector<std::string> phasesOf(const std::string& method, const std::string& reference) {
    std::vector<std::string> out;
    for (const std::string& name : {method, reference})
        for (std::string_view p : framePhases(methodOrThrow(name)))
            if (std::find(out.begin(), out.end(), p) == out.end()) out.emplace_back(p);
    return out;
}

std::string csvHeader(const std::vector<std::string>& kPhases) {
    std::string h = "frame,penumbra_reference,penumbra_method,dI_lt_0.05,dI_0.05_0.1,dI_0.1_0.2,"
                    "dI_ge_0.2,parity_percent,max_dI,mean_dI";
    for (const char* who : {"method", "reference"})
        for (const std::string& phase : kPhases) {
            std::string p = phase;
            std::replace(p.begin(), p.end(), ' ', '_');
            h += std::string(",") + who + "_" + p + "_ms";
        }
    return h + ",method_frame_ms,reference_frame_ms\n";
}

int runCompare(const CompareRequest& r) {
    const std::string method = r.method;
    const std::string reference = referenceOf(method);
    const std::vector<std::string> kPhases = phasesOf(method, reference);
    const Scene scene = loadScene(r.scene);
    const float aspect = static_cast<float>(r.width) / static_cast<float>(r.height);
    CameraPath path = [&] {
        if (r.path != "default") {
            try {
                return readCameraPath(r.path);
            } catch (const std::runtime_error& e) {
                throw InputError(e.what());
            }
        }
        return defaultWalkthrough(initialCamera(scene, r.scene, r.width, r.height), scene.bounds);
    }();
    auto context = EglContext::create();
    const ShaderLibrary shaders = makeShaderLibrary(r.scene);
    RenderSettings settings = makeRenderSettings(r.scene);
    settings.method = method;
    checkMethodOptions(settings, r.width, r.height);
    Renderer methodRenderer(shaders, scene, settings);
    settings.method = reference;
    Renderer referenceRenderer(shaders, scene, settings);
    methodRenderer.resize(r.width, r.height);
    referenceRenderer.resize(r.width, r.height);
    std::cout << "context: " << context->description() << "\n"
              << "scene: " << scene.source << " (" << scene.triangleCount() << " triangles)\n"
              << method << " vs " << reference << ", " << r.frames << " frames at " << r.width
              << "x" << r.height << ", shadow map " << providerName(settings.shadow.provider) << " "
              << settings.shadow.size << "^2, "
              << requestedPasses(methodOrThrow(method), settings.options, settings.shadow.size,
                                 r.width, r.height)
              << " passes\n";

    std::ostringstream csv;
    csv << csvHeader(kPhases) << std::setprecision(6);
    const bool tty = ::isatty(STDOUT_FILENO) != 0;
    std::vector<SoftStats> all;
    std::map<std::string, std::vector<double>> phaseMs;
    int worst = -1;
    double worstScore = -1.0;
    FrameImages worstMethod, worstReference;
    for (int i = 0; i < r.frames; ++i) {
        const CameraView cam = path.frame(i, r.frames, scene.bounds, aspect);
        methodRenderer.render(cam);
        referenceRenderer.render(cam);
        FrameImages a = readFrame(methodRenderer), b = readFrame(referenceRenderer);
        requireFinite(a.visibility, "method visibility");
        requireFinite(b.visibility, "reference visibility");
        const SoftStats s = compareSoftShadows(a.visibility, b.visibility);
        all.push_back(s);
        csv << i << "," << s.penumbraReference << "," << s.penumbraMethod;
        for (double d : s.deltaBuckets) csv << "," << 100.0 * d;
        csv << "," << 100.0 * s.parityShare << "," << s.maxDelta << "," << s.meanDelta;
        for (const Renderer* rr : {&methodRenderer, &referenceRenderer})
            for (const std::string& phase : kPhases) {
                const double ms = passMs(*rr, phase);
                csv << "," << ms;
                phaseMs[std::string(rr == &methodRenderer ? "method " : "reference ") + phase]
                    .push_back(ms);
            }
        csv << "," << methodRenderer.timer().frameMs() << "," << referenceRenderer.timer().frameMs()
            << "\n";
        // The worst frame: most pixels off by 0.1 or more, then the largest mean difference.
        const double score =
            (s.deltaBuckets[2] + s.deltaBuckets[3]) * static_cast<double>(s.penumbraEither) +
            s.meanDelta;
        if (score > worstScore) {
            worstScore = score;
            worst = i;
            worstMethod = std::move(a);
            worstReference = std::move(b);
        }
        if (tty) std::cout << "\rframe " << (i + 1) << "/" << r.frames << std::flush;
    }
    if (tty) std::cout << "\n";

    // Summary.
    auto mean = [&](auto get) {
        double sum = 0.0;
        for (const SoftStats& s : all) sum += get(s);
        return all.empty() ? 0.0 : sum / static_cast<double>(all.size());
    };
    auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v.empty() ? 0.0 : v[v.size() / 2];
    };
    nlohmann::json j;
    j["method"] = method;
    j["reference"] = reference;
    j["frames"] = r.frames;
    j["width"] = r.width;
    j["height"] = r.height;
    j["shadowMap"] = {{"provider", providerName(settings.shadow.provider)},
                      {"size", settings.shadow.size}};
    j["passes"] = requestedPasses(methodOrThrow(method), settings.options, settings.shadow.size,
                                  r.width, r.height);
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
    j["worstFrame"] = worst;
    nlohmann::json times;
    for (const auto& [name, v] : phaseMs) times[name] = {{"medianMs", median(v)}};
    j["phases"] = times;
    const double floodRatio =
        median(phaseMs["reference flood"]) / std::max(median(phaseMs["method flood"]), 1e-9);
    j["floodTimeReferenceOverMethod"] = floodRatio;

    // Everything is computed; now write (each file under a temporary name, then renamed).
    const std::filesystem::path dir(r.out);
    writeTextFile(dir / "frames.csv", csv.str());
    writeTextFile(dir / "summary.json", j.dump(2) + "\n");
    const std::string stem = "worst_frame_" + std::to_string(worst);
    writePng(dir / (stem + ".png"),
             sideBySide({visibilityToGrey(worstMethod.visibility),
                         visibilityToGrey(worstReference.visibility),
                         differencePicture(worstMethod.visibility, worstReference.visibility)}));
    std::vector<float> diff(worstMethod.visibility.data.size());
    for (std::size_t k = 0; k < diff.size(); ++k)
        diff[k] = worstMethod.visibility.data[k] - worstReference.visibility.data[k];
    writeExr(dir / (stem + ".exr"), r.width, r.height,
             {{"method", worstMethod.visibility.data},
              {"reference", worstReference.visibility.data},
              {"difference", diff}});

    std::cout << std::fixed << std::setprecision(3)
              << "penumbra pixels (reference, mean per frame): "
              << j["meanPenumbraPixelsReference"].get<double>() << "\n"
              << "|dI| < 0.05: " << 100 * j["meanShareDeltaBelow0.05"].get<double>()
              << "% of penumbra pixels (mean; worst frame " << 100 * minBelow << "%)\n"
              << "parity differs: " << 100 * j["meanParityShare"].get<double>()
              << "% of pixels (mean; max " << 100 * maxParity << "%)\n"
              << "flood time " << reference << " / " << method << ": " << floodRatio
              << " (medians)\n"
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
                    "{\"fov\": deg, \"keys\": [{\"eye\": [x,y,z], \"target\": [x,y,z]}, ...]}")
        ->capture_default_str();
    cmd->add_option("--frames", s->frames, "Frames along the path")
        ->check(CLI::Range(1, 100000))
        ->capture_default_str();
    cmd->add_option("--out", s->out, "Output folder")->capture_default_str();
    return [s] {
        CompareRequest r = *s;
        r.method = r.scene.method;
        return runCompare(r);
    };
}

} // namespace fl::app
