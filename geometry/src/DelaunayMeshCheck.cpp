// WorkMesh: adjacency from a triangle list, and the O(n) check of the degree argument
// (DelaunayMesh.h) that certifies the mesh C1 hands to C2.
#include <geometry/detail/DelaunayMesh.h>

#include <geometry/detail/TriangulationFlip.h>

#include <jfa/CpuKernel.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <utility>

namespace fl::geom::detail {

using glm::dvec2;

namespace {

// One vertex a's triangles ("its star"), entry i being the triangle (a, b_i, c_i) with outgoing
// halfedge a -> b_i and incoming halfedge c_i -> a. The triangle clockwise of i (across a-b_i)
// is the entry j with c_j == b_i, and then the twin of a -> b_i is c_j -> a. The star is sound
// when every entry has at most one such j, no j serves two entries (else an edge has three
// triangles or a directed edge repeats), and the entries form a single fan (one cycle, or one
// path: else a is a pinch point). Both functions link the twins and return the most clockwise
// entry (the boundary one, if any), or kNoHalfedge if the star is not sound. Each star writes
// only its own outgoing halfedges' twins, so stars can be processed in parallel; when all are
// sound, b's star pairs b -> a with a -> b exactly as a's star pairs them the other way.

// Up to 32 triangles (all but extreme vertices): bit masks, no branches in the inner loop.
constexpr std::size_t kSmallStar = 32;

std::uint32_t smallStar(const std::vector<std::uint32_t>& tris, std::vector<std::uint32_t>& half,
                        const std::uint32_t* entries, std::size_t k) {
    std::uint32_t b[kSmallStar], c[kSmallStar], cw[kSmallStar], ccw[kSmallStar];
    for (std::size_t i = 0; i < k; ++i) {
        b[i] = tris[nextHalfedge(entries[i])];
        c[i] = tris[prevHalfedge(entries[i])];
    }
    std::uint32_t matched = 0, start = 0, open = 0;
    for (std::size_t i = 0; i < k; ++i) {
        std::uint32_t mask = 0;
        for (std::size_t j = 0; j < k; ++j) mask |= std::uint32_t(c[j] == b[i]) << j;
        if (mask == 0) {
            cw[i] = kNoHalfedge;
            start = std::uint32_t(i);
            ++open;
            continue;
        }
        const auto j = static_cast<std::uint32_t>(std::countr_zero(mask));
        if ((mask & (mask - 1)) != 0 || (matched >> j & 1u) != 0) return kNoHalfedge;
        matched |= 1u << j;
        cw[i] = j;
        ccw[j] = std::uint32_t(i);
    }
    if (open > 1) return kNoHalfedge;
    std::size_t seen = 1;
    for (std::uint32_t i = start; (matched >> i & 1u) != 0;) {
        i = ccw[i];
        if (i == start) break;
        if (++seen > k) return kNoHalfedge;
    }
    if (seen != k) return kNoHalfedge;
    for (std::size_t i = 0; i < k; ++i)
        if (cw[i] != kNoHalfedge) half[entries[i]] = prevHalfedge(entries[cw[i]]);
    return start;
}

// Any number of triangles (a circle's centre): sorting instead of comparing all pairs.
std::uint32_t largeStar(const std::vector<std::uint32_t>& tris, std::vector<std::uint32_t>& half,
                        const std::uint32_t* entries, std::size_t k) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> byC(k); // (c_j, j)
    for (std::size_t j = 0; j < k; ++j) byC[j] = {tris[prevHalfedge(entries[j])], std::uint32_t(j)};
    std::sort(byC.begin(), byC.end());
    std::vector<std::uint32_t> cw(k, kNoHalfedge), ccw(k, kNoHalfedge);
    std::uint32_t start = 0, open = 0;
    for (std::size_t i = 0; i < k; ++i) {
        const std::uint32_t b = tris[nextHalfedge(entries[i])];
        auto it =
            std::lower_bound(byC.begin(), byC.end(), std::pair<std::uint32_t, std::uint32_t>{b, 0});
        if (it == byC.end() || it->first != b) {
            start = std::uint32_t(i);
            ++open;
            continue;
        }
        const std::uint32_t j = it->second;
        if ((++it != byC.end() && it->first == b) || ccw[j] != kNoHalfedge) return kNoHalfedge;
        cw[i] = j;
        ccw[j] = std::uint32_t(i);
    }
    if (open > 1) return kNoHalfedge;
    std::size_t seen = 1;
    for (std::uint32_t i = ccw[start]; i != kNoHalfedge && i != start; i = ccw[i])
        if (++seen > k) return kNoHalfedge;
    if (seen != k) return kNoHalfedge;
    for (std::size_t i = 0; i < k; ++i)
        if (cw[i] != kNoHalfedge) half[entries[i]] = prevHalfedge(entries[cw[i]]);
    return start;
}

} // namespace

