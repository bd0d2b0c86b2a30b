#pragma once
// A capture's progress on disk, so that `capture --resume` continues a killed or failed run.
// A ground-truth walkthrough takes hours on a software renderer; before this, a run that died
// at frame 900 of 1000 started again from frame 0.
//
//   DIR/progress.jsonl   line 1: {"floodlightCapture": 1, "identity": HASH, "frames": TOTAL}
//                        then one line per finished frame: every method's CSV row and times
//   DIR/resume/          what the next frame's metrics need from the last one: every method's
//                        visibility and the reference's (state_S_I.exr, uncompressed). The same
//                        file of an earlier frame stays while it is a method's worst frame so
//                        far: it holds that frame's pictures for the report.
//
// A frame is finished when its line is in the journal: its frame files and pictures are written
// first, the line last, and the superseded pictures are removed after it. A killed run therefore
// loses at most the frames in flight: one synchronously, up to four with --capture-threads (the
// one being rendered, the one read back a frame behind and the two queued for the workers,
// CapturePipeline.h). The journal and
// resume/ go when the capture's summary and report are written.

#include <app/CaptureResults.h>

#include <io/ImageIO.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fl::app {

/// One method's part of a finished frame: its CSV row and its times.
struct RunFrame {
    FrameRow row;
    double frameMs = 0.0;
    PhaseTimes::Phases phases;
    std::optional<FloodSample> flood;
};

/// One finished frame of one resolution (index into the script's resolutions), every method.
struct FrameRecord {
    int size = 0;
    int frame = 0;
    double referenceMs = 0.0;
    std::vector<RunFrame> runs; // in the script's method order
};

/// What scoring the next frame needs from the last one (its flicker against this frame).
struct ScorerState {
    std::vector<FloatImage> previous; // each method's visibility
    FloatImage previousReference, previousReceivers;
    FloatImage previousDepth; // the reference frame's depthOf(motion): the next reprojection
};

/// A hash of everything that fixes a capture's results, as 16 hex digits (FNV-1a 64): a resumed
/// run must render what the killed one would have.
class CaptureIdentity {
  public:
    CaptureIdentity& add(std::string_view bytes);
    CaptureIdentity& add(double value);
    [[nodiscard]] std::string hex() const;

  private:
    std::uint64_t h_ = 14695981039346656037ull;
};

/// The journal and the pictures of one capture folder.
class CaptureProgress {
  public:
    /// Starts afresh in `dir`: removes an earlier run's progress, frames and report pictures
    /// (saying so when that run was unfinished) and writes the journal's first line.
    static CaptureProgress start(const std::filesystem::path& dir, const std::string& identity,
                                 int totalFrames);
    /// Continues the unfinished run in `dir`: reads its journal (dropping a torn last line)
    /// and checks the identity; throws InputError if the run was of another script or its
    /// journal is damaged. nullopt when `dir` holds no unfinished run.
    static std::optional<CaptureProgress> resume(const std::filesystem::path& dir,
                                                 const std::string& identity, int totalFrames);

    /// The frames an earlier run finished (read by resume()), in the order they were rendered.
    [[nodiscard]] const std::vector<FrameRecord>& records() const { return records_; }
    /// How many frames are finished: the earlier run's and this run's.
    [[nodiscard]] int finished() const { return static_cast<int>(records_.size()) + saved_; }

    /// Saves frame `frame` of resolution `size`: the scorer's state after it (also the pictures
    /// of `worstRuns`, the global runs whose worst frame it is), then its line.
    void save(const FrameRecord& record, const ScorerState& state,
              const std::vector<std::size_t>& worstRuns);
    /// The scorer's state after the last finished frame of resolution `size` (`runs` methods).
    [[nodiscard]] ScorerState loadState(int size, int frame, std::size_t runs) const;
    /// The worst pictures of method `k` of resolution `size`, saved with frame `frame`'s state.
    [[nodiscard]] WorstPictures loadWorst(int size, std::size_t k, int frame) const;
    /// Marks the files of a resumed run as in use, so that saves remove them once superseded:
    /// the state of (resolution, frame) if any, and each global run's worst (resolution, frame).
    void adopt(std::optional<std::pair<int, int>> state,
               const std::vector<std::pair<std::size_t, std::pair<int, int>>>& worst);

    /// The capture's outputs are written: removes the journal and resume/.
    void finish();

  private:
    CaptureProgress(std::filesystem::path dir) : dir_(std::move(dir)) {}
    [[nodiscard]] std::filesystem::path journal() const { return dir_ / "progress.jsonl"; }
    [[nodiscard]] std::filesystem::path statePath(int size, int frame) const;
    void append(const std::string& line);

    std::filesystem::path dir_;
    std::vector<FrameRecord> records_;
    int saved_ = 0; // frames this run saved (their records live in the capture's results only)
    std::filesystem::path state_;              // the current state file
    std::vector<std::filesystem::path> worst_; // by global run: the state file of its worst frame
};

/// The journal line of a finished frame, and back (throws std::runtime_error on a bad line).
std::string recordLine(const FrameRecord& record);
FrameRecord parseRecordLine(const std::string& line);

} // namespace fl::app
