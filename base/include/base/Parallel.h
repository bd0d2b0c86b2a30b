#pragma once
// Thread fan-out over rows: the one way Floodlight's CPU code splits work among threads.

#include <functional>

namespace fl {

/// Resolves a thread count: 0 -> hardware_concurrency() (at least 1); negative throws
/// std::invalid_argument.
int resolveThreads(int threads);

/// Number of row bands a pass over `rows` rows uses: min(resolveThreads(threads), rows), >= 1.
int bandCount(int rows, int threads);

/// Runs body(rowBegin, rowEnd, band) over rows [0, rows) split into bandCount(rows, threads)
/// contiguous bands, each on its own thread (band 0 on the caller's); rethrows the first exception.
void parallelRows(int rows, int threads, const std::function<void(int, int, int)>& body);

} // namespace fl
