// `floodlight capture SCRIPT.json --out DIR`: every frame of a capture script with every method
// and the ground truth (`reference`), headless. Writes PNG + EXR per frame x method, frames.csv
// (one row per frame x method), summary.json and report.html (written last, so a run that fails
// leaves neither a summary nor a report behind). Every finished frame goes into the folder's
// progress (CaptureProgress.h) first: `--resume` continues a killed or failed run from there.

#include "CaptureProgress.h"
#include "CaptureResults.h"
#include "Commands.h"

#include <base/InputFile.h>
#include <base/OutputFiles.h>
#include <base/Process.h>
#include <base/Stats.h>
#include <renderer/run/FrameRunner.h>

#include <renderer/context/EglContext.h>
#include <renderer/io/Capture.h>
#include <renderer/metrics/ShadowStats.h>
#include <renderer/metrics/SoftStats.h>
#include <renderer/soft/EyeSoftShadow.h>

#include <algorithm>
#include <chrono>
#include <fstream>
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
    bool resume = false;
    int stopAfter = 0; // frames this run renders at most (0: all)
};

// The exit status of a run that --stop-after ended with frames left (its progress is kept).
constexpr int kStoppedEarly = 3;

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

// The script's time axis: its animations (checked against the scene), frame i at start + i / fps.
FramePlan::Clip timeAxis(const CaptureScript& script, const Scene& scene) {
    try {
        return FramePlan::Clip::of(scene, script.animation.name, script.animation.start,
                                   script.animation.fps);
    } catch (const std::invalid_argument& e) {
        throw CaptureScriptError(script.file.string() + ": animation.name: " + e.what());
    }
}

// The metrics of one resolution's runs, frame by frame: each method against the ground truth,
// its added flicker since the previous frame, its worst frame, and a JFA run's |dI| buckets
// against its standard-flooding counterpart.
class FrameScorer {
  public:
    FrameScorer(std::vector<MethodRun>& runs, std::size_t first, int jfaPasses)
        : runs_(runs), first_(first) {
        state_.previous.resize(runs.size() - first);
        for (std::size_t k = first; k < runs.size(); ++k) {
            const int c = counterpartOf(runs, k, jfaPasses);
            counterpart_.push_back(c);
            if (c >= 0) runs[k].counterpart = runs[static_cast<std::size_t>(c)].label;
        }
    }

    /// Scores frame i: `visibility` holds one image per run (moved from), `ref` the truth.
    void score(int i, std::vector<FloatImage>& visibility, const FrameImages& ref) {
        // Flicker compares with the previous frame: on the same surface points (reprojected with
        // the reference's motion; every method sees the same surfaces), and, as before, on the
        // same pixels where both frames have receivers.
        const FloatImage flickerReceivers =
            i > 0 ? bothReceivers(state_.previousReceivers, ref.receivers) : FloatImage{};
        std::optional<Reprojection> reprojection;
        if (i > 0)
            reprojection.emplace(ref.motion, state_.previousDepth, ref.receivers,
                                 state_.previousReceivers);
        for (std::size_t k = 0; k < visibility.size(); ++k) {
            MethodRun& run = runs_[first_ + k];
            FrameRow row;
            row.frame = i;
            // Every method sees the same surfaces: the reference's receivers are theirs.
            row.metrics = compareWithReference(visibility[k], ref.visibility, ref.receivers);
            if (reprojection) {
                row.flicker = addedSurfaceFlicker(*reprojection, state_.previous[k], visibility[k],
                                                  state_.previousReference, ref.visibility);
                row.screenFlicker =
                    addedFlicker(state_.previous[k], visibility[k], state_.previousReference,
                                 ref.visibility, flickerReceivers);
            }
            if (isWorse(run, row)) run.worst = {visibility[k], ref.visibility, ref.receivers};
            run.rows.push_back(std::move(row));
        }
        for (std::size_t k = 0; k < visibility.size(); ++k) {
            if (counterpart_[k] >= 0)
                runs_[first_ + k].rows.back().deltaBuckets =
                    compareSoftShadows(
                        visibility[k],
                        visibility[static_cast<std::size_t>(counterpart_[k]) - first_])
                        .deltaBuckets;
            state_.previous[k] = std::move(visibility[k]);
        }
        state_.previousReference = ref.visibility;
        state_.previousReceivers = ref.receivers;
        state_.previousDepth = depthOf(ref.motion);
    }

