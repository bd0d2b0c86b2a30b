#include "LowerEnvelope.h"

#include <base/Parallel.h>

#include <algorithm>
#include <vector>

namespace fl::jfa::detail {

namespace {

// Ceil(n / d) for d > 0.
std::int64_t ceilDiv(std::int64_t n, std::int64_t d) {
    return n >= 0 ? (n + d - 1) / d : -((-n) / d);
}

// One line: d[x] = min_q (x - q)^2 + f[q] over q with f[q] < kFarSquared, arg[x] = that q. v
// holds the envelope's parabolas, from[j] the first x where v[j] is minimal.
void envelope1d(const std::int64_t* f, int n, std::int64_t* d, int* arg, int* v,
                std::int64_t* from) {
    int k = -1;
    for (int q = 0; q < n; ++q) {
        if (f[q] >= kFarSquared) continue;
        const std::int64_t fq = f[q] + std::int64_t(q) * q;
        std::int64_t start = 0;
        while (k >= 0) {
            const int p = v[k];
            // q is at most p from ceil(...) on.
            start = ceilDiv(fq - (f[p] + std::int64_t(p) * p), 2 * std::int64_t(q - p));
            if (start > from[k]) break;
            --k;
        }
        if (k < 0) start = 0;
        if (start >= n) continue; // q is never the minimum inside the line
        ++k;
        v[k] = q;
        from[k] = start;
    }
    if (k < 0) {
        std::fill(d, d + n, kFarSquared);
        std::fill(arg, arg + n, -1);
        return;
    }
    int j = 0;
    for (int x = 0; x < n; ++x) {
        while (j < k && from[j + 1] <= x) ++j;
        const std::int64_t dx = x - v[j];
        d[x] = dx * dx + f[v[j]];
        arg[x] = v[j];
    }
}

} // namespace

void transformLines(std::int64_t* dist, int* nearest, std::size_t lines, int n, std::size_t stride,
                    const std::function<std::size_t(std::size_t)>& lineStart, int threads) {
    const auto count = static_cast<std::size_t>(n);
    fl::parallelRows(static_cast<int>(lines), threads, [&](int begin, int end, int) {
        std::vector<std::int64_t> f(count), d(count), from(count);
        std::vector<int> arg(count), v(count);
        for (int i = begin; i < end; ++i) {
            const std::size_t start = lineStart(std::size_t(i));
            for (std::size_t x = 0; x < count; ++x) f[x] = dist[start + x * stride];
            envelope1d(f.data(), n, d.data(), arg.data(), v.data(), from.data());
            for (std::size_t x = 0; x < count; ++x) dist[start + x * stride] = d[x];
            if (nearest != nullptr) {
                for (std::size_t x = 0; x < count; ++x) nearest[start + x * stride] = arg[x];
            }
        }
    });
}

} // namespace fl::jfa::detail
