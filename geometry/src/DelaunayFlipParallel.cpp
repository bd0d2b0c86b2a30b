// Step C4 on several threads. What C4 does at a million points (1M uniform, 256²,
// measured 2026-11-29): C3 inserts with Lawson flips, so C4 finds 7 failing edges among 3M and
// makes 23 flips; its 200 ms are the 3M exact incircle tests, not the flips. So the threads
// share the tests, which only read the mesh (no locks, no ownership), and the flips run on one
// thread from the edges that failed. Why that is Lawson's algorithm still: an edge that passed
// stays locally Delaunay until a flip changes one of its triangles, and every flip re-tests the
// four edges around it (WorkMesh::flipFrom), so the flips end with every edge locally Delaunay,
// the Delaunay triangulation: the same triangles as the one-thread C4 wherever they are unique
// (tests: delaunay_flip_parallel_test).
//
// Tried first and dropped: flipping in strips as C3 inserts (a thread flips only between two
// triangles with all vertices in its strip). With nearly nothing to flip it only added work:
// 35 ms to find each triangle's strip and 25 % more per test (the ownership look-ups).
#include <geometry/detail/DelaunaySteps.h>

#include <geometry/detail/TriangulationFlip.h>

#include <base/Parallel.h>

#include <algorithm>
#include <cstdint>

namespace fl::geom::detail {

std::vector<std::uint32_t> failingEdges(const WorkMesh& mesh, int threads) {
    const std::size_t count = mesh.triangles.size() / 3;
    const int bands = bandCount(int(std::min<std::size_t>(count, 1u << 30)), threads);
    std::vector<std::vector<std::uint32_t>> failing(static_cast<std::size_t>(bands));
    // Bands of triangles in slot order, so the bands' lists joined are in ascending order.
    parallelRows(int(count), threads, [&](int begin, int end, int band) {
        std::vector<std::uint32_t>& out = failing[std::size_t(band)];
        for (auto e = 3 * std::uint32_t(begin); e < 3 * std::uint32_t(end); ++e) {
            const std::uint32_t twin = mesh.halfedges[e];
            if (twin != kNoHalfedge && twin > e &&
                shouldFlip(mesh.points, mesh.triangles, mesh.halfedges, e))
                out.push_back(e);
        }
    });
    std::vector<std::uint32_t> all;
    for (const std::vector<std::uint32_t>& f : failing) all.insert(all.end(), f.begin(), f.end());
    return all;
}

std::size_t flipToDelaunay(WorkMesh& mesh, int threads) {
    // Below some thirty thousand points a thread costs more than it saves.
    if (bandCount(2, threads) < 2 || mesh.triangles.size() / 3 < kMinParallelFlip)
        return mesh.makeDelaunay();
    return mesh.flipFrom(failingEdges(mesh, threads), 0);
}

} // namespace fl::geom::detail