    /// Takes back the frames an earlier run finished (a resumed capture): their rows, each
    /// run's worst pictures and, when frames are left (`more`), the state after the last one.
    void replay(const std::vector<const FrameRecord*>& done, bool more, CaptureProgress& progress) {
        std::vector<std::pair<std::size_t, int>> worst;
        for (std::size_t k = 0; k + first_ < runs_.size(); ++k) {
            MethodRun& run = runs_[first_ + k];
            for (const FrameRecord* r : done) {
                isWorse(run, r->runs.at(k).row);
                run.rows.push_back(r->runs.at(k).row);
            }
            if (run.worstFrame >= 0) {
                run.worst = progress.loadWorst(first_ + k, run.worstFrame);
                worst.emplace_back(first_ + k, run.worstFrame);
            }
        }
        std::optional<std::pair<int, int>> last; // (resolution, frame) of the state kept
        if (!done.empty() && more) {
            last = {done.back()->size, done.back()->frame};
            state_ = progress.loadState(last->first, last->second, state_.previous.size());
        }
        progress.adopt(last, worst);
    }

    /// What the next frame's flicker needs from the last one scored.
    [[nodiscard]] const ScorerState& state() const { return state_; }

  private:
    // Whether `row` is the run's worst frame so far; if so, it becomes the run's worst.
    static bool isWorse(MethodRun& run, const FrameRow& row) {
        if (row.metrics.rmse <= run.worstRmse) return false;
        run.worstRmse = row.metrics.rmse;
        run.worstFrame = row.frame;
        return true;
    }

    std::vector<MethodRun>& runs_;
    std::size_t first_;
    std::vector<int> counterpart_;
    ScorerState state_;
};

// The stem of frame i's files ("frame_00042").
std::string frameStem(int i) {
    char stem[32];
    std::snprintf(stem, sizeof stem, "frame_%05d", i);
    return stem;
}

// A resumed frame's files must still be there: a frame whose line is in the journal is kept,
// not rendered again.
void requireFrameFiles(const fs::path& dir, int i) {
    for (const char* ext : {".png", ".visibility.png", ".exr"}) {
        const fs::path file = dir / (frameStem(i) + ext);
        if (!fs::is_regular_file(file))
            throw InputError(file.string() + ": missing, but the progress journal says frame " +
                             std::to_string(i) +
                             " is finished (run without --resume to start "
                             "over)");
    }
}

// One resolution's part of a capture run.
struct SizeRun {
    int index = 0; // into the script's resolutions
    int width = 0, height = 0;
    std::vector<const FrameRecord*> done; // its frames an earlier run finished
    int budget = -1;                      // frames this run may still render (-1: all)
};

