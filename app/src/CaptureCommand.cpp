// `floodlight capture SCRIPT.json --out DIR`: every frame of a capture script with every method
// and the ground truth (`reference`), headless. Writes PNG + EXR per frame x method, frames.csv
// (one row per frame x method), summary.json and report.html (written last, so a run that fails
// leaves neither a summary nor a report behind).

#include "CaptureResults.h"
#include "Commands.h"

#include <base/InputFile.h>
#include <base/OutputFiles.h>
#include <renderer/run/FrameRunner.h>

#include <renderer/context/EglContext.h>
#include <renderer/io/Capture.h>
#include <renderer/metrics/ShadowStats.h>
#include <renderer/metrics/SoftStats.h>
#include <renderer/soft/EyeSoftShadow.h>

#include <iomanip>
#include <iostream>
#include <memory>

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
    makeOutputFolder(dir, "--out");
    std::error_code ec;
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

// The standard-flooding run a JFA run's |dI| buckets are measured against: the script's run of
// Whether a script's entry is the ground truth itself (its row is then the reference against
// itself, from lane 0): the same method, and every option the entry gives has the reference's
// value. {"method": "reference", "mapSize": 1024} beside a 2048² reference is a method of its
// own, rendered in its own lane.
bool isTheReference(const MethodSpec& m, const RenderSettings& reference) {
    if (m.method != reference.method) return false;
    for (const auto& [flag, value] : m.options.values()) {
        const auto it = reference.options.values().find(flag);
        if (it == reference.options.values().end() || it->second != value) return false;
    }
    return true;
}

// referenceOf(its method) at the same size and pass count; -1 if the script has none.
int counterpartOf(const std::vector<MethodRun>& runs, std::size_t k, int defaultPasses) {
    const MethodSpec& m = runs[k].spec;
    const std::optional<std::string> want = referenceOf(m.method);
    if (!want) return -1;
    const auto passes = [&](const MethodSpec& spec) {
        const MethodOption& o = floodPassesOption();
        return spec.options.has(o.flag) ? spec.options.integer(o) : defaultPasses;
    };
    for (std::size_t c = 0; c < runs.size(); ++c)
        if (runs[c].spec.method == *want && runs[c].width == runs[k].width &&
            runs[c].height == runs[k].height && passes(runs[c].spec) == passes(m))
            return static_cast<int>(c);
    return -1;
}

// What every resolution of a capture shares.
struct CaptureSetup {
    const CaptureScript& script;
    const SceneOptions& options;
    const Scene& scene;
    const gl::ShaderLibrary& shaders;
    RenderSettings base, reference;
    fs::path dir;
};

// The metrics of one resolution's runs, frame by frame: each method against the ground truth,
// its added flicker since the previous frame, its worst frame, and a JFA run's |dI| buckets
// against its standard-flooding counterpart.
class FrameScorer {
  public:
    FrameScorer(std::vector<MethodRun>& runs, std::size_t first, int jfaPasses)
        : runs_(runs), first_(first), previous_(runs.size() - first) {
        for (std::size_t k = first; k < runs.size(); ++k) {
            const int c = counterpartOf(runs, k, jfaPasses);
            counterpart_.push_back(c);
            if (c >= 0) runs[k].counterpart = runs[static_cast<std::size_t>(c)].label;
        }
    }

