#pragma once
// Per-pass GPU timing: GL timer queries where the driver supports them, glFinish wall time on
// software rasterisers (llvmpipe reads 0 for compute dispatches).

#include <gpu/Gl.h>

#include <chrono>
#include <string>
#include <vector>

namespace fl::gl {

struct PassTime {
    std::string name;
    double ms = 0.0;
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
    /// Waits for the GPU, resolves every pass and the frame's total wall time.
    void endFrame();
    [[nodiscard]] const std::vector<PassTime>& passes() const { return results_; }
    [[nodiscard]] double frameMs() const { return frameMs_; }
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
};

} // namespace fl::gl
