#pragma once
// The frame loop that `capture`, `compare` and the benchmarks share: walk a camera path (and the
// light along its keys) or hold one camera, render every lane each frame, read the frames back,
// keep each lane's frame and phase times from its renderer's PassTimer, show a progress bar on a
// terminal. Also what such runs write: CSV tables and JSON summaries, each under a temporary name
// first, then renamed, so a failed run never leaves a half-written file under the final name.

#include <gpu/PassTimer.h>
#include <renderer/Renderer.h>
#include <renderer/run/Capture.h>
#include <scene/CameraPath.h>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace fl {

/// The standard-flooding method a jump-flooding method is measured against (same pass count),
/// from the method table (jfa-l -> flood-l, jfa-e -> flood-e); none for every other method.
std::optional<std::string> referenceOf(const std::string& method);

/// A flooding method's flood in one frame: the passes it ran (with `--jfa-passes auto`, the
/// count it chose) and the share of the grid's texels its band covered (1 for a full-grid flood).
struct FloodSample {
    int passes = 0;
    double activeShare = 1.0;
    /// Share of the grid an average pass computed: activeShare, or less within the flood's front
    /// (jfa/Band.h).
    double computedShare = 1.0;
};

/// What the renderer's last frame flooded; nullopt for methods that do not flood.
std::optional<FloodSample> floodSample(const Renderer& renderer);

/// Bytes of render targets and images the renderer's last frame wrote, per phase in the order
/// the phases ran (a phase run more than once summed): what each pass told its timer
/// (PassTimer::wrote), plus the flood's, added to its "flood" phase: the passes run x the cells'
/// texture x the share of the grid an average pass computed (reads 4 bytes back, like
/// floodSample). Computed from the targets' formats, not measured.
std::vector<std::pair<std::string, std::int64_t>> writtenBytes(const Renderer& renderer);

/// One renderer's times over a run: per frame, the frame's total and each pass its timer
/// reported, and its flood (passes, active share) where the method floods.
class PhaseTimes {
  public:
    using Phases = std::vector<std::pair<std::string, double>>; // (pass name, ms) in pass order

    /// Appends the frame `timer` has just timed, with its flood.
    void record(const gl::PassTimer& timer, std::optional<FloodSample> flood = std::nullopt);
    /// Appends a frame timed earlier (a resumed capture's frames, read from its progress).
    void append(double frameMs, Phases phases, std::optional<FloodSample> flood);
    /// Frame i's flood; nullopt where the method did not flood.
    [[nodiscard]] const std::optional<FloodSample>& flood(std::size_t i) const {
        return flood_.at(i);
    }
    /// Median over the frames that flooded of the passes and of the active share (nullopt if
    /// none did).
    [[nodiscard]] std::optional<FloodSample> medianFlood() const;
    [[nodiscard]] std::size_t frames() const { return frameMs_.size(); }
    [[nodiscard]] const std::vector<double>& frameMs() const { return frameMs_; }
    /// The passes of frame i, in the order they ran.
    [[nodiscard]] const Phases& phases(std::size_t i) const { return phases_.at(i); }
    /// The phase's ms in frame i: summed if it ran more than once, 0 if it did not run.
    [[nodiscard]] double phaseMs(std::size_t i, const std::string& name) const;
    /// The phase's ms in every frame, counting frames without it as 0.
    [[nodiscard]] std::vector<double> phaseSeries(const std::string& name) const;
    /// Whether any frame ran the phase.
    [[nodiscard]] bool ran(const std::string& name) const;
    /// Median frame time (fl::median; 0 without frames).
    [[nodiscard]] double medianFrameMs() const;
    /// Median of the phase over every frame, counting frames without it as 0.
    [[nodiscard]] double medianPhaseMs(const std::string& name) const;

  private:
    std::vector<double> frameMs_;
    std::vector<Phases> phases_;
    std::vector<std::optional<FloodSample>> flood_;
};

/// Every phase any of `times` ran, in the order first seen: the phase columns of a table.
std::vector<std::string> phaseNames(const std::vector<const PhaseTimes*>& times);

/// One renderer the loop drives. `label` names its frames in error messages.
struct Lane {
    std::string label;
    Renderer* renderer = nullptr;
    PhaseTimes times; // filled by FrameRunner::run, one entry per frame
};