bool WorkMesh::setTriangles(std::vector<std::uint32_t> tris) {
    triangles = std::move(tris);
    freeSlots_.clear();
    pending_.clear();
    lastTriangle_ = 0;
    const std::size_t n = points.size();
    const auto count = static_cast<std::uint32_t>(triangles.size());
    // Outgoing halfedges grouped by start vertex (a counting sort). Each vertex then pairs its
    // own outgoing and incoming halfedges: every edge at a vertex is found among that vertex's
    // few triangles, read from one short run of memory.
    std::vector<std::uint32_t> first(n + 1, 0);
    for (const std::uint32_t v : triangles) ++first[v + 1];
    for (std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
    std::vector<std::uint32_t> out(count);
    {
        std::vector<std::uint32_t> cursor(first.begin(), first.end() - 1);
        for (std::uint32_t e = 0; e < count; ++e) out[cursor[triangles[e]]++] = e;
    }
    halfedges.assign(count, kNoHalfedge);
    vertexEdge.assign(n, kNoHalfedge);
    std::atomic<bool> sound = true;
    jfa::parallelRows(int(n), threads_, [&](int begin, int end, int) {
        for (auto a = std::uint32_t(begin); a < std::uint32_t(end); ++a) {
            const std::uint32_t* entries = out.data() + first[a];
            const std::size_t k = first[a + 1] - first[a];
            if (k == 0) continue;
            const std::uint32_t start = k <= kSmallStar
                                            ? smallStar(triangles, halfedges, entries, k)
                                            : largeStar(triangles, halfedges, entries, k);
            if (start == kNoHalfedge) {
                sound = false; // overlapping or pinched triangles
                return;
            }
            vertexEdge[a] = entries[start];
        }
    });
    return sound;
}

bool WorkMesh::flipFlatTriangles() {
    const auto noBoundaryTracking = [](std::uint32_t) {};
    for (std::uint32_t t = 0; 3 * t < triangles.size(); ++t) {
        const std::uint32_t e0 = 3 * t;
        if (fastOrientSign(points[triangles[e0]], points[triangles[e0 + 1]],
                           points[triangles[e0 + 2]]) != 0)
            continue;
        std::uint32_t e = kNoHalfedge;
        for (std::uint32_t k = e0; k < e0 + 3; ++k)
            if (strictlyBetween(points[triangles[k]], points[triangles[prevHalfedge(k)]],
                                points[triangles[nextHalfedge(k)]]))
                e = k;
        if (e == kNoHalfedge || halfedges[e] == kNoHalfedge) return false;
        const std::uint32_t o = halfedges[e];
        flip(triangles, halfedges, e, noBoundaryTracking);
        for (const std::uint32_t h : {e, o})
            if (fastOrientSign(points[triangles[h]], points[triangles[nextHalfedge(h)]],
                               points[triangles[prevHalfedge(h)]]) <= 0)
                return false;
        touch(e / 3);
        touch(o / 3);
    }
    return true;
}

bool WorkMesh::isTriangulation(std::size_t required) const {
    if (!freeSlots_.empty() || triangles.empty() || halfedges.size() != triangles.size())
        return false;
    const auto count = static_cast<std::uint32_t>(triangles.size());
    std::atomic<bool> positive = true;
    jfa::parallelRows(int(count / 3), threads_, [&](int begin, int end, int) {
        for (auto e = 3 * std::uint32_t(begin); e < 3 * std::uint32_t(end) && positive; e += 3)
            if (fastOrientSign(points[triangles[e]], points[triangles[e + 1]],
                               points[triangles[e + 2]]) <= 0)
                positive = false;
    });
    if (!positive) return false;
    std::size_t used = 0;
    for (std::size_t v = 0; v < points.size(); ++v)
        if (vertexEdge[v] != kNoHalfedge) ++used;
    for (std::size_t v = 0; v < required; ++v)
        if (vertexEdge[v] == kNoHalfedge) return false;
    std::size_t boundary = 0;
    std::uint32_t someBoundary = kNoHalfedge;
    for (std::uint32_t e = 0; e < count; ++e)
        if (halfedges[e] == kNoHalfedge) {
            ++boundary;
            someBoundary = e;
        }
    // A disk: V - E + F = 1 with E = (3F + B) / 2, and (below) a single boundary cycle.
    const std::size_t faces = count / 3;
    if ((count + boundary) % 2 != 0 || someBoundary == kNoHalfedge) return false;
    if (used + faces != (count + boundary) / 2 + 1) return false;
    // The boundary cycle: all turns convex (left, or straight on), and it turns around once. With
    // every turn in [0, pi) the edge direction passes from the lower to the upper half-plane
    // exactly once per revolution; both are decided by exact comparisons.
    const auto upper = [&](std::uint32_t e) {
        const dvec2 a = points[triangles[e]], b = points[triangles[nextHalfedge(e)]];
        return b.y > a.y || (b.y == a.y && b.x > a.x);
    };
    std::size_t length = 0, revolutions = 0;
    std::uint32_t e = someBoundary;
    do {
        const std::uint32_t next = nextBoundary(e);
        if (!convexTurn(points[triangles[e]], points[triangles[next]],
                        points[triangles[nextHalfedge(next)]]))
            return false;
        if (!upper(e) && upper(next)) ++revolutions;
        e = next;
        if (++length > boundary) return false;
    } while (e != someBoundary);
    return length == boundary && revolutions == 1;
}

} // namespace fl::geom::detail