    /// Scores frame i: `visibility` holds one image per run (moved from), `ref` the truth.
    void score(int i, std::vector<FloatImage>& visibility, const FrameImages& ref) {
        // Flicker compares with the previous frame: count pixels that are receivers in both.
        const FloatImage flickerReceivers =
            i > 0 ? bothReceivers(previousReceivers_, ref.receivers) : FloatImage{};
        for (std::size_t k = 0; k < visibility.size(); ++k) {
            MethodRun& run = runs_[first_ + k];
            FrameRow row;
            row.frame = i;
            // Every method sees the same surfaces: the reference's receivers are theirs.
            row.metrics = compareWithReference(visibility[k], ref.visibility, ref.receivers);
            if (i > 0)
                row.flicker = addedFlicker(previous_[k], visibility[k], previousReference_,
                                           ref.visibility, flickerReceivers);
            if (row.metrics.rmse > run.worstRmse) {
                run.worstRmse = row.metrics.rmse;
                run.worstFrame = i;
                run.worstMethod = visibility[k];
                run.worstReference = ref.visibility;
                run.worstReceivers = ref.receivers;
            }
            run.rows.push_back(std::move(row));
        }
        for (std::size_t k = 0; k < visibility.size(); ++k) {
            if (counterpart_[k] >= 0)
                runs_[first_ + k].rows.back().deltaBuckets =
                    compareSoftShadows(
                        visibility[k],
                        visibility[static_cast<std::size_t>(counterpart_[k]) - first_])
                        .deltaBuckets;
            previous_[k] = std::move(visibility[k]);
        }
        previousReference_ = ref.visibility;
        previousReceivers_ = ref.receivers;
    }

  private:
    std::vector<MethodRun>& runs_;
    std::size_t first_;
    std::vector<int> counterpart_;
    std::vector<FloatImage> previous_;
    FloatImage previousReference_, previousReceivers_;
};

// Every frame of the script at w x h: appends one MethodRun per method to `results`.
void captureSize(const CaptureSetup& c, int w, int h, FrameRunner& runner,
                 CaptureResults& results) {
    const CaptureScript& script = c.script;
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    const std::size_t first = results.runs.size();
    // One renderer per method: each keeps its own maps and timers, and the reference's maps (its
    // own size) are never shared with a method's. Lane 0 is the reference; a `reference` entry
    // in the script's methods reads lane 0 rather than rendering the ground truth twice.
    Renderer reference(c.shaders, c.scene, c.reference);
    reference.resize(w, h);
    std::vector<std::unique_ptr<Renderer>> renderers;
    std::vector<Lane> lanes(1);
    lanes[0] = {"reference", &reference, {}};
    std::vector<std::size_t> laneOf;
    for (const MethodSpec& m : script.methods) {
        MethodRun run;
        run.spec = m;
        run.label = script.resolutions.size() > 1 ? m.label + " @" + size : m.label;
        run.width = w;
        run.height = h;
        laneOf.push_back(0);
        if (!isTheReference(m, c.reference)) {
            renderers.push_back(
                std::make_unique<Renderer>(c.shaders, c.scene, settingsFor(c.base, m)));
            renderers.back()->resize(w, h);
            laneOf.back() = lanes.size();
            lanes.push_back({run.label, renderers.back().get(), {}});
        }
        results.runs.push_back(std::move(run));
    }
    MethodOptions defaults; // the script's jfaPasses as a number (0: auto)
    defaults.set(floodPassesOption().flag, script.jfaPasses);
    FrameScorer scorer(results.runs, first, defaults.integer(floodPassesOption()));
    const FramePlan plan{
        .scene = &c.scene,
        .camera = script.camera
                      ? *script.camera
                      : defaultWalkthrough(initialCamera(c.scene, c.options, w, h), c.scene.bounds),
        .frames = script.frames,
        .width = w,
        .height = h,
        .lightKeys = script.lightKeys};
    const fs::path framesDir = c.dir / "frames" / size;
    runner.run(plan, lanes, [&](int i, std::vector<FrameImages>& laneImages) {
        const FrameImages& ref = laneImages[0];
        if (script.saveFrames) {
            char stem[32];
            std::snprintf(stem, sizeof stem, "frame_%05d", i);
            writeFrame(ref, framesDir / "reference", stem);
            for (std::size_t k = 0; k < script.methods.size(); ++k)
                if (laneOf[k] != 0)
                    writeFrame(laneImages[laneOf[k]], framesDir / safeName(script.methods[k].label),
                               stem);
        }
        std::vector<FloatImage> visibility(script.methods.size());
        for (std::size_t k = 0; k < script.methods.size(); ++k)
            // A `reference` entry's row is the reference against itself (lane 0, copied);
            // every other lane belongs to one method alone.
            visibility[k] =
                laneOf[k] == 0 ? ref.visibility : std::move(laneImages[laneOf[k]].visibility);
        scorer.score(i, visibility, ref);
    });
    for (std::size_t k = 0; k < script.methods.size(); ++k)
        results.runs[first + k].times = lanes[laneOf[k]].times;
    const std::vector<double>& refMs = lanes[0].times.frameMs();
    results.referenceFrameMs.insert(results.referenceFrameMs.end(), refMs.begin(), refMs.end());
}

