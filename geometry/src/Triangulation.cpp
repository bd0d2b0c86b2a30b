#include <geometry/Triangulation.h>

#include <geometry/detail/TriangulationFlip.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace fl::geom {
namespace {

std::uint64_t edgeKey(std::uint32_t from, std::uint32_t to) {
    return (std::uint64_t{from} << 32) | to;
}

} // namespace

void buildHalfedges(Triangulation& mesh) {
    const auto& tris = mesh.triangles;
    if (tris.size() % 3 != 0)
        throw std::invalid_argument("buildHalfedges: triangles holds " +
                                    std::to_string(tris.size()) + " indices, not a multiple of 3");
    if (tris.size() >= kNoHalfedge)
        throw std::invalid_argument("buildHalfedges: too many triangles for 32-bit halfedges");
    for (std::size_t t = 0; t < tris.size() / 3; ++t) {
        const std::uint32_t i = tris[3 * t], j = tris[3 * t + 1], k = tris[3 * t + 2];
        for (const std::uint32_t v : {i, j, k})
            if (v >= mesh.points.size())
                throw std::invalid_argument("buildHalfedges: triangle " + std::to_string(t) +
                                            " uses vertex " + std::to_string(v) +
                                            " but there are " + std::to_string(mesh.points.size()) +
                                            " points");
        if (i == j || j == k || k == i)
            throw std::invalid_argument("buildHalfedges: triangle " + std::to_string(t) +
                                        " repeats a vertex (" + std::to_string(i) + ", " +
                                        std::to_string(j) + ", " + std::to_string(k) + ")");
    }

    // Sorting the directed edges finds both duplicates and opposites in O(n log n).
    std::vector<std::pair<std::uint64_t, std::uint32_t>> directed(tris.size());
    for (std::uint32_t e = 0; e < tris.size(); ++e)
        directed[e] = {edgeKey(tris[e], tris[nextHalfedge(e)]), e};
    std::sort(directed.begin(), directed.end());
    for (std::size_t i = 1; i < directed.size(); ++i)
        if (directed[i].first == directed[i - 1].first) {
            const std::uint32_t e0 = directed[i - 1].second, e1 = directed[i].second;
            throw std::invalid_argument(
                "buildHalfedges: non-manifold mesh: directed edge " + std::to_string(tris[e0]) +
                " -> " + std::to_string(tris[nextHalfedge(e0)]) + " occurs in triangles " +
                std::to_string(e0 / 3) + " and " + std::to_string(e1 / 3) +
                " (an edge with more than two triangles, or neighbours of opposite orientation)");
        }

    mesh.halfedges.assign(tris.size(), kNoHalfedge);
    for (std::uint32_t e = 0; e < tris.size(); ++e) {
        const std::uint64_t reverse = edgeKey(tris[nextHalfedge(e)], tris[e]);
        const auto it = std::lower_bound(directed.begin(), directed.end(),
                                         std::pair<std::uint64_t, std::uint32_t>{reverse, 0});
        if (it != directed.end() && it->first == reverse) mesh.halfedges[e] = it->second;
    }
}

std::size_t legalize(Triangulation& mesh) {
    if (mesh.halfedges.size() != mesh.triangles.size()) buildHalfedges(mesh);
    auto& tris = mesh.triangles;
    auto& half = mesh.halfedges;

    // Each flip removes an edge between two points that can never come back (the lifted surface
    // only goes down), so a valid mesh needs at most one flip per pair of points.
    const std::size_t n = mesh.points.size();
    const std::size_t flipLimit = n < 2 ? 0 : n * (n - 1) / 2;

    std::vector<std::uint32_t> pending;
    for (std::uint32_t e = 0; e < half.size(); ++e)
        if (half[e] != kNoHalfedge && e < half[e]) pending.push_back(e);

    std::size_t flips = 0;
    const auto noBoundaryTracking = [](std::uint32_t) {};
    while (!pending.empty()) {
        const std::uint32_t e = pending.back();
        pending.pop_back();
        // A stale entry simply tests whatever edge slot e holds now.
        if (half[e] == kNoHalfedge || !detail::shouldFlip(mesh.points, tris, half, e)) continue;
        const std::uint32_t o = half[e];
        detail::flip(tris, half, e, noBoundaryTracking);
        if (++flips > flipLimit)
            throw std::runtime_error("legalize: more than n(n-1)/2 = " + std::to_string(flipLimit) +
                                     " flips; the mesh is not a valid triangulation");
        pending.insert(pending.end(), {e, prevHalfedge(e), o, prevHalfedge(o)});
    }
    return flips;
}

} // namespace fl::geom
