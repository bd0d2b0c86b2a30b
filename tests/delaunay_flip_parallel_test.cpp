// Step C4 on several threads (geometry/src/DelaunayFlipParallel.cpp, issue 31). Each test starts
// from a valid triangulation far from Delaunay (delaunayReference's, scrambled by random legal
// flips), so most edges fail and the strips have real work; it then requires that the strips
// made most of the flips (so a test cannot pass on the sequential path alone) and that the result
// is the Delaunay triangulation: the same triangle set as one thread where it is unique, the same
// count and a passing exact check where it is not (co-circular grids). 3 and 4 strips (more than
// the cores here) put more triangles on the strips' borders.
#include <geometry/Delaunay.h>
#include <geometry/Predicates.h>
#include <geometry/Triangulation.h>

#include <jfa/Sites.h>

#include "../geometry/src/DelaunayMesh.h"
#include "../geometry/src/DelaunaySteps.h"
#include "../geometry/src/TriangulationFlip.h"

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

// C4 on one thread and with the strips on 2..4; `unique`: the triangle sets must be equal.
void expectStripsMatchOneThread(const std::vector<dvec2>& points, bool unique) {
    WorkMesh one = scrambledMesh(points, 2, 5);
    ASSERT_GE(one.triangles.size() / 3, detail::kMinParallelFlip);
    const std::size_t oneFlips = detail::flipToDelaunay(one, 1);
    ASSERT_GT(oneFlips, one.triangles.size() / 3 / 4) << "the scrambled mesh is nearly Delaunay";
    const TriangulationReport oneReport = checkTriangulation(asTriangulation(one));
    ASSERT_TRUE(oneReport.ok()) << oneReport.summary();
    for (const int threads : {2, 3, 4}) {
        WorkMesh many = scrambledMesh(points, 2, 5);
        std::size_t stripFlips = 0;
        const std::vector<std::uint32_t> rest = detail::flipInStrips(many, threads, stripFlips);
        const std::size_t flips = many.flipFrom(rest, stripFlips);
        // Most flips were the strips' (only those near their borders are left).
        EXPECT_GT(double(stripFlips), 0.75 * double(flips)) << threads << " threads";
        EXPECT_LT(double(rest.size()), 0.1 * double(many.triangles.size() / 3));
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
    expectStripsMatchOneThread(pts, true);
}

// A grid: every cell's four corners are co-circular, and whole columns of points lie exactly on
// the strips' cuts (a quantile of the x coordinates is one of them): the batch boundary case.
TEST(ParallelC4, CoCircularGridAcrossStripsMatchesOneThreadInCount) {
    std::vector<dvec2> pts;
    for (int y = 0; y < 150; ++y)
        for (int x = 0; x < 250; ++x) pts.emplace_back(double(x), double(y));
    expectStripsMatchOneThread(pts, false);
}

// Points clustered around the strips' cut: most triangles have vertices in two strips (frozen),
// so the sequential flips after the strips carry much of the work and must finish it.
TEST(ParallelC4, PointsCrowdedAtTheCutMatchOneThread) {
    jfa::SplitMix64 rng(8);
    std::vector<dvec2> pts(40000);
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const double u = rng.unit(), v = rng.unit();
        // Half in a thin band across the middle of the wider axis (x), where the cut falls;
        // half spread out.
        pts[i] = i % 2 == 0 ? dvec2(1.0 + (u - 0.5) * 1e-3, v) : dvec2(2.0 * u, v);
    }
    WorkMesh one = scrambledMesh(pts, 2, 9);
    detail::flipToDelaunay(one, 1);
    WorkMesh two = scrambledMesh(pts, 2, 9);
    detail::flipToDelaunay(two, 2);
    const TriangulationReport report = checkTriangulation(asTriangulation(two));
    ASSERT_TRUE(report.ok()) << report.summary();
    EXPECT_EQ(triangleSet(two.triangles), triangleSet(one.triangles));
}

// The whole pipeline on enough points for C4's strips (more than kMinParallelFlip triangles):
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
