#pragma once
// Order statistics of timing series (benchmarks, capture and compare runs).

#include <algorithm>
#include <vector>

namespace fl {

/// The median of `v` (mean of the two middle values for an even count); 0 for an empty series.
inline double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// The smallest value of `v`; 0 for an empty series.
inline double minimum(const std::vector<double>& v) {
    return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end());
}

} // namespace fl
