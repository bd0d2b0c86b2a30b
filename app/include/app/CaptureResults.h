#pragma once
// What a capture run measured, handed from the run (CaptureCommand.cpp) to the outputs
// (CaptureOutput.cpp: CSV, JSON summary) and the HTML report (Report*.cpp).

#include <app/CaptureScript.h>
#include <renderer/run/FrameRunner.h>

#include <gpu/LiveObjects.h>

#include <io/ImageIO.h>
#include <renderer/metrics/BiasArtifacts.h>
#include <renderer/metrics/Metrics.h>

#include <nlohmann/json.hpp>

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fl::app {

/// One frame of one method (one CSV row).
struct FrameRow {
    int frame = 0;
    FrameMetrics metrics;
    /// Added flicker since the previous frame on the same surface points (Metrics.h,
    /// addedSurfaceFlicker; none on frame 0), and the screen-space figure of before (the same
    /// pixel in both frames: camera motion moving a shadow across the screen counts too).
    std::optional<double> flicker;
    std::optional<double> screenFlicker;
    /// |dI| buckets against the standard-flooding counterpart (thesis Fig. 5.4(a)), for JFA
    /// methods whose counterpart is in the script.
    std::optional<std::array<double, 4>> deltaBuckets;
    /// Acne and peter-panning against the reference (renderer/metrics/BiasArtifacts.h).
    BiasArtifactCounts bias;
};

/// A method's worst frame: its visibility, the reference's and the receivers its metrics counted.
struct WorstPictures {
    FloatImage method, reference, receivers;
};

/// Every frame of one method at one resolution, and its worst frame's pictures.
struct MethodRun {
    std::string label; // "pcss:16/24", with " @WxH" when the script has several resolutions
    MethodSpec spec;
    int width = 0, height = 0;
    std::string counterpart; // label of the standard-flooding run its dI buckets are against
    std::vector<FrameRow> rows;
    PhaseTimes times; // frame and per-pass times, one entry per row
    int worstFrame = -1;
    double worstRmse = -1.0;
    WorstPictures worst;
};

/// What the process held after a frame: a capture of thousands of frames must end about where
/// it began (a soak: bench/soak.sh).
struct ResourceSample {
    int frame = -1; // -1: not sampled
    std::size_t residentKiB = 0;
    gl::ObjectCounts glObjects;
};

/// Where one sitting's wall time went, in seconds. Rendering and read-back are the GL thread's;
/// metrics, files and progress are the time the tasks took, on the GL thread when the capture
/// runs synchronously (--capture-threads 0), else on worker threads, overlapped with rendering
/// (their sum may then exceed the wall); waiting is the GL thread's wait for the workers.
struct PhaseSplit {
    double wall = 0.0; // from the command's start to the last frame's progress
    double render = 0.0, readBack = 0.0, metrics = 0.0, files = 0.0, progress = 0.0;
    double waiting = 0.0;
    int threads = 0; // worker threads (0: synchronous)
};

/// The split's phases, in the order printed and written (summary.json's "phaseSplit", in
/// seconds): the one list of them.
struct SplitPhase {
    const char* name; // the JSON key, "<name>Seconds"
    double PhaseSplit::*seconds;
};
inline constexpr SplitPhase kSplitPhases[] = {
    {"wall", &PhaseSplit::wall},         {"render", &PhaseSplit::render},
    {"readBack", &PhaseSplit::readBack}, {"metrics", &PhaseSplit::metrics},
    {"files", &PhaseSplit::files},       {"progress", &PhaseSplit::progress},
    {"waiting", &PhaseSplit::waiting}};

struct CaptureResults {
    const CaptureScript* script = nullptr;
    std::string identity; // the hash a resumed run must match (CaptureProgress.h)
    std::string context;  // GL renderer description
    std::string sceneName;
    std::vector<MethodRun> runs;
    std::vector<double> referenceFrameMs; // the ground truth's own time, every frame
    ResourceSample firstFrame, lastFrame; // after this run's first and last frame
    std::vector<double> progressMs;       // per frame: keeping its progress (CaptureProgress)
    /// Per frame: the sum of every lane's render (GPU-waited) ms, what progressMs is held to.
    std::vector<double> renderMs;
    PhaseSplit split;
};

/// The share of the wall time spent outside rendering (the target: at most one half).
double outsideRendering(const PhaseSplit& split);
/// Keeping the progress against rendering: the median over this sitting's frames of the frame's
/// progress ms over the ms its lanes took to render (0 without frames).
double progressShare(const CaptureResults& r);

/// Prints the summary's table (one line per method), the resources after this sitting's first
/// and last frame, and the phase split with what keeping the progress cost.
void printSummaryTable(const nlohmann::json& summary);
void printResources(const CaptureResults& r);
void printPhaseSplit(const CaptureResults& r);

/// Folder-safe form of a label ("pcss:16/24 @64x64" -> "pcss_16-24_64x64").
std::string safeName(const std::string& label);

/// The CSV: one row per frame x method.
CsvTable resultsCsv(const CaptureResults& r);
/// The JSON summary: per method, pooled RMSEs, mean misclassification, width error, added
/// flicker, median per-phase and frame times, time relative to `hard`.
nlohmann::json resultsSummary(const CaptureResults& r);

/// The report: one self-contained HTML file (inline SVG charts, images linked relatively from
/// `imageDir`, which the caller has written: IMAGEDIR/worst_SAFENAME.png).
std::string reportHtml(const CaptureResults& r, const nlohmann::json& summary,
                       const std::string& imageDir);

} // namespace fl::app