// frames.csv, the worst-frame pictures, summary.json and report.html, together or not at all
// (base/OutputFiles.h): a report that cannot be written takes the summary with it, so neither
// claims a run that did not finish.
nlohmann::json writeOutputs(const fs::path& dir, const CaptureResults& results) {
    OutputSet outputs;
    writeCsv(dir / "frames.csv", resultsCsv(results));
    const fs::path imageDir = dir / "report";
    for (const MethodRun& run : results.runs)
        writePng(
            imageDir / ("worst_" + safeName(run.label) + ".png"),
            sideBySide({visibilityToGrey(run.worstMethod), visibilityToGrey(run.worstReference),
                        differencePicture(run.worstMethod, run.worstReference, 4.0f,
                                          run.worstReceivers)}));
    const nlohmann::json summary = resultsSummary(results);
    writeJson(dir / "summary.json", summary);
    writeTextFile(dir / "report.html", reportHtml(results, summary, "report"));
    outputs.commit();
    return summary;
}

void printSummaryTable(const nlohmann::json& summary) {
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
    std::cout << std::defaultfloat;
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
    so.methodOptions[std::string(floodPassesOption().flag)] = script.jfaPasses;
    so.strictMethodOptions = false; // the script's methods each take their own
    so.timing = req.timing;
    const Scene scene = loadScene(so);
    auto context = EglContext::create();
    const gl::ShaderLibrary shaders = makeShaderLibrary(so);
    CaptureSetup setup{script, so, scene, shaders, makeRenderSettings(so), {}, dir};
    setup.reference = setup.base;
    {
        const MethodDescriptor& truth = script.reference.method();
        setup.reference.method = std::string(truth.name);
        setup.reference.options.set(truth.option("samples")->flag, script.reference.samples);
        if (const MethodOption* mapSize = truth.option("mapSize"))
            setup.reference.options.set(mapSize->flag, script.reference.mapSize);
        if (const MethodOption* pattern = truth.option("pattern"))
            setup.reference.options.set(pattern->flag, script.reference.pattern);
    }

    CaptureResults results;
    results.script = &script;
    results.context = context->description();
    results.sceneName = scene.source;
    std::cout << "context: " << results.context << "\nscene: " << scene.source << " ("
              << scene.triangleCount() << " triangles), " << script.frames << " frames x "
              << script.methods.size() << " methods x " << script.resolutions.size()
              << " resolution(s); reference: " << referenceText(script.reference) << "\n";
    FrameRunner runner(script.frames * static_cast<int>(script.resolutions.size()));
    for (const auto& [w, h] : script.resolutions) captureSize(setup, w, h, runner, results);
    runner.finish();

    // Everything is measured; now the outputs, the summary and the report last.
    const nlohmann::json summary = writeOutputs(dir, results);
    printSummaryTable(summary);
    std::cout << "wrote " << (dir / "frames.csv").string() << ", "
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
    cmd->add_option("script", r->script,
                    "Capture script (JSON, at most " + std::to_string(kTextInputLimitMiB) +
                        " MiB, as its camera-path file; at most " +
                        std::to_string(kMaxCaptureFrames) + " frames; see examples/capture/)")
        ->required();
    addOutOption(*cmd, r->out, "Output folder");
    cmd->add_option("--shader-dir", r->shaderDir,
                    "Load shaders from this folder instead of the binary");
    cmd->add_option("--timing", r->timing, "Pass timing: auto, query (GL timers), finish")
        ->check(CLI::IsMember({"auto", "query", "finish"}))
        ->capture_default_str();
    return [r] { return runCapture(*r); };
}

} // namespace fl::app
