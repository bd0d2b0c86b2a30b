// `floodlight capture SCRIPT.json --out DIR`: every frame of a capture script with every method
// and the ground truth (`reference`), headless. Writes PNG + EXR per frame x method, frames.csv
// (one row per frame x method), summary.json and report.html (written last, so a run that fails
// leaves neither a summary nor a report behind). Every finished frame goes into the folder's
// progress (CaptureProgress.h) first: `--resume` continues a killed or failed run from there.
// With --capture-threads N > 0 (auto: on a GPU) the GL thread only renders and reads back (a
// frame behind, through pixel buffers); the files, metrics and progress run on N workers
// (CapturePipeline.h), with the same outputs. summary.json's "phaseSplit" says where the time
// went.

#include <app/CapturePipeline.h>
#include <app/CaptureProgress.h>
#include <app/CaptureResults.h>
#include <app/CaptureScorer.h>
#include <app/Commands.h>

#include <base/InputFile.h>
#include <base/OutputFiles.h>
#include <base/Process.h>
#include <base/Stats.h>
#include <renderer/run/FrameRunner.h>

#include <renderer/context/EglContext.h>
#include <renderer/metrics/ShadowStats.h>
#include <renderer/metrics/SoftStats.h>
#include <renderer/run/Capture.h>
#include <renderer/soft/EyeSoftShadow.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <thread>

