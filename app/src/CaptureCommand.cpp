// `floodlight capture SCRIPT.json --out DIR`: every frame of a capture script with every method
// and the ground truth (`reference`), headless. Writes PNG + EXR per frame x method, frames.csv
// (one row per frame x method), summary.json and report.html (written last, so a run that fails
// leaves neither a summary nor a report behind).

#include "CaptureResults.h"
#include "Commands.h"

#include <renderer/Capture.h>
#include <renderer/EglContext.h>
#include <renderer/ShadowStats.h>
#include <renderer/soft/EyeSoftShadow.h>
#include <renderer/soft/SoftStats.h>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>
#include <unistd.h>

namespace fl::app {

namespace {

namespace fs = std::filesystem;

struct CaptureRequest {
    std::string script;
    std::string out = "captures/capture";
    std::string shaderDir;
    std::string timing = "auto";
};

// Creates DIR, proves it writable and removes the outputs of an earlier run there, so that a
// failure of this run cannot leave an old summary or report looking like this run's.
void prepareOutput(const fs::path& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
        throw InputError("--out " + dir.string() + ": cannot create the folder" +
                         (ec ? " (" + ec.message() + ")" : std::string()));
    try {
        writeTextFile(dir / ".capture-write-test", "");
    } catch (const std::runtime_error& e) {
        throw InputError("--out " + dir.string() + ": cannot write there (" + e.what() + ")");
    }
    fs::remove(dir / ".capture-write-test", ec);
    for (const char* stale : {"report.html", "summary.json", "frames.csv"}) {
        fs::remove(dir / stale, ec);
        if (ec) throw InputError((dir / stale).string() + ": cannot remove the old file");
    }
}

class Progress {
  public:
    explicit Progress(int total) : total_(total), tty_(::isatty(STDOUT_FILENO) != 0) {}
    void step(int done) {
        if (!tty_) return;
        const double s = std::chrono::duration<double>(Clock::now() - start_).count();
        const int width = 30, filled = total_ > 0 ? width * done / total_ : width;
        const double eta = done > 0 ? s / done * (total_ - done) : 0.0;
        std::cout << "\r[" << std::string(static_cast<size_t>(filled), '#')
                  << std::string(static_cast<size_t>(width - filled), '.') << "] " << done << "/"
                  << total_ << " frames, " << std::fixed << std::setprecision(0) << s << " s, ETA "
                  << eta << " s " << std::defaultfloat << std::flush;
    }
    void finish() {
        if (tty_) std::cout << "\n";
    }

