#pragma once
// Per-pass GPU timing: GL timer queries where the driver supports them, glFinish wall time on
// software rasterisers (llvmpipe reads 0 for compute dispatches).

#include <gpu/Gl.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace fl::gl {

struct PassTime {
    std::string name;
    double ms = 0.0;
    /// Bytes of render targets and images the pass said it wrote (PassTimer::wrote): computed
    /// from the targets' formats and the texels written, not measured.
    std::int64_t bytes = 0;
};

enum class TimingMode { Auto, Query, Finish };

class PassTimer {
  public:
    /// Auto picks Finish on software renderers, Query elsewhere (needs a current context).
    explicit PassTimer(TimingMode mode = TimingMode::Auto);
    /// Starts a frame: clears the previous frame's results.
    void beginFrame();
    /// Brackets one pass; passes must not nest.
    void begin(const char* name);
    void end();
    /// Adds `bytes` written (render targets, images) to the open pass; throws std::logic_error
    /// outside begin()/end(). A pass that writes every texel of a target adds
    /// gl::textureBytes(target).
    void wrote(std::int64_t bytes);
    /// Waits for the GPU, resolves every pass and the frame's total wall time.
    void endFrame();
    [[nodiscard]] const std::vector<PassTime>& passes() const { return results_; }
    [[nodiscard]] double frameMs() const { return frameMs_; }
    /// The bytes every pass of the frame wrote, summed.
    [[nodiscard]] std::int64_t frameBytes() const;
    [[nodiscard]] TimingMode mode() const { return mode_; }
    /// "query" or "finish".
    [[nodiscard]] const char* modeName() const;

  private:
    using Clock = std::chrono::steady_clock;
    TimingMode mode_;
    std::vector<Query> queries_; // grows to the most passes a frame has used
    std::vector<PassTime> results_;
    Clock::time_point frameStart_{}, passStart_{};
    double frameMs_ = 0.0;
    bool open_ = false; // between begin() and end()
};

/// One pass of a timer that may be absent (a method's `in.timer`): begins at construction, ends
/// at end() or at the end of its scope, and adds the bytes the pass wrote; without a timer it
/// does nothing. What the `if (timer)` guards around begin(), wrote() and end() did, once.
class TimedPass {
  public:
    TimedPass(PassTimer* timer, const char* name) : timer_(timer) {
        if (timer_) timer_->begin(name);
    }
    ~TimedPass() { end(); }
    TimedPass(const TimedPass&) = delete;
    TimedPass& operator=(const TimedPass&) = delete;
    /// PassTimer::wrote on the open pass.
    void wrote(std::int64_t bytes) const {
        if (timer_) timer_->wrote(bytes);
    }
    /// Ends the pass now; later calls, and the destructor, do nothing.
    void end() {
        if (timer_) timer_->end();
        timer_ = nullptr;
    }

  private:
    PassTimer* timer_;
};

} // namespace fl::gl
