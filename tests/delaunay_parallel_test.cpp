// Step C3 on several threads (geometry/src/DelaunayInsertParallel.cpp, issue 31): the pipeline's
// result with the parallel strips equals the one-thread result: the same triangle set where the
// Delaunay triangulation is unique (generic, clustered input), the same triangle count and a
// passing exact check where it is not (co-circular rings and grids, collinear lines). Each
// fixture has far more missing sites than kMinParallelInsert (a small texture), and the tests
// also require that the strips inserted most of them, so they cannot pass on the sequential
// path alone; 3 and 4 strips (more than the cores here) put more sites near strip borders.
#include <geometry/Delaunay.h>

#include <jfa/Sites.h>

#include <geometry/detail/DelaunaySteps.h>

#include "TriangleSet.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace fl::geom {
namespace {

using glm::dvec2;
using test::triangleSet;

DelaunayResult runWithThreads(const std::vector<dvec2>& points, int size, int threads) {
    DelaunayOptions options;
    options.discrete.size = size;
    options.discrete.threads = threads;
    options.check = true; // throws if the result is not a Delaunay triangulation
    return delaunay(points, options);
}

// Runs one thread and 2..4 threads; `unique`: the triangle sets must be equal. At most
// `sequentialShare` of the sites may be left to the sequential pass.
void expectParallelMatchesSequential(const std::vector<dvec2>& points, int size, bool unique,
                                     double sequentialShare = 0.25) {
    const DelaunayResult one = runWithThreads(points, size, 1);
    ASSERT_GT(one.counts.missingInserted, 2 * detail::kMinParallelInsert);
    EXPECT_GE(one.counts.sequentialInserts, one.counts.missingInserted);
    for (const int threads : {2, 3, 4}) {
        const DelaunayResult many = runWithThreads(points, size, threads);
        EXPECT_EQ(many.counts.rebuilds, 0u);
        // Most sites went through the strips (only those near their borders are left).
        EXPECT_LT(double(many.counts.sequentialInserts),
                  sequentialShare * double(many.counts.missingInserted))
            << threads << " threads";
        const TriangulationReport report = checkTriangulation(many.mesh);
        ASSERT_TRUE(report.ok()) << report.summary();
        EXPECT_EQ(many.mesh.triangleCount(), one.mesh.triangleCount()) << threads << " threads";
        if (unique) {
            EXPECT_EQ(triangleSet(many.mesh.triangles), triangleSet(one.mesh.triangles))
                << threads << " threads";
        }
    }
}

std::vector<dvec2> clusteredPoints(std::size_t n, std::uint64_t seed) {
    jfa::SplitMix64 rng(seed);
    std::vector<dvec2> centres(6);
    for (dvec2& c : centres) c = dvec2(rng.unit(), rng.unit()) * 10.0;
    std::vector<dvec2> pts(n);
    for (std::size_t i = 0; i < n; ++i)
        pts[i] = centres[i % centres.size()] + dvec2(rng.unit(), rng.unit()) * 0.3;
    return pts;
}

TEST(ParallelC3, UniformPointsMatchOneThread) {
    jfa::SplitMix64 rng(3);
    std::vector<dvec2> pts(30000);
    for (dvec2& p : pts) p = dvec2(rng.unit(), rng.unit());
    expectParallelMatchesSequential(pts, 64, true);
}

TEST(ParallelC3, ClusteredPointsMatchOneThread) {
    expectParallelMatchesSequential(clusteredPoints(30000, 11), 128, true);
}

// Rings of points around one centre: every ring is co-circular, so the triangulation inside a
// ring is not unique and many incircle tests are exactly zero.
TEST(ParallelC3, CoCircularRingsMatchOneThreadInCount) {
    std::vector<dvec2> pts;
    for (int ring = 1; ring <= 60; ++ring)
        for (int i = 0; i < 400; ++i) {
            const double a = 2.0 * std::numbers::pi * i / 400.0;
            pts.emplace_back(ring * std::cos(a), ring * std::sin(a));
        }
    expectParallelMatchesSequential(pts, 64, false);
}

TEST(ParallelC3, GridMatchesOneThreadInCount) {
    std::vector<dvec2> pts;
    for (int y = 0; y < 160; ++y)
        for (int x = 0; x < 160; ++x) pts.emplace_back(x * 0.25, y * 0.25);
    expectParallelMatchesSequential(pts, 32, false);
}

// Sites on two parallel lines: collinear runs, sites exactly on hull edges, flat triangles
// avoided only by the exact orientation tests. Before C3 the mesh between the lines has long
// triangles across the strip borders (a few kept sites per line); sites inside such a frozen
// triangle wait for the sequential pass, and a strip where most sites fail gives up after
// kStripTrial of them (3 and 4 strips do), so here the strips need only have inserted some.
TEST(ParallelC3, CollinearLinesMatchOneThreadInCount) {
    jfa::SplitMix64 rng(5);
    std::vector<dvec2> pts;
    for (int i = 0; i < 30000; ++i) pts.emplace_back(rng.unit() * 10.0, double(i % 2));
    expectParallelMatchesSequential(pts, 64, false, 1.0);
}

// C3's insertion order with its largest rounds' Hilbert quadrants sorted on the threads is the
// one-thread order, item for item (the largest rounds here, 75k and 19k items, are above
// the sort's threshold for threads), also with many equal coordinates (a grid's columns and rows).
TEST(ParallelC3, InsertionOrderIsTheSameOnAnyThreadCount) {
    jfa::SplitMix64 rng(12);
    for (const bool grid : {false, true}) {
        std::vector<detail::OrderItem> items(100000);
        for (std::uint32_t i = 0; i < items.size(); ++i) {
            const dvec2 p =
                grid ? dvec2(double(i % 316), double(i / 316)) : dvec2(rng.unit(), rng.unit());
            items[i] = {p, i};
        }
        std::vector<detail::OrderItem> one = items;
        detail::insertionOrder(one, 1);
        for (const int threads : {2, 3, 4}) {
            std::vector<detail::OrderItem> many = items;
            detail::insertionOrder(many, threads);
            bool same = true;
            for (std::size_t k = 0; k < one.size(); ++k)
                same = same && one[k].index == many[k].index;
            EXPECT_TRUE(same) << threads << " threads" << (grid ? ", grid" : "");
        }
    }
}

} // namespace
} // namespace fl::geom