  private:
    using Clock = std::chrono::steady_clock;
    int total_;
    bool tty_;
    Clock::time_point start_ = Clock::now();
};

std::vector<std::pair<std::string, double>> phases(const Renderer& r) {
    std::vector<std::pair<std::string, double>> out;
    for (const PassTime& p : r.timer().passes()) out.emplace_back(p.name, p.ms);
    return out;
}

// The standard-flooding counterpart of a JFA run (same pass count), or -1.
int counterpartOf(const std::vector<MethodRun>& runs, std::size_t k, int defaultPasses) {
    const MethodSpec& m = runs[k].spec;
    const std::string_view want = methodOrThrow(m.method).reference;
    if (want.empty()) return -1;
    const auto passes = [&](const MethodSpec& spec) {
        const MethodOption& o = floodPassesOption();
        return spec.options.has(o.flag) ? spec.options.integer(o) : defaultPasses;
    };
    for (std::size_t c = 0; c < runs.size(); ++c)
        if (runs[c].spec.method == want && runs[c].width == runs[k].width &&
            runs[c].height == runs[k].height && passes(runs[c].spec) == passes(m))
            return static_cast<int>(c);
    return -1;
}

int runCapture(const CaptureRequest& req) {
    CaptureScript script;
    try {
        script = readCaptureScript(req.script);
    } catch (const CaptureScriptError& e) {
        throw InputError(e.what());
    }
    const fs::path dir(req.out);
    prepareOutput(dir);

    SceneOptions so;
    so.scene = script.scene.string();
    so.lightRadius = script.lightRadius;
    so.shaderDir = req.shaderDir;
    so.shadowMapSize = script.shadowMapSize;
    so.shadowMap = script.shadowMapProvider;
    so.methodOptions[std::string(floodPassesOption().flag)] = std::to_string(script.jfaPasses);
    so.strictMethodOptions = false; // the script's methods each take their own
    so.timing = req.timing;
    const Scene scene = loadScene(so);
    auto context = EglContext::create();
    const ShaderLibrary shaders = makeShaderLibrary(so);
    const RenderSettings base = makeRenderSettings(so);
    RenderSettings refSettings = base;
    refSettings.method = "reference";
    {
        const MethodDescriptor& truth = methodOrThrow(refSettings.method);
        refSettings.options.set(truth.option("samples")->flag, script.reference.samples);
        refSettings.options.set(truth.option("mapSize")->flag, script.reference.mapSize);
    }

    CaptureResults results;
    results.script = &script;
    results.context = context->description();
    results.sceneName = scene.source;
    const bool severalSizes = script.resolutions.size() > 1;
    std::cout << "context: " << results.context << "\nscene: " << scene.source << " ("
              << scene.triangleCount() << " triangles), " << script.frames << " frames x "
              << script.methods.size() << " methods x " << script.resolutions.size()
              << " resolution(s); reference " << script.reference.samples << " samples, "
              << script.reference.mapSize << "^2 maps\n";
    Progress progress(script.frames * static_cast<int>(script.resolutions.size()));
    int done = 0;
    for (const auto& [w, h] : script.resolutions) {
        const std::string size = std::to_string(w) + "x" + std::to_string(h);
        const std::size_t first = results.runs.size();
        // One renderer per method: each keeps its own maps and timers, and the reference's
        // maps (its own size) are never shared with a method's.
        Renderer reference(shaders, scene, refSettings);
        reference.resize(w, h);
        std::vector<std::unique_ptr<Renderer>> renderers;
        for (const MethodSpec& m : script.methods) {
            MethodRun run;
            run.spec = m;
            run.label = severalSizes ? m.label + " @" + size : m.label;
            run.width = w;
            run.height = h;
            results.runs.push_back(std::move(run));
            renderers.push_back(
                m.method == refSettings.method
                    ? nullptr
                    : std::make_unique<Renderer>(shaders, scene, settingsFor(base, m)));
            if (renderers.back()) renderers.back()->resize(w, h);
        }
        std::vector<int> counterpart;
        for (std::size_t k = first; k < results.runs.size(); ++k) {
            const int c = counterpartOf(results.runs, k, script.jfaPasses);
            counterpart.push_back(c);
            if (c >= 0) results.runs[k].counterpart = results.runs[static_cast<size_t>(c)].label;
        }
        const CameraPath path =
            script.camera ? *script.camera
                          : defaultWalkthrough(initialCamera(scene, so, w, h), scene.bounds);
        const float aspect = static_cast<float>(w) / static_cast<float>(h);
        const fs::path framesDir = dir / "frames" / size;
        std::vector<FloatImage> previous(script.methods.size());
        FloatImage previousReference, previousReceivers;
        for (int i = 0; i < script.frames; ++i) {
            if (!script.lightKeys.empty()) {
                Light light = sceneLight(scene);
                light.position = lightPositionAt(script.lightKeys, i, script.frames);
                if (light.type != Light::Type::Spot)
                    light.direction = glm::normalize(scene.bounds.center() - light.position);
                reference.setLight(light);
                for (auto& r : renderers)
                    if (r) r->setLight(light);
            }
            const CameraView cam = path.frame(i, script.frames, scene.bounds, aspect);
            char stem[32];
            std::snprintf(stem, sizeof stem, "frame_%05d", i);
            reference.render(cam);
            const FrameImages ref = readFrame(reference);
            results.referenceFrameMs.push_back(reference.timer().frameMs());
            requireFinite(ref.visibility, "reference visibility, frame " + std::to_string(i));
            if (script.saveFrames) writeFrame(ref, framesDir / "reference", stem);
            std::vector<FrameImages> images(script.methods.size());
            // Flicker compares with the previous frame: count pixels that are receivers in both.
            const FloatImage flickerReceivers =
                i > 0 ? bothReceivers(previousReceivers, ref.receivers) : FloatImage{};
            for (std::size_t k = 0; k < script.methods.size(); ++k) {
                MethodRun& run = results.runs[first + k];
                const Renderer& r = renderers[k] ? *renderers[k] : reference;
                if (renderers[k]) {
                    renderers[k]->render(cam);
                    images[k] = readFrame(r);
                    requireFinite(images[k].visibility,
                                  run.label + " visibility, frame " + std::to_string(i));
                    if (script.saveFrames)
                        writeFrame(images[k], framesDir / safeName(run.spec.label), stem);
                } else {
                    images[k] = ref; // the script lists `reference`: its row, against itself
                }
                FrameRow row;
                row.frame = i;
                // Every method sees the same surfaces: the reference's receivers are theirs.
                row.metrics =
                    compareWithReference(images[k].visibility, ref.visibility, ref.receivers);
                if (i > 0)
                    row.flicker = addedFlicker(previous[k], images[k].visibility, previousReference,
                                               ref.visibility, flickerReceivers);
                row.phasesMs = phases(r);
                row.frameMs = r.timer().frameMs();
                if (row.metrics.rmse > run.worstRmse) {
                    run.worstRmse = row.metrics.rmse;
                    run.worstFrame = i;
                    run.worstMethod = images[k].visibility;
                    run.worstReference = ref.visibility;
                    run.worstReceivers = ref.receivers;
                }
                run.rows.push_back(std::move(row));
            }
            for (std::size_t k = 0; k < script.methods.size(); ++k) {
                if (counterpart[k] >= 0)
                    results.runs[first + k].rows.back().deltaBuckets =
                        compareSoftShadows(
                            images[k].visibility,
                            images[static_cast<std::size_t>(counterpart[k]) - first].visibility)
                            .deltaBuckets;
                previous[k] = std::move(images[k].visibility);
            }
            previousReference = ref.visibility;
            previousReceivers = ref.receivers;
            progress.step(++done);
        }
    }
    progress.finish();

    // Everything is measured; now the outputs, the summary and the report last.
    writeTextFile(dir / "frames.csv", resultsCsv(results));
    const fs::path imageDir = dir / "report";
    for (const MethodRun& run : results.runs)
        writePng(
            imageDir / ("worst_" + safeName(run.label) + ".png"),
            sideBySide({visibilityToGrey(run.worstMethod), visibilityToGrey(run.worstReference),
                        differencePicture(run.worstMethod, run.worstReference, 4.0f,
                                          run.worstReceivers)}));
    const nlohmann::json summary = resultsSummary(results);
    try {
        writeTextFile(dir / "summary.json", summary.dump(2) + "\n");
        writeTextFile(dir / "report.html", reportHtml(results, summary, "report"));
    } catch (...) {
        std::error_code ec;
        fs::remove(dir / "summary.json", ec);
        throw;
    }

    std::cout << std::left << std::setw(22) << "method" << std::right << std::setw(10) << "rmse"
              << std::setw(12) << "rmse pen." << std::setw(10) << "miscl.%" << std::setw(11)
              << "flicker" << std::setw(11) << "frame ms"
              << "\n"
              << std::fixed;
    for (const auto& m : summary["methods"])
        std::cout << std::left << std::setw(22) << m["label"].get<std::string>() << std::right
                  << std::setprecision(4) << std::setw(10) << m["rmse"].get<double>()
                  << std::setw(12) << m["rmsePenumbra"].get<double>() << std::setprecision(2)
                  << std::setw(10) << m["misclassifiedPercent"].get<double>()
                  << std::setprecision(5) << std::setw(11) << m["addedFlicker"].get<double>()
                  << std::setprecision(2) << std::setw(11) << m["medianFrameMs"].get<double>()
                  << "\n";
    std::cout << std::defaultfloat << "wrote " << (dir / "frames.csv").string() << ", "
              << (dir / "summary.json").string() << ", " << (dir / "report.html").string()
              << (script.saveFrames ? ", frames under " + (dir / "frames").string() : "") << "\n";
    return 0;
}

} // namespace

Runner addCaptureCommand(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "capture", "Render a capture script (camera path x methods) headless, with the ground "
                   "truth, and write PNG/EXR frames, frames.csv, summary.json and report.html");
    auto r = std::make_shared<CaptureRequest>();
    cmd->add_option("script", r->script, "Capture script (JSON; see examples/capture/)")
        ->required();
    cmd->add_option("--out", r->out, "Output folder")->capture_default_str();
    cmd->add_option("--shader-dir", r->shaderDir,
                    "Load shaders from this folder instead of the binary");
    cmd->add_option("--timing", r->timing, "Pass timing: auto, query (GL timers), finish")
        ->check(CLI::IsMember({"auto", "query", "finish"}))
        ->capture_default_str();
    return [r] { return runCapture(*r); };
}

} // namespace fl::app
