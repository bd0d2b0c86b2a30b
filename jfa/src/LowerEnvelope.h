#pragma once
// The exact squared distance transform along one axis (lower envelope of parabolas, integer
// arithmetic). Both exact references are separable and build on it: exactIntegerEdt (2D,
// Reference.cpp) runs it along columns then rows, exactSquaredDistances3d (Jfa3d.cpp) along x, y
// and z. Private to floodlight_jfa.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>

namespace fl::jfa::detail {

/// Squared distance of an element no site reaches (yet): beats no real distance and stays far
/// from overflow when a line adds (x - q)^2 to it.
inline constexpr std::int64_t kFarSquared = std::numeric_limits<std::int64_t>::max() / 4;

/// Transforms `lines` lines of `dist` in place: line i has n elements `stride` apart from
/// dist[lineStart(i)], and each becomes d[x] = min over q of (x - q)^2 + d[q], taken over the q
/// with d[q] < kFarSquared (kFarSquared if there is none). If `nearest` is given, the same
/// positions of it receive the minimizing q (-1 if none; on ties one of them). Lines are split
/// among `threads` threads (0 = all hardware threads); results do not depend on the split.
void transformLines(std::int64_t* dist, int* nearest, std::size_t lines, int n, std::size_t stride,
                    const std::function<std::size_t(std::size_t)>& lineStart, int threads);

} // namespace fl::jfa::detail