namespace fl::app {

namespace {

namespace fs = std::filesystem;

struct CaptureRequest {
    std::string script;
    std::string out = "captures/capture";
    std::string shaderDir;
    std::string timing = "auto";
    bool resume = false;
    int stopAfter = 0;            // frames this run renders at most (0: all)
    std::string threads = "auto"; // --capture-threads: auto or 0..kMaxCaptureThreads
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

// Whether a script's entry is the ground truth itself (its row is then the reference against
// itself, from lane 0): the same method, and every option the entry gives has the reference's
// value (given or the row's default). {"method": "reference", "mapSize": 1024} beside a 2048²
// reference is a method of its own, rendered in its own lane.
bool isTheReference(const MethodSpec& m, const RenderSettings& reference) {
    if (m.method != reference.method) return false;
    for (const MethodOption* o : methodOrThrow(m.method).options)
        if (m.options.has(o->flag) && m.options.text(*o) != reference.options.text(*o))
            return false;
    return true;
}

// What every resolution of a capture shares.
struct CaptureSetup {
    const CaptureScript& script;
    const SceneOptions& options;
    const Scene& scene;
    const gl::ShaderLibrary& shaders;
    RenderSettings base, reference;
    fs::path dir;
    int threads = 0; // workers for files, metrics and progress (0: synchronous)
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

// Frames queued for files, metrics and progress at once (each holds every lane's images); the
// GL thread waits when as many are unfinished.
constexpr int kFramesInFlight = 2;

// What every frame of one resolution's capture shares, for its tasks.
struct FrameJob {
    const CaptureScript& script;
    const std::vector<Lane>& lanes;
    const std::vector<std::size_t>& laneOf; // by method: its lane
    const std::vector<fs::path>& laneDirs;  // by lane: its frames' folder
    FrameScorer& scorer;
    CaptureProgress& progress;
    CaptureResults& results;
    std::size_t first; // the resolution's first run in results.runs
    int size;          // the resolution's index in the script
};

// Queues frame i (every lane's images, moved from `laneImages`): its files, each lane's a task
// of its own, then its metrics and progress, in frame order. The times go into its record here,
// on the GL thread, which alone appends to the lanes' times.
void submitFrame(CapturePipeline& pipeline, const FrameJob& job, int i,
                 std::vector<FrameImages>& laneImages) {
    struct Frame {
        std::vector<FrameImages> images; // by lane
        FrameRecord record;
    };
    auto f = std::make_shared<Frame>();
    f->images = std::move(laneImages);
    laneImages.resize(f->images.size());
    const auto n = static_cast<std::size_t>(i); // the lanes' times hold every frame of the size
    f->record = {job.size, i, job.lanes[0].times.frameMs().at(n), {}};
    double renderMs = 0.0;
    for (const Lane& lane : job.lanes) renderMs += lane.times.frameMs().at(n);
    for (std::size_t k = 0; k < job.script.methods.size(); ++k) {
        const PhaseTimes& t = job.lanes[job.laneOf[k]].times;
        f->record.runs.push_back({{}, t.frameMs().at(n), t.phases(n), t.flood(n)});
    }
    std::vector<CapturePipeline::Task> files;
    if (job.script.saveFrames)
        for (std::size_t l = 0; l < f->images.size(); ++l)
            files.push_back({&PhaseSplit::files, [f, l, &job, i] {
                                 writeFrame(f->images[l], job.laneDirs[l], frameStem(i));
                             }});
    const auto metrics = [f, &job, i] {
        std::vector<FloatImage> visibility(job.laneOf.size());
        const FrameImages& ref = f->images[0];
        for (std::size_t k = 0; k < visibility.size(); ++k)
            // A `reference` entry's row is the reference against itself (lane 0, copied);
            // every other lane belongs to one method alone. The files are written by now.
            visibility[k] = job.laneOf[k] == 0 ? ref.visibility
                                               : std::move(f->images[job.laneOf[k]].visibility);
        job.scorer.score(i, visibility, ref);
    };
    const auto keep = [f, &job, i, renderMs] {
        // The frame is finished: into the progress, with the runs whose worst frame it is.
        std::vector<std::size_t> worst;
        for (std::size_t k = 0; k < job.laneOf.size(); ++k) {
            const MethodRun& run = job.results.runs[job.first + k];
            f->record.runs[k].row = run.rows.back();
            if (run.worstFrame == i) worst.push_back(job.first + k);
        }
        const auto start = std::chrono::steady_clock::now();
        job.progress.save(f->record, job.scorer.state(), worst);
        job.results.progressMs.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
        job.results.renderMs.push_back(renderMs);
    };
    pipeline.submit(std::move(files),
                    {{&PhaseSplit::metrics, metrics}, {&PhaseSplit::progress, keep}});
}

// One resolution's part of a capture run.
struct SizeRun {
    int index = 0; // into the script's resolutions
    int width = 0, height = 0;
    std::vector<const FrameRecord*> done; // its frames an earlier run finished
    int budget = -1;                      // frames this run may still render (-1: all)
};

// One resolution's renderers and lanes.
struct SizeLanes {
    std::vector<std::unique_ptr<Renderer>> renderers; // [0]: the reference's
    std::vector<Lane> lanes;
    std::vector<std::size_t> laneOf; // by method: its lane
    std::vector<fs::path> laneDirs;  // by lane: its frames' folder
};

// The lanes of one resolution, w x h, and a MethodRun per method appended to `results`. One
// renderer per method: each keeps its own maps and timers, and the reference's maps (its own
// size) are never shared with a method's. Lane 0 is the reference; a `reference` entry in the
// script's methods reads lane 0 rather than rendering the ground truth twice.
SizeLanes makeLanes(const CaptureSetup& c, int w, int h, CaptureResults& results) {
    const CaptureScript& script = c.script;
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    SizeLanes sl;
    const auto add = [&](const std::string& label, const RenderSettings& settings) {
        sl.renderers.push_back(std::make_unique<Renderer>(c.shaders, c.scene, settings));
        sl.renderers.back()->resize(w, h);
        sl.lanes.push_back({label, sl.renderers.back().get(), {}});
        return sl.lanes.size() - 1;
    };
    add("reference", c.reference);
    for (const MethodSpec& m : script.methods) {
        MethodRun run;
        run.spec = m;
        run.label = script.resolutions.size() > 1 ? m.label + " @" + size : m.label;
        run.width = w;
        run.height = h;
        sl.laneOf.push_back(
            isTheReference(m, c.reference) ? 0 : add(run.label, settingsFor(c.base, m)));
        results.runs.push_back(std::move(run));
    }
    const fs::path framesDir = c.dir / "frames" / size;
    sl.laneDirs.assign(sl.lanes.size(), framesDir / "reference");
    for (std::size_t k = 0; k < script.methods.size(); ++k)
        if (sl.laneOf[k] != 0)
            sl.laneDirs[sl.laneOf[k]] = framesDir / safeName(script.methods[k].label);
    return sl;
}

// The frames an earlier run finished: their files must be there, and their times go into the
// lanes (the rows and the scorer's state: FrameScorer::replay).
void takeBack(const CaptureScript& script, const std::vector<const FrameRecord*>& done,
              SizeLanes& sl) {
    for (const FrameRecord* r : done) {
        if (script.saveFrames)
            for (const fs::path& d : sl.laneDirs) requireFrameFiles(d, r->frame);
        for (std::size_t l = 0; l < sl.lanes.size(); ++l) {
            // A lane's times are those of its methods' rows (lane 0: the reference's own time,
            // with its phases where a `reference` entry kept them).
            const auto k = std::find(sl.laneOf.begin(), sl.laneOf.end(), l) - sl.laneOf.begin();
            if (k == std::ssize(sl.laneOf))
                sl.lanes[l].times.append(r->referenceMs, {}, std::nullopt);
            else
                sl.lanes[l].times.append(r->runs.at(std::size_t(k)).frameMs,
                                         r->runs.at(std::size_t(k)).phases,
                                         r->runs.at(std::size_t(k)).flood);
        }
    }
}

// Every frame of the script at one resolution: appends one MethodRun per method to `results`,
// takes back the frames an earlier run finished, and records every frame it renders in
// `progress`. Returns the frames it rendered.
int captureSize(const CaptureSetup& c, const SizeRun& at, FrameRunner& runner,
                CaptureResults& results, CaptureProgress& progress) {
    const CaptureScript& script = c.script;
    const int w = at.width, h = at.height;
    const std::size_t first = results.runs.size();
    SizeLanes sl = makeLanes(c, w, h, results);
    std::vector<Lane>& lanes = sl.lanes;
    const std::vector<std::size_t>& laneOf = sl.laneOf;
    const std::vector<fs::path>& laneDirs = sl.laneDirs;
    MethodOptions defaults; // the script's jfaPasses as a number (0: auto)
    defaults.set(floodPassesOption().flag, script.jfaPasses);
    FrameScorer scorer(results.runs, first, defaults.integer(floodPassesOption()));
    takeBack(script, at.done, sl);
    scorer.replay(at.done, std::ssize(at.done) < script.frames, progress);

    const int firstFrame = static_cast<int>(at.done.size());
    const int rendered = at.budget < 0 ? script.frames - firstFrame
                                       : std::min(at.budget, script.frames - firstFrame);
    const FramePlan plan{
        .scene = &c.scene,
        .camera = script.camera ? std::variant<CameraView, CameraPath>(*script.camera)
                                : namedCamera(script.cameraPath, c.scene, c.options, w, h),
        .frames = script.frames,
        .first = firstFrame,
        .last = firstFrame + rendered - 1,
        .width = w,
        .height = h,
        .lightKeys = script.lightKeys,
        // A resumed run's first frame would carry the start-up (shader compilation, first
        // allocations) that only frame 0 carries in a run without a break: one frame unrecorded.
        .warmup = firstFrame > 0 ? 1 : 0,
        // Pipelined: the GL thread goes on rendering while the frame before is copied out.
        .readBehind = c.threads > 0,
        .clip = timeAxis(script, c.scene),
        // The reference's motion reprojects every method's flicker (FrameScorer::score).
        .motionLane = 0,
        // And its surfaces say where acne and peter-panning can show (FrameScorer::score).
        .biasMasks = true};
    const FrameJob frameJob{script,   lanes,   laneOf, laneDirs, scorer,
                            progress, results, first,  at.index};
    // Declared after everything its tasks use: it finishes them before those go.
    CapturePipeline pipeline(c.threads, kFramesInFlight, results.split);
    if (rendered > 0)
        runner.run(plan, lanes, [&](int i, std::vector<FrameImages>& laneImages) {
            submitFrame(pipeline, frameJob, i, laneImages);
            // Memory and GL objects (one glIs* per name ever issued) after this sitting's first
            // frame and each resolution's last, not every frame.
            const bool firstSample = results.firstFrame.frame < 0, lastSample = i == plan.last;
            if (firstSample || lastSample) {
                const ResourceSample sample{i, residentKiB(), gl::countLiveObjects()};
                if (firstSample) results.firstFrame = sample;
                if (lastSample) results.lastFrame = sample;
            }
        });
    pipeline.drain();
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

// --capture-threads: a count, or auto: none on a software rasterizer (its frames use every
// core: workers slowed them, and added to the frame times it records: medium.json's rendering
// took 200 s alone, 265 s beside two workers), else one a core but the GL thread's, up to 4.
// Needs the GL context.
int captureThreads(const std::string& option) {
    if (option != "auto") return std::stoi(option); // checked by the option's validator
    if (gl::isSoftwareRenderer()) return 0;
    return std::clamp(static_cast<int>(std::thread::hardware_concurrency()) - 1, 1, 4);
}

// The folder's progress: the unfinished run's with --resume (when there is one), else a new one.
std::optional<CaptureProgress> openProgress(const CaptureRequest& req, const fs::path& dir,
                                            const std::string& identity, int total) {
    std::optional<CaptureProgress> progress;
    if (req.resume) {
        progress = CaptureProgress::resume(dir, identity, total);
        if (!progress)
            std::cout << "no unfinished capture in " << dir.string()
                      << " to resume: starting from frame 0\n";
    }
    if (!progress) progress = CaptureProgress::start(dir, identity, total);
    return progress;
}

// The scene and renderer options of a capture script.
SceneOptions sceneOptionsOf(const CaptureScript& script, const CaptureRequest& req) {
    SceneOptions so;
    so.scene = script.scene.string();
    so.lightRadius = script.lightRadius;
    so.lightSize = script.lightSize;
    so.shaderDir = req.shaderDir;
    so.shadowMapSize = script.shadowMapSize;
    so.shadowMap = script.shadowMapProvider;
    so.tsm = script.tsm;
    so.methodOptions[std::string(floodPassesOption().flag)] = script.jfaPasses;
    so.strictMethodOptions = false; // the script's methods each take their own
    so.timing = req.timing;
    so.ground = script.ground;
    return so;
}

// The ground truth's settings: `base` with the script's reference method and the options the
// script gives it (its row's defaults for the rest).
RenderSettings referenceSettings(const CaptureScript& script, RenderSettings base) {
    base.method = std::string(script.reference.method().name);
    for (const auto& [flag, value] : script.reference.options.values())
        base.options.set(flag, value);
    return base;
}

// Every resolution's frames, within --stop-after's budget; on a failure, says how to resume.
void renderSizes(const CaptureSetup& setup, const CaptureRequest& req,
                 const std::vector<std::vector<const FrameRecord*>>& done, FrameRunner& runner,
                 CaptureResults& results, CaptureProgress& progress, int total) {
    int budget = req.stopAfter > 0 ? req.stopAfter : -1;
    try {
        for (std::size_t s = 0; s < setup.script.resolutions.size(); ++s) {
            const auto [w, h] = setup.script.resolutions[s];
            const int rendered = captureSize(setup, {static_cast<int>(s), w, h, done[s], budget},
                                             runner, results, progress);
            if (budget >= 0) budget -= rendered;
        }
    } catch (const std::exception&) {
        runner.finish();
        if (progress.finished() > 0)
            std::cerr << "note: " << progress.finished() << " of " << total
                      << " frames are finished in " << setup.dir.string()
                      << "; add --resume to continue from there\n";
        throw;
    }
    runner.finish();
}

// The outputs, the summary and the report, once every frame is measured.
void finishCapture(const fs::path& dir, const CaptureScript& script, CaptureResults& results,
                   CaptureProgress& progress) {
    const nlohmann::json summary = writeOutputs(dir, results);
    progress.finish();
    printSummaryTable(summary);
    printResources(results);
    printPhaseSplit(results);
    std::cout << "wrote " << (dir / "frames.csv").string() << ", "
              << (dir / "summary.json").string() << ", " << (dir / "report.html").string()
              << (script.saveFrames ? ", frames under " + (dir / "frames").string() : "") << "\n";
}

int runCapture(const CaptureRequest& req) {
    const auto started = std::chrono::steady_clock::now();
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
    std::optional<CaptureProgress> progress = openProgress(req, dir, identity, total);
    const std::vector<std::vector<const FrameRecord*>> done = framesDone(*progress, script, dir);
    const int finished = progress->finished();

    const SceneOptions so = sceneOptionsOf(script, req);
    const Scene scene = loadScene(so);
    auto context = EglContext::create();
    const gl::ShaderLibrary shaders = makeShaderLibrary(so);
    const RenderSettings base = makeRenderSettings(so);
    const CaptureSetup setup{script, so,
                             scene,  shaders,
                             base,   referenceSettings(script, base),
                             dir,    captureThreads(req.threads)};

    CaptureResults results;
    results.script = &script;
    results.identity = identity;
    results.context = context->description();
    results.sceneName = scene.source;
    std::cout << "context: " << results.context << "\nscene: " << scene.source << " ("
              << scene.triangleCount() << " triangles), " << script.frames << " frames x "
              << script.methods.size() << " methods x " << script.resolutions.size()
              << " resolution(s); reference: " << referenceText(script.reference) << "\n"
              << setupLine(scene, base, script.resolutions.front().first,
                           script.resolutions.front().second)
              << "\n";
    if (finished > 0)
        std::cout << "resuming: " << finished << " of " << total << " frames finished earlier\n";
    FrameRunner runner(total, finished);
    renderSizes(setup, req, done, runner, results, *progress, total);
    results.split.render = runner.seconds().render;
    results.split.readBack = runner.seconds().readBack;
    results.split.wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (progress->finished() < total) {
        std::cout << "stopped after " << req.stopAfter
                  << " frames (--stop-after): " << progress->finished() << " of " << total
                  << " finished in " << dir.string() << "; add --resume to continue\n";
        return kStoppedEarly;
    }
    finishCapture(dir, script, results, *progress);
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
    cmd->add_option("--capture-threads", r->threads,
                    "Worker threads that write the frames' files and compute their metrics and "
                    "progress while the next frames render: auto or 0 to " +
                        std::to_string(kMaxCaptureThreads) +
                        " (0: one frame after another, on the GL thread; auto: 0 on a software "
                        "rasterizer, whose frames use every core, else up to 4). Same outputs "
                        "either way")
        ->check(CLI::Validator(
            [](const std::string& text) -> std::string {
                if (text == "auto") return {};
                const std::string problem = numberProblem(text, 0, kMaxCaptureThreads, true);
                // "must be an integer in [0, 16], got 'x'" -> "must be auto or an integer ..."
                return problem.starts_with("must be ") ? "must be auto or " + problem.substr(8)
                                                       : problem;
            },
            "auto|INT"))
        ->capture_default_str();
    return [r] { return runCapture(*r); };
}

} // namespace fl::app