// Every frame of the script at one resolution: appends one MethodRun per method to `results`,
// takes back the frames an earlier run finished, and records every frame it renders in
// `progress`. Returns the frames it rendered.
int captureSize(const CaptureSetup& c, const SizeRun& at, FrameRunner& runner,
                CaptureResults& results, CaptureProgress& progress) {
    const CaptureScript& script = c.script;
    const int w = at.width, h = at.height;
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
    const fs::path framesDir = c.dir / "frames" / size;
    std::vector<fs::path> laneDirs(lanes.size(), framesDir / "reference");
    for (std::size_t k = 0; k < script.methods.size(); ++k)
        if (laneOf[k] != 0) laneDirs[laneOf[k]] = framesDir / safeName(script.methods[k].label);

    // The frames an earlier run finished: their files, times and rows, and the scorer's state.
    for (const FrameRecord* r : at.done) {
        if (script.saveFrames)
            for (const fs::path& d : laneDirs) requireFrameFiles(d, r->frame);
        for (std::size_t l = 0; l < lanes.size(); ++l) {
            // A lane's times are those of its methods' rows (lane 0: the reference's own time,
            // with its phases where a `reference` entry kept them).
            const auto k = std::find(laneOf.begin(), laneOf.end(), l) - laneOf.begin();
            if (k == std::ssize(laneOf))
                lanes[l].times.append(r->referenceMs, {}, std::nullopt);
            else
                lanes[l].times.append(r->runs.at(std::size_t(k)).frameMs,
                                      r->runs.at(std::size_t(k)).phases,
                                      r->runs.at(std::size_t(k)).flood);
        }
    }
    scorer.replay(at.done, std::ssize(at.done) < script.frames, progress);

    const int firstFrame = static_cast<int>(at.done.size());
    const int rendered = at.budget < 0 ? script.frames - firstFrame
                                       : std::min(at.budget, script.frames - firstFrame);
    const FramePlan plan{
        .scene = &c.scene,
        .camera = script.camera
                      ? *script.camera
                      : defaultWalkthrough(initialCamera(c.scene, c.options, w, h), c.scene.bounds),
        .frames = script.frames,
        .first = firstFrame,
        .last = firstFrame + rendered - 1,
        .width = w,
        .height = h,
        .lightKeys = script.lightKeys,
        // A resumed run's first frame would carry the start-up (shader compilation, first
        // allocations) that only frame 0 carries in a run without a break: one frame unrecorded.
        .warmup = firstFrame > 0 ? 1 : 0,
        .clip = timeAxis(script, c.scene),
        // The reference's motion reprojects every method's flicker (FrameScorer::score).
        .motionLane = 0};
    if (rendered > 0)
        runner.run(plan, lanes, [&](int i, std::vector<FrameImages>& laneImages) {
            const FrameImages& ref = laneImages[0];
            if (script.saveFrames)
                for (std::size_t l = 0; l < lanes.size(); ++l)
                    writeFrame(laneImages[l], laneDirs[l], frameStem(i));
            std::vector<FloatImage> visibility(script.methods.size());
            for (std::size_t k = 0; k < script.methods.size(); ++k)
                // A `reference` entry's row is the reference against itself (lane 0, copied);
                // every other lane belongs to one method alone.
                visibility[k] =
                    laneOf[k] == 0 ? ref.visibility : std::move(laneImages[laneOf[k]].visibility);
            scorer.score(i, visibility, ref);

            // The frame is finished: into the progress, with the worst pictures it replaced.
            FrameRecord record{at.index, i, lanes[0].times.frameMs().back(), {}};
            std::vector<std::pair<std::size_t, const WorstPictures*>> worst;
            for (std::size_t k = 0; k < script.methods.size(); ++k) {
                const MethodRun& run = results.runs[first + k];
                const PhaseTimes& t = lanes[laneOf[k]].times;
                const std::size_t n = t.frames() - 1;
                record.runs.push_back({run.rows.back(), t.frameMs()[n], t.phases(n), t.flood(n)});
                if (run.worstFrame == i) worst.emplace_back(first + k, &run.worst);
            }
            const auto saveStart = std::chrono::steady_clock::now();
            progress.save(record, scorer.state(), worst);
            results.progressMs.push_back(std::chrono::duration<double, std::milli>(
                                             std::chrono::steady_clock::now() - saveStart)
                                             .count());
            // Memory and GL objects (one glIs* per name ever issued) after this sitting's first
            // frame and each resolution's last, not every frame.
            const bool firstSample = results.firstFrame.frame < 0, lastSample = i == plan.last;
            if (firstSample || lastSample) {
                const ResourceSample sample{i, residentKiB(), gl::countLiveObjects()};
                if (firstSample) results.firstFrame = sample;
                if (lastSample) results.lastFrame = sample;
            }
        });
    for (std::size_t k = 0; k < script.methods.size(); ++k)
        results.runs[first + k].times = lanes[laneOf[k]].times;
    const std::vector<double>& refMs = lanes[0].times.frameMs();
    results.referenceFrameMs.insert(results.referenceFrameMs.end(), refMs.begin(), refMs.end());
    return rendered;
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
            sideBySide({visibilityToGrey(run.worst.method), visibilityToGrey(run.worst.reference),
                        differencePicture(run.worst.method, run.worst.reference, 4.0f,
                                          run.worst.receivers)}));
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

// The hash of everything a capture's results depend on besides the build: the script's bytes,
// its camera keys (a camera file's among them), the scene file's size and time, the shaders.
std::string captureIdentity(const CaptureScript& script, const CaptureRequest& req) {
    CaptureIdentity id;
    id.add(readInputFile(script.file, "capture script", kTextInputLimitMiB));
    if (script.camera) {
        for (const CameraKey& k : script.camera->keys())
            for (int a = 0; a < 3; ++a) id.add(k.eye[a]).add(k.target[a]);
        id.add(script.camera->yfovDegrees())
            .add(static_cast<double>(script.camera->interpolation()));
    }
    std::error_code ec;
    if (!script.scene.empty())
        id.add(script.scene.string())
            .add(static_cast<double>(fs::file_size(script.scene, ec)))
            .add(static_cast<double>(
                fs::last_write_time(script.scene, ec).time_since_epoch().count()));
    id.add(req.shaderDir);
    return id.hex();
}

// Whether DIR holds the finished capture of this identity (its summary.json says so).
bool finishedHere(const fs::path& dir, const std::string& identity) {
    std::ifstream in(dir / "summary.json");
    if (!in) return false;
    const nlohmann::json summary = nlohmann::json::parse(in, nullptr, false);
    return summary.is_object() && summary.value("identity", "") == identity &&
           summary.value("complete", false);
}

// The journal's frames, grouped by resolution; throws InputError unless they are the first
// frames of the script in the order a run renders them.
std::vector<std::vector<const FrameRecord*>>
framesDone(const CaptureProgress& progress, const CaptureScript& script, const fs::path& dir) {
    std::vector<std::vector<const FrameRecord*>> done(script.resolutions.size());
    std::size_t size = 0;
    for (const FrameRecord& r : progress.records()) {
        if (size < done.size() && std::ssize(done[size]) == script.frames) ++size;
        if (r.size != static_cast<int>(size) || size >= done.size() ||
            r.frame != std::ssize(done[size]) || r.runs.size() != script.methods.size())
            throw InputError((dir / "progress.jsonl").string() + ": frame " +
                             std::to_string(r.frame) + " of resolution " + std::to_string(r.size) +
                             " is out of order (damaged; run without --resume to start over)");
        done[size].push_back(&r);
    }
    return done;
}

