#include <app/CapturePipeline.h>

#include <algorithm>
#include <chrono>

namespace fl::app {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

} // namespace

CapturePipeline::CapturePipeline(int threads, int framesInFlight, PhaseSplit& split)
    : split_(split), framesInFlight_(static_cast<std::size_t>(std::max(1, framesInFlight))) {
    split_.threads = threads;
    for (int t = 0; t < threads; ++t) workers_.emplace_back([this] { work(); });
}

CapturePipeline::~CapturePipeline() {
    {
        std::unique_lock lock(mutex_);
        waitFor([this] { return frames_.empty(); }, lock);
        stop_ = true;
    }
    changed_.notify_all();
    for (std::thread& t : workers_) t.join();
}

bool CapturePipeline::runTask(const Task& task, long frame, std::unique_lock<std::mutex>& lock) {
    if (lock.owns_lock()) lock.unlock();
    const Clock::time_point start = Clock::now();
    std::exception_ptr error;
    try {
        task.run();
    } catch (...) {
        error = std::current_exception();
    }
    const double s = secondsSince(start);
    lock.lock();
    split_.*task.phase += s;
    if (error && (failed_ < 0 || frame < failed_)) {
        failed_ = frame;
        error_ = error;
    }
    return !error;
}

void CapturePipeline::work() {
    std::unique_lock lock(mutex_);
    for (;;) {
        // Frames that can no longer be committed go unrun.
        while (!frames_.empty() && !orderedBusy_ && dropped(frames_.front()) &&
               frames_.front().running == 0) {
            frames_.pop_front();
            changed_.notify_all();
        }
        if (!frames_.empty() && !orderedBusy_) {
            // The oldest frame's ordered tasks, once its files are written.
            Frame& f = frames_.front();
            if (f.nextParallel == f.parallel.size() && f.running == 0 && !dropped(f)) {
                orderedBusy_ = true;
                const std::vector<Task> ordered = std::move(f.ordered);
                for (const Task& t : ordered)
                    if (dropped(f) || !runTask(t, f.index, lock)) break;
                frames_.pop_front(); // f is the front still: only this worker pops while busy
                orderedBusy_ = false;
                changed_.notify_all();
                continue;
            }
        }
        Frame* next = nullptr;
        for (Frame& f : frames_)
            if (f.nextParallel < f.parallel.size() && !dropped(f)) {
                next = &f;
                break;
            }
        if (next) {
            const Task& task = next->parallel[next->nextParallel++];
            ++next->running;
            const long index = next->index;
            Frame* self = next; // deque elements stay put: only the front is popped, and
                                // not while it has tasks running
            runTask(task, index, lock);
            --self->running;
            changed_.notify_all();
            continue;
        }
        if (stop_) return;
        changed_.wait(lock);
    }
}

void CapturePipeline::waitFor(const std::function<bool()>& done,
                              std::unique_lock<std::mutex>& lock) {
    if (done()) return;
    const Clock::time_point start = Clock::now();
    changed_.wait(lock, done);
    split_.waiting += secondsSince(start);
}

void CapturePipeline::rethrowFailure() {
    if (error_) std::rethrow_exception(error_);
}

void CapturePipeline::submit(std::vector<Task> parallel, std::vector<Task> ordered) {
    const long index = submitted_++;
    if (workers_.empty()) {
        // Synchronous: as the capture ran before the pipeline, task by task.
        for (const std::vector<Task>* tasks : {&parallel, &ordered})
            for (const Task& t : *tasks) {
                std::unique_lock lock(mutex_, std::defer_lock);
                if (!runTask(t, index, lock)) rethrowFailure();
            }
        return;
    }
    std::unique_lock lock(mutex_);
    waitFor([this] { return error_ || frames_.size() < framesInFlight_; }, lock);
    rethrowFailure();
    frames_.push_back({index, std::move(parallel), std::move(ordered), 0, 0});
    changed_.notify_all();
}

void CapturePipeline::drain() {
    std::unique_lock lock(mutex_);
    waitFor([this] { return frames_.empty(); }, lock);
    rethrowFailure();
}

} // namespace fl::app