/// What one loop renders: frames [first, frames) of a `frames`-frame run at width x height, along
/// a camera path or all from one camera (a benchmark's repeated frame). The light moves along
/// `lightKeys` (lightPositionAt); with none, each renderer's light stays where it is.
struct FramePlan {
    const Scene* scene = nullptr;
    std::variant<CameraView, CameraPath> camera;
    int frames = 0;
    /// The first frame rendered: a resumed capture starts after the frames it already has.
    int first = 0;
    /// The last frame rendered (-1: frames - 1): a capture told to stop early ends before.
    int last = -1;
    int width = 0, height = 0;
    std::vector<glm::vec3> lightKeys;
    /// Frames rendered before frame `first` at its camera and light, neither recorded nor passed
    /// on: a benchmark's warm-up (shader compilation, first-use allocations).
    int warmup = 0;
    /// false: frames are timed only, nothing is read back (onFrame gets empty images).
    bool readBack = true;
    /// true: read back through pixel buffers a frame behind (FrameReadBack): frame i's images
    /// are mapped, and passed to onFrame, after frame i + 1 is rendered, so the GL thread never
    /// waits for a copy. The last frame's follow when the loop ends. Same images either way.
    bool readBehind = false;
    /// The time axis (scene/Pose.h): when set, every lane plays these animations and
    /// frame i is posed at start + i * step seconds (step 0: every frame at `start`), with frame
    /// i - 1's time as the motion target's previous one.
    struct Clip {
        std::vector<int> animations;
        double start = 0.0, step = 0.0;
        [[nodiscard]] double timeOf(int frame) const { return start + frame * step; }
        /// The clip of `animation` (all | none | NAME | INDEX: chooseAnimations) on `scene`
        /// from `start` at `fps` frames per second (0: every frame at `start`). Throws
        /// std::invalid_argument for an animation the scene does not have.
        static Clip of(const Scene& scene, const std::string& animation, double start, double fps);
    };
    std::optional<Clip> clip;
    /// The lane whose frames write the motion target (Renderer::render with the frame before's
    /// camera), for flicker on the same surface point; -1: none. The other lanes' surfaces pass
    /// skips it, so their times carry no cost that only scoring adds.
    int motionLane = -1;
    /// true: the motion lane's frames also carry the acne and peter-panning masks
    /// (FrameImages::facingLight, contact; renderer/metrics/BiasArtifacts.h), read from its
    /// surfaces right after it renders.
    bool biasMasks = false;
};

/// Drives lanes through one or more plans, with one progress bar over all of them.
class FrameRunner {
  public:
    /// The frame's images, one per lane in lane order; the callback may move from them.
    using OnFrame = std::function<void(int frame, std::vector<FrameImages>& images)>;

    /// `totalFrames`: the frames of every plan this runner will run (the progress bar's end);
    /// `done`: how many of them an earlier run already rendered (a resumed capture).
    explicit FrameRunner(int totalFrames, int done = 0);
    /// Renders every frame of `plan` with every lane (in lane order, frame by frame, so lanes
    /// share the machine's state alike), reads each back and checks its visibility is finite
    /// (unless !plan.readBack), appends the lane's times, then calls `onFrame` (if set).
    void run(const FramePlan& plan, std::vector<Lane>& lanes, const OnFrame& onFrame = {});
    /// Ends the progress line (call once, after the last plan).
    void finish();

    /// Wall seconds the calling thread spent in every run() so far: rendering (Renderer::render,
    /// which waits for the GPU at its end) and reading the frames back (with the finiteness
    /// check and the times), not counting `onFrame`.
    struct Seconds {
        double render = 0.0, readBack = 0.0;
    };
    [[nodiscard]] const Seconds& seconds() const { return seconds_; }

  private:
    void showProgress();
    // Frame i's images of every lane to `images` (each lane's finiteness checked), a frame behind.
    void finishReadBack(std::vector<FrameReadBack>& reads, std::vector<Lane>& lanes, int i,
                        std::vector<FrameImages>& images);
    // Hands frame i to onFrame and advances the progress bar.
    void handOver(int i, std::vector<FrameImages>& images, const OnFrame& onFrame);

    using Clock = std::chrono::steady_clock;
    int total_;
    int done_;
    int doneBefore_; // frames of an earlier run: not in this run's rate
    bool tty_;       // the bar is drawn on a terminal only: logs and pipes get no carriage returns
    Clock::time_point start_ = Clock::now();
    Seconds seconds_;
};

/// A CSV table built row by row: the header line, then one line per row. Cells go through an
/// ostream at its default 6 significant digits.
class CsvTable {
  public:
    explicit CsvTable(const std::vector<std::string>& columns);
    /// Appends a cell to the current row.
    template <class T>
    CsvTable& operator<<(const T& value) {
        separate();
        out_ << value;
        return *this;
    }
    /// Appends an empty cell (a value this row does not have).
    CsvTable& blank();
    /// Ends the current row.
    void endRow();
    [[nodiscard]] std::string text() const { return out_.str(); }

  private:
    void separate();

    std::ostringstream out_;
    bool rowStarted_ = false;
};

/// `text` usable in a CSV header or cell: spaces become '_', commas ';' ("shadow map" ->
/// "shadow_map").
std::string csvName(std::string text);
/// Writes the table to `path` (temporary name, then rename).
void writeCsv(const std::filesystem::path& path, const CsvTable& table);
/// Writes `j` indented by 2, with a final newline, to `path` (temporary name, then rename).
void writeJson(const std::filesystem::path& path, const nlohmann::json& j);

} // namespace fl
