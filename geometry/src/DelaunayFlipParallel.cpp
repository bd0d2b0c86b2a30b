// Step C4 on several threads (issue 31): the points are cut into one strip per thread as C3's
// (stripOf), and a triangle belongs to a strip when its three vertices lie in it; the others
// are frozen. Each thread runs the sequential C4's Lawson flips over the edges of its own
// triangles, but flips an edge only between two of them. Race-free for C3's reason
// (DelaunayInsertParallel.cpp): a flip of two of a thread's triangles gives two triangles of the
// same four vertices, so ownership never changes; a triangle next to one of a thread's shares
// two of its vertices, so it is the thread's or frozen, and frozen triangles are not written;
// halfedge entries are written only for edges with both ends in the writer's strip.
//
// Why the sequential flips can start from a short list: after the threads, an edge with one of
// a thread's triangles on a side was tested after the last flip that touched it (a flip
// re-tests the four edges around it), so it is locally Delaunay unless it was left in the list;
// the edges between two frozen triangles were never tested and go in the list too. Lawson's
// algorithm from the list then ends with every edge locally Delaunay: the Delaunay
// triangulation, the same triangles as the sequential C4 wherever they are unique
// (tests: delaunay_parallel_test, ParallelC4*).
#include "DelaunaySteps.h"

#include "TriangulationFlip.h"

#include <base/Parallel.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace fl::geom::detail {

namespace {

// Marks a triangle with vertices in more than one strip (strips are < 255).
constexpr std::uint8_t kFrozenTriangle = 255;

// Every 16th point: enough for the strips' quantiles, without an index per point at C4's peak.
constexpr std::uint32_t kStripSample = 16;

// The strip owning each triangle (all three vertices in it), or kFrozenTriangle.
std::vector<std::uint8_t> triangleOwners(const WorkMesh& mesh,
                                         const std::vector<std::uint8_t>& strip, int threads) {
    const std::size_t count = mesh.triangles.size() / 3;
    std::vector<std::uint8_t> owner(count);
    parallelRows(int(count), threads, [&](int begin, int end, int) {
        for (auto t = std::size_t(begin); t < std::size_t(end); ++t) {
            const std::uint32_t* tri = &mesh.triangles[3 * t];
            const std::uint8_t s = strip[tri[0]];
            owner[t] = strip[tri[1]] == s && strip[tri[2]] == s ? s : kFrozenTriangle;
        }
    });
    return owner;
}

// One strip's flips: Lawson's algorithm over the edges of its triangles, each edge tested from
// its lower halfedge (or from this side, across to a frozen triangle); a failing edge to a frozen
// triangle goes to `left`. Returns the number of flips.
std::size_t flipStrip(WorkMesh& mesh, const std::vector<std::uint8_t>& owner, std::uint8_t k,
                      std::size_t limit, std::vector<std::uint32_t>& left) {
    auto& tris = mesh.triangles;
    auto& half = mesh.halfedges;
    const auto noBoundaryTracking = [](std::uint32_t) {};
    std::vector<std::uint32_t> stack;
    std::size_t flips = 0;
    for (std::uint32_t t = 0; t < owner.size(); ++t) {
        if (owner[t] != k) continue;
        for (std::uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
            const std::uint32_t twin = half[e];
            if (twin == kNoHalfedge || (twin < e && owner[twin / 3] == k)) continue;
            stack.push_back(e);
            while (!stack.empty()) {
                const std::uint32_t h = stack.back();
                stack.pop_back();
                const std::uint32_t o = half[h];
                if (o == kNoHalfedge || !shouldFlip(mesh.points, tris, half, h)) continue;
                if (owner[o / 3] != k) {
                    left.push_back(h);
                    continue;
                }
                flip(tris, half, h, noBoundaryTracking);
                if (++flips > limit)
                    throw std::runtime_error(
                        "delaunay: more than n(n-1)/2 = " + std::to_string(limit) +
                        " flips; the mesh is not a triangulation");
                stack.insert(stack.end(), {h, prevHalfedge(h), o, prevHalfedge(o)});
            }
        }
    }
    return flips;
}

} // namespace

std::vector<std::uint32_t> flipInStrips(WorkMesh& mesh, int threads, std::size_t& flips) {
    const std::size_t count = mesh.triangles.size() / 3;
    const int strips = std::min(bandCount(int(std::min<std::size_t>(count, 1u << 30)), threads),
                                int(kFrozenTriangle) - 1);
    std::vector<std::uint32_t> sample;
    for (std::uint32_t v = 0; v < mesh.points.size(); v += kStripSample)
        if (mesh.inMesh(v)) sample.push_back(v);
    if (sample.empty()) return {};
    std::vector<std::uint8_t> owner;
    {
        const std::vector<std::uint8_t> strip = stripOf(mesh, sample, strips);
        owner = triangleOwners(mesh, strip, threads);
    }
    std::vector<std::vector<std::uint32_t>> left(static_cast<std::size_t>(strips));
    std::vector<std::size_t> made(static_cast<std::size_t>(strips), 0);
    const std::size_t limit = mesh.flipLimit();
    parallelRows(strips, threads, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k)
            made[std::size_t(k)] =
                flipStrip(mesh, owner, std::uint8_t(k), limit, left[std::size_t(k)]);
    });
    std::vector<std::uint32_t> rest;
    for (int k = 0; k < strips; ++k) {
        flips += made[std::size_t(k)];
        rest.insert(rest.end(), left[std::size_t(k)].begin(), left[std::size_t(k)].end());
    }
    // The edges between two frozen triangles, each once.
    for (std::uint32_t t = 0; t < count; ++t) {
        if (owner[t] != kFrozenTriangle) continue;
        for (std::uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
            const std::uint32_t twin = mesh.halfedges[e];
            if (twin != kNoHalfedge && twin > e && owner[twin / 3] == kFrozenTriangle)
                rest.push_back(e);
        }
    }
    return rest;
}

std::size_t flipToDelaunay(WorkMesh& mesh, int threads) {
    // Below some ten thousand points a thread costs more than it saves.
    if (bandCount(2, threads) < 2 || mesh.triangles.size() / 3 < kMinParallelFlip)
        return mesh.makeDelaunay();
    std::size_t flips = 0;
    const std::vector<std::uint32_t> rest = flipInStrips(mesh, threads, flips);
    return mesh.flipFrom(rest, flips);
}

} // namespace fl::geom::detail
