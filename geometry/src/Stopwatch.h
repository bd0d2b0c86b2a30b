#pragma once
// Wall-clock lap times for the per-step timings the Delaunay pipelines report.

#include <chrono>

namespace fl::geom::detail {

class Stopwatch {
  public:
    /// Milliseconds since the last call (or construction).
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
        last_ = now;
        return ms;
    }

  private:
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

} // namespace fl::geom::detail