int runCapture(const CaptureRequest& req) {
    CaptureScript script;
    try {
        script = readCaptureScript(req.script);
    } catch (const CaptureScriptError& e) {
        throw InputError(e.what());
    }
    const fs::path dir(req.out);
    const std::string identity = captureIdentity(script, req);
    const int total = script.frames * static_cast<int>(script.resolutions.size());
    if (req.resume && !fs::exists(dir / "progress.jsonl") && finishedHere(dir, identity)) {
        std::cout << dir.string()
                  << ": this capture is finished (summary.json); nothing to "
                     "resume\n";
        return 0;
    }
    prepareOutput(dir);
    std::optional<CaptureProgress> progress;
    if (req.resume) {
        progress = CaptureProgress::resume(dir, identity, total);
        if (!progress)
            std::cout << "no unfinished capture in " << dir.string()
                      << " to resume: starting from frame 0\n";
    }
    if (!progress) progress = CaptureProgress::start(dir, identity, total);
    const std::vector<std::vector<const FrameRecord*>> done = framesDone(*progress, script, dir);
    const int finished = progress->finished();

    SceneOptions so;
    so.scene = script.scene.string();
    so.lightRadius = script.lightRadius;
    so.shaderDir = req.shaderDir;
    so.shadowMapSize = script.shadowMapSize;
    so.shadowMap = script.shadowMapProvider;
    so.methodOptions[std::string(floodPassesOption().flag)] = script.jfaPasses;
    so.strictMethodOptions = false; // the script's methods each take their own
    so.timing = req.timing;
    so.ground = script.ground;
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
    results.identity = identity;
    results.context = context->description();
    results.sceneName = scene.source;
    std::cout << "context: " << results.context << "\nscene: " << scene.source << " ("
              << scene.triangleCount() << " triangles), " << script.frames << " frames x "
              << script.methods.size() << " methods x " << script.resolutions.size()
              << " resolution(s); reference: " << referenceText(script.reference) << "\n";
    if (finished > 0)
        std::cout << "resuming: " << finished << " of " << total << " frames finished earlier\n";
    FrameRunner runner(total, finished);
    int budget = req.stopAfter > 0 ? req.stopAfter : -1;
    try {
        for (std::size_t s = 0; s < script.resolutions.size(); ++s) {
            const auto [w, h] = script.resolutions[s];
            const int rendered = captureSize(setup, {static_cast<int>(s), w, h, done[s], budget},
                                             runner, results, *progress);
            if (budget >= 0) budget -= rendered;
        }
    } catch (const std::exception&) {
        runner.finish();
        if (progress->finished() > 0)
            std::cerr << "note: " << progress->finished() << " of " << total
                      << " frames are finished in " << dir.string()
                      << "; add --resume to continue from there\n";
        throw;
    }
    runner.finish();
    if (progress->finished() < total) {
        std::cout << "stopped after " << req.stopAfter
                  << " frames (--stop-after): " << progress->finished() << " of " << total
                  << " finished in " << dir.string() << "; add --resume to continue\n";
        return kStoppedEarly;
    }

    // Everything is measured; now the outputs, the summary and the report last.
    const nlohmann::json summary = writeOutputs(dir, results);
    progress->finish();
    printSummaryTable(summary);
    if (results.lastFrame.frame >= 0)
        std::cout << "resources: resident " << results.firstFrame.residentKiB << " KiB after frame "
                  << results.firstFrame.frame << ", " << results.lastFrame.residentKiB
                  << " KiB after frame " << results.lastFrame.frame << "; GL objects "
                  << results.firstFrame.glObjects.total() << ", "
                  << results.lastFrame.glObjects.total() << "\n";
    if (!results.progressMs.empty())
        std::cout << "progress for --resume: " << std::fixed << std::setprecision(1)
                  << median(results.progressMs) << " ms a frame (median) to keep\n"
                  << std::defaultfloat;
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
    cmd->add_flag("--resume", r->resume,
                  "Continue the unfinished run in --out (killed, failed or stopped): keep its "
                  "finished frames, render the rest. Refused if the script, its camera or scene "
                  "changed; without an unfinished run, starts from frame 0");
    cmd->add_option("--stop-after", r->stopAfter,
                    "Render at most N frames in this run (1 to " +
                        std::to_string(kMaxCaptureFrames) +
                        "), then stop with exit status 3, keeping the progress for --resume (a "
                        "long capture in several sittings)")
        ->check(integer(1, kMaxCaptureFrames));
    return [r] { return runCapture(*r); };
}

} // namespace fl::app
