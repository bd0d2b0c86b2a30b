#pragma once
// A capture's metrics, frame by frame (CaptureCommand.cpp runs it, on a worker thread when the
// capture is pipelined: CapturePipeline.h).

#include <app/CaptureProgress.h>
#include <app/CaptureResults.h>

#include <renderer/run/Capture.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace fl::app {

// The metrics of one resolution's runs, frame by frame: each method against the ground truth,
// its added flicker since the previous frame, its worst frame, and a JFA run's |dI| buckets
// against its standard-flooding counterpart.
class FrameScorer {
  public:
    /// Scores runs[first..]: the methods of one resolution; `jfaPasses` is the script's
    /// (0: auto), the pass count a counterpart must share.
    FrameScorer(std::vector<MethodRun>& runs, std::size_t first, int jfaPasses);

    /// Scores frame i: `visibility` holds one image per run (moved from), `ref` the truth.
    void score(int i, std::vector<FloatImage>& visibility, const FrameImages& ref);

    /// Takes back the frames an earlier run finished (a resumed capture): their rows, each
    /// run's worst pictures and, when frames are left (`more`), the state after the last one.
    void replay(const std::vector<const FrameRecord*>& done, bool more, CaptureProgress& progress);

    /// What the next frame's flicker needs from the last one scored.
    [[nodiscard]] const ScorerState& state() const { return state_; }

  private:
    // Whether `row` is the run's worst frame so far; if so, it becomes the run's worst.
    static bool isWorse(MethodRun& run, const FrameRow& row);

    std::vector<MethodRun>& runs_;
    std::size_t first_;
    std::vector<int> counterpart_;
    ScorerState state_;
};

} // namespace fl::app
