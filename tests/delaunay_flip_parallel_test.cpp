// Step C4 on several threads (geometry/src/DelaunayFlipParallel.cpp, issue 31): the threads test
// every edge (failingEdges), one thread flips from the failing ones. Each mesh test starts from a
// valid triangulation far from Delaunay (delaunayReference's, scrambled by random legal flips), so
// a large share of the edges fail and a test cannot pass with the threads' lists lost or cut
// short; the result must be the Delaunay triangulation: the same triangle set as one thread where
// it is unique, the same count and a passing exact check where it is not (co-circular grids).
// 3 and 4 threads (more than the cores here) put more band borders in the slots.
#include <geometry/Delaunay.h>
#include <geometry/Predicates.h>
#include <geometry/Triangulation.h>

#include <jfa/Sites.h>

#include <geometry/detail/DelaunayMesh.h>
#include <geometry/detail/DelaunaySteps.h>
#include <geometry/detail/TriangulationFlip.h>

#include "TriangleSet.h"

#include <gtest/gtest.h>

#include <vector>

namespace fl::geom {
namespace {

using detail::WorkMesh;
using glm::dvec2;
using test::triangleSet;

// delaunayReference's triangulation of `points` with `rounds` x (edges) random flips of strictly
// convex quads: a valid triangulation with most edges no longer locally Delaunay.
WorkMesh scrambledMesh(const std::vector<dvec2>& points, int rounds, std::uint64_t seed) {
    const Triangulation dt = delaunayReference(points);
    WorkMesh mesh(points);
    EXPECT_TRUE(mesh.setTriangles(dt.triangles));
    jfa::SplitMix64 rng(seed);
    const auto noBoundaryTracking = [](std::uint32_t) {};
    const std::size_t edges = mesh.halfedges.size();
    for (std::size_t i = 0; i < std::size_t(rounds) * edges; ++i) {
        const auto e = static_cast<std::uint32_t>(rng.unit() * double(edges)) % edges;
        const std::uint32_t o = mesh.halfedges[e];
        if (o == kNoHalfedge) continue;
        const dvec2 p0 = points[mesh.triangles[e]];
        const dvec2 p1 = points[mesh.triangles[nextHalfedge(e)]];
        const dvec2 a = points[mesh.triangles[prevHalfedge(e)]];
        const dvec2 b = points[mesh.triangles[prevHalfedge(o)]];
        if (orient2dSign(p0, b, a) > 0 && orient2dSign(p1, a, b) > 0)
            detail::flip(mesh.triangles, mesh.halfedges, e, noBoundaryTracking);
    }
    return mesh;
}

Triangulation asTriangulation(const WorkMesh& mesh) {
    return {mesh.points, mesh.triangles, mesh.halfedges};
}

// C4 on one thread and on 2..4; `unique`: the triangle sets must be equal.
void expectThreadsMatchOneThread(const std::vector<dvec2>& points, bool unique) {
    WorkMesh one = scrambledMesh(points, 2, 5);
    ASSERT_GE(one.triangles.size() / 3, detail::kMinParallelFlip);
    const std::vector<std::uint32_t> oneFailing = detail::failingEdges(one, 1);
    ASSERT_GT(oneFailing.size(), one.triangles.size() / 3 / 8) << "nearly Delaunay already";
    detail::flipToDelaunay(one, 1);
    const TriangulationReport oneReport = checkTriangulation(asTriangulation(one));
    ASSERT_TRUE(oneReport.ok()) << oneReport.summary();
    for (const int threads : {2, 3, 4}) {
        WorkMesh many = scrambledMesh(points, 2, 5);
        // Every band's failing edges, none twice, in ascending order.
        EXPECT_EQ(detail::failingEdges(many, threads), oneFailing) << threads << " threads";
        detail::flipToDelaunay(many, threads);
        const TriangulationReport report = checkTriangulation(asTriangulation(many));
        ASSERT_TRUE(report.ok()) << threads << " threads: " << report.summary();
        EXPECT_EQ(many.triangles.size(), one.triangles.size()) << threads << " threads";
        if (unique) {
            EXPECT_EQ(triangleSet(many.triangles), triangleSet(one.triangles))
                << threads << " threads";
        }
    }
}

TEST(ParallelC4, UniformPointsMatchOneThread) {
    jfa::SplitMix64 rng(21);
    std::vector<dvec2> pts(40000);
    for (dvec2& p : pts) p = dvec2(rng.unit(), rng.unit());
    expectThreadsMatchOneThread(pts, true);
}

// A grid: every cell's four corners are co-circular, so many Delaunay triangulations exist and
// the threads' flips may pick any of them.
TEST(ParallelC4, CoCircularGridMatchesOneThreadInCount) {
    std::vector<dvec2> pts;
    for (int y = 0; y < 150; ++y)
        for (int x = 0; x < 250; ++x) pts.emplace_back(double(x), double(y));
    expectThreadsMatchOneThread(pts, false);
}

// Most edges failing at once, many of them next to each other across the bands' borders: a
// mesh scrambled four times over, in a thin band of points (long, thin triangles).
TEST(ParallelC4, HeavilyScrambledThinBandMatchesOneThread) {
    jfa::SplitMix64 rng(8);
    std::vector<dvec2> pts(40000);
    for (dvec2& p : pts) p = dvec2(rng.unit() * 100.0, rng.unit());
    WorkMesh one = scrambledMesh(pts, 4, 9);
    detail::flipToDelaunay(one, 1);
    WorkMesh two = scrambledMesh(pts, 4, 9);
    ASSERT_GT(detail::failingEdges(two, 2).size(), two.triangles.size() / 3 / 8);
    detail::flipToDelaunay(two, 2);
    const TriangulationReport report = checkTriangulation(asTriangulation(two));
    ASSERT_TRUE(report.ok()) << report.summary();
    EXPECT_EQ(triangleSet(two.triangles), triangleSet(one.triangles));
}

// The whole pipeline on enough points for C4's threads (more than kMinParallelFlip triangles):
// the same triangles on 1 and 2 threads.
TEST(ParallelC4, PipelineOnTwoThreadsMatchesOneThread) {
    jfa::SplitMix64 rng(4);
    std::vector<dvec2> pts(40000);
    for (dvec2& p : pts) p = dvec2(rng.unit(), rng.unit()) * 3.0;
    DelaunayOptions options;
    options.discrete.size = 128;
    options.check = true; // throws if the result is not a Delaunay triangulation
    options.discrete.threads = 1;
    const DelaunayResult one = delaunay(pts, options);
    options.discrete.threads = 2;
    const DelaunayResult two = delaunay(pts, options);
    ASSERT_GE(two.mesh.triangleCount(), detail::kMinParallelFlip);
    EXPECT_EQ(triangleSet(two.mesh.triangles), triangleSet(one.mesh.triangles));
}

} // namespace
} // namespace fl::geom
