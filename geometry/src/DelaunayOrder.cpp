// The insertion order of step C3: a biased randomized insertion order (BRIO, Amenta, Choi and
// Rote 2003) whose rounds are each sorted along a Hilbert curve (median splits, as CGAL's
// spatial_sort). Why: C3 inserts the missing sites one by one with a walk from the previous
// one, so consecutive sites must be close (Hilbert), and the rounds of doubling size keep the
// expected work of the incremental algorithm linear whatever the distribution: a plain
// left-to-right or per-pixel order made C3/C4 quadratic on clustered input (kuzmin: nearly all
// sites in one pixel) and on collinear input (two-lines: long cascades of flips).
#include <geometry/detail/DelaunaySteps.h>

#include <base/Parallel.h>

#include <algorithm>
#include <cstdint>

namespace fl::geom::detail {
namespace {

using glm::dvec2;

// Sorts the items themselves, not indices into the points: after the shuffle an index is a
// random access, and the median splits touch every item once per level.
struct HilbertSorter {
    using It = std::vector<OrderItem>::iterator;

    // Puts the median (by axis, ascending or not) in the middle; returns the middle.
    It split(It begin, It end, int axis, bool up) const {
        const It middle = begin + (end - begin) / 2;
        if (begin == end) return middle;
        std::nth_element(begin, middle, end, [&](const OrderItem& a, const OrderItem& b) {
            const double pa = a.p[axis], pb = b.p[axis];
            return up ? pa < pb : pa > pb;
        });
        return middle;
    }

    // The 2D Hilbert median sort: four quadrants by median splits, visited in curve order with
    // the sub-curves' orientations.
    void sort(It begin, It end, int x, bool upX, bool upY) const {
        if (end - begin <= 8) {
            // Tiny groups: order along the leading axis (consecutive enough for the walks).
            std::sort(begin, end, [&](const OrderItem& a, const OrderItem& b) {
                return upX ? a.p[x] < b.p[x] : a.p[x] > b.p[x];
            });
            return;
        }
        const int y = 1 - x;
        const It m2 = split(begin, end, x, upX);
        const It m1 = split(begin, m2, y, upY);
        const It m3 = split(m2, end, y, !upY);
        sort(begin, m1, y, upY, upX);
        sort(m1, m2, x, upX, upY);
        sort(m2, m3, x, upX, upY);
        sort(m3, end, y, !upY, !upX);
    }

    // One call of sort() (a range and its orientation), for the threads.
    struct Part {
        It begin, end;
        int x;
        bool upX, upY;
    };

    // sort()'s recursion down `depth` levels, the calls it would make there collected in `parts`
    // instead: sorting each part as sort() would gives the same order as one sort() call.
    void collect(It begin, It end, int x, bool upX, bool upY, int depth,
                 std::vector<Part>& parts) const {
        if (depth == 0 || end - begin <= 8) {
            parts.push_back({begin, end, x, upX, upY});
            return;
        }
        const int y = 1 - x;
        const It m2 = split(begin, end, x, upX);
        const It m1 = split(begin, m2, y, upY);
        const It m3 = split(m2, end, y, !upY);
        collect(begin, m1, y, upY, upX, depth - 1, parts);
        collect(m1, m2, x, upX, upY, depth - 1, parts);
        collect(m2, m3, x, upX, upY, depth - 1, parts);
        collect(m3, end, y, !upY, !upX, depth - 1, parts);
    }

    // sort() with its quadrants (4^depth parts, enough for every thread) on `threads` threads;
    // the order does not depend on the thread count.
    void sortParallel(It begin, It end, int threads) const {
        const int bands = bandCount(int(std::min<std::ptrdiff_t>(end - begin, 1 << 30)), threads);
        if (bands == 1 || end - begin < kMinParallelSort) {
            sort(begin, end, 0, true, true);
            return;
        }
        int depth = 1;
        while ((1 << (2 * depth)) < bands && depth < 4) ++depth;
        std::vector<Part> parts;
        collect(begin, end, 0, true, true, depth, parts);
        parallelRows(int(parts.size()), threads, [&](int first, int last, int) {
            for (int i = first; i < last; ++i) {
                const Part& p = parts[std::size_t(i)];
                sort(p.begin, p.end, p.x, p.upX, p.upY);
            }
        });
    }

    // Below this a round is sorted on the caller's thread (threads cost more than they save).
    static constexpr std::ptrdiff_t kMinParallelSort = 16384;
};

} // namespace

void insertionOrder(std::vector<OrderItem>& items, int threads) {
    // Deterministic shuffle (xorshift64), then rounds: the first quarter recursively, the rest
    // Hilbert-sorted, so round sizes grow geometrically.
    std::uint64_t state = 0x9e3779b97f4a7c15ull;
    for (std::size_t i = items.size(); i > 1; --i) {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        std::swap(items[i - 1], items[state % i]);
    }
    const HilbertSorter sorter;
    auto end = items.end();
    while (true) {
        const auto size = end - items.begin();
        const auto middle = items.begin() + (size < 256 ? 0 : size / 4);
        sorter.sortParallel(middle, end, threads);
        if (middle == items.begin()) break;
        end = middle;
    }
}

} // namespace fl::geom::detail
