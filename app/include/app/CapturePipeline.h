#pragma once
// The work a capture does for each frame once it is read back, off the GL thread: the frame's
// files (each lane's PNG and EXR, in any order, several at once), then its metrics and progress
// (in frame order: a frame's flicker needs the frame before scored, and the journal must list
// frames in order, each after its files). The GL thread renders the next frames meanwhile.
//
// With no workers, submit() runs a frame's tasks at once, on the caller's thread: the
// synchronous capture of before, kept as the path the pipelined one is checked against.

#include <app/CaptureResults.h>

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace fl::app {

/// The most worker threads `capture --capture-threads` takes.
inline constexpr int kMaxCaptureThreads = 16;

class CapturePipeline {
  public:
    /// One task and the phase its seconds count in (PhaseSplit: files, metrics, progress).
    struct Task {
        double PhaseSplit::*phase;
        std::function<void()> run;
    };

    /// `threads` workers (0: synchronous); at most `framesInFlight` (>= 1) frames queued or
    /// running at once, so that memory stays bounded. Task times and the caller's waits add to
    /// `split`, which the caller reads only after drain().
    CapturePipeline(int threads, int framesInFlight, PhaseSplit& split);
    /// Finishes what can still be finished (every frame before a failed one), then joins; never
    /// throws (a capture that failed on the GL thread keeps the frames before the failure).
    ~CapturePipeline();
    CapturePipeline(const CapturePipeline&) = delete;
    CapturePipeline& operator=(const CapturePipeline&) = delete;

    /// Queues a frame: `parallel` tasks in any order, concurrently; then `ordered` ones, one
    /// after another, after every earlier frame's. Blocks while the frames in flight are at the
    /// limit. Rethrows the failure of an earlier frame's task (the earliest frame's).
    void submit(std::vector<Task> parallel, std::vector<Task> ordered);
    /// Waits for every frame submitted; rethrows the first failure (the earliest frame's).
    void drain();

  private:
    struct Frame {
        long index = 0;
        std::vector<Task> parallel, ordered;
        std::size_t nextParallel = 0; // the first parallel task not started
        std::size_t running = 0;      // parallel tasks started, not finished
    };

    void work();
    // Runs `task`, adding its seconds to the split; false if it threw (the error is kept).
    bool runTask(const Task& task, long frame, std::unique_lock<std::mutex>& lock);
    // A failed frame and those after it are not committed: their tasks left go unrun.
    [[nodiscard]] bool dropped(const Frame& f) const { return failed_ >= 0 && f.index >= failed_; }
    void rethrowFailure();
    void waitFor(const std::function<bool()>& done, std::unique_lock<std::mutex>& lock);

    PhaseSplit& split_;
    std::size_t framesInFlight_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<Frame> frames_; // oldest first
    bool orderedBusy_ = false; // the front frame's ordered tasks are running
    bool stop_ = false;
    long submitted_ = 0;
    long failed_ = -1; // the earliest frame whose task threw
    std::exception_ptr error_;
    std::vector<std::thread> workers_;
};

} // namespace fl::app
