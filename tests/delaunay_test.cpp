// The thesis' Delaunay pipeline end to end (geometry/Delaunay.h: G1-G6 on the CPU, then C1-C4):
// on generic inputs the result is exactly the triangle set of the independent reference
// triangulator; on cocircular and otherwise degenerate inputs (where the Delaunay triangulation
// is not unique) it passes the strict exact checker; bad inputs get their messages; stages,
// counts and determinism. Textures from 16 to 1024 make collisions (missing sites) and bad
// shifts common.
#include <geometry/Delaunay.h>

#include <jfa/Sites.h>

// The pipeline's private mesh, to test its local edits (vertex removal, site shifting) directly.
#include <geometry/detail/DelaunaySteps.h>

#include "TriangleSet.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace fl::geom {
namespace {

using glm::dvec2;
using test::triangleSet;

DelaunayResult run(const std::vector<dvec2>& points, int size, bool stages = false) {
    DelaunayOptions options;
    options.discrete.size = size;
    options.keepStages = stages;
    return delaunay(points, options);
}

std::size_t distinctCount(std::vector<dvec2> pts) {
    std::sort(pts.begin(), pts.end(),
              [](dvec2 a, dvec2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
    return std::size_t(std::unique(pts.begin(), pts.end()) - pts.begin());
}

// Strict check (Delaunay, hull, Euler, every distinct point used) plus the count bookkeeping.
void expectValid(const DelaunayResult& r, const std::vector<dvec2>& points) {
    const TriangulationReport report = checkTriangulation(r.mesh);
    ASSERT_TRUE(report.ok()) << report.summary();
    EXPECT_EQ(report.vertices, distinctCount(points));
    EXPECT_EQ(r.counts.duplicates, points.size() - distinctCount(points));
    ASSERT_EQ(r.duplicateOf.size(), points.size());
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        ASSERT_LE(r.duplicateOf[i], i);
        EXPECT_EQ(points[r.duplicateOf[i]], points[i]);
        EXPECT_EQ(r.duplicateOf[r.duplicateOf[i]], r.duplicateOf[i]);
    }
    if (r.counts.rebuilds == 0) {
        EXPECT_EQ(r.counts.goodShifts + r.counts.badShifts, r.discrete.snapped.kept.size());
        EXPECT_EQ(r.counts.missingInserted + r.counts.duplicates, r.discrete.missing().size());
    }
}

// Generic points: the Delaunay triangulation is unique, so the sets must be equal.
void expectSameAsReference(const std::vector<dvec2>& points, int size) {
    const DelaunayResult r = run(points, size);
    expectValid(r, points);
    EXPECT_EQ(triangleSet(r.mesh.triangles), triangleSet(delaunayReference(points).triangles))
        << "size " << size;
}

std::vector<dvec2> uniform(std::size_t n, std::uint64_t seed) {
    jfa::SplitMix64 rng(seed);
    std::vector<dvec2> pts(n);
    for (dvec2& p : pts) p = dvec2(rng.unit(), rng.unit());
    return pts;
}

std::vector<dvec2> gaussian(std::size_t n, std::uint64_t seed) {
    jfa::SplitMix64 rng(seed);
    std::vector<dvec2> pts(n);
    for (dvec2& p : pts) {
        // Box-Muller: most points crowd a few pixels around the centre.
        const double r = std::sqrt(-2.0 * std::log(1.0 - rng.unit()));
        const double a = 2.0 * std::numbers::pi * rng.unit();
        p = dvec2(r * std::cos(a), r * std::sin(a));
    }
    return pts;
}

std::vector<dvec2> clustered(std::size_t n, std::uint64_t seed) {
    jfa::SplitMix64 rng(seed);
    std::vector<dvec2> centres(8);
    for (dvec2& c : centres) c = dvec2(rng.unit(), rng.unit()) * 100.0;
    std::vector<dvec2> pts(n);
    for (std::size_t i = 0; i < n; ++i)
        pts[i] = centres[i % centres.size()] + dvec2(rng.unit(), rng.unit()) * 0.05;
    return pts;
}

TEST(Delaunay, UniformPointsMatchTheReference) {
    for (const int size : {16, 64, 256, 1024}) expectSameAsReference(uniform(3000, 1), size);
    for (std::uint64_t seed = 2; seed < 40; ++seed)
        expectSameAsReference(uniform(200 + 20 * seed, seed), int(16 << (seed % 6)));
}

TEST(Delaunay, GaussianPointsMatchTheReference) {
    for (const int size : {64, 256, 1024}) expectSameAsReference(gaussian(4000, 7), size);
}

TEST(Delaunay, ClusteredPointsMatchTheReference) {
    for (const int size : {64, 512}) expectSameAsReference(clustered(4000, 9), size);
}

std::vector<dvec2> gridPoints(int w, int h, double step) {
    std::vector<dvec2> pts;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) pts.emplace_back(x * step, y * step);
    return pts;
}

// Cocircular and collinear inputs: many valid Delaunay triangulations, so only the checker.
TEST(Delaunay, GridsAreTriangulated) {
    for (const int size : {8, 16, 33, 64, 256}) {
        const std::vector<dvec2> grid = gridPoints(33, 21, 0.5);
        const DelaunayResult r = run(grid, size);
        expectValid(r, grid);
        EXPECT_EQ(r.mesh.triangleCount(), 2u * 32u * 20u) << "size " << size;
    }
}

TEST(Delaunay, CirclePointsAreTriangulated) {
    std::vector<dvec2> circle;
    for (int i = 0; i < 720; ++i) {
        const double a = 2.0 * std::numbers::pi * i / 720.0;
        circle.emplace_back(std::cos(a), std::sin(a));
    }
    circle.emplace_back(0.0, 0.0);
    for (const int size : {16, 128, 1024}) expectValid(run(circle, size), circle);
}

TEST(Delaunay, TwoLinesAreTriangulated) {
    jfa::SplitMix64 rng(5);
    std::vector<dvec2> lines;
    for (int i = 0; i < 400; ++i) lines.emplace_back(rng.unit() * 10.0, double(i % 2));
    for (const int size : {16, 256}) expectValid(run(lines, size), lines);
    // Collinear points on the hull of a wider set.
    std::vector<dvec2> framed = lines;
    for (int i = 0; i < 50; ++i) framed.emplace_back(rng.unit() * 10.0, 0.5 + rng.unit() * 0.2);
    for (const int size : {16, 256}) expectValid(run(framed, size), framed);
}

TEST(Delaunay, ExtremeMagnitudes) {
    // Coordinates from 1e-300 to 1e300: nearly everything shares the centre pixel.
    jfa::SplitMix64 rng(11);
    std::vector<dvec2> pts;
    for (int i = 0; i < 300; ++i) {
        const auto coordinate = [&] {
            const double sign = rng.unit() < 0.5 ? -1.0 : 1.0;
            return sign * std::pow(10.0, -300.0 + 600.0 * rng.unit());
        };
        pts.emplace_back(coordinate(), coordinate());
    }
    for (const int size : {16, 512}) expectValid(run(pts, size), pts);
    // A bounding box wider than the largest double: G1 maps the halved points.
    const double big = std::numeric_limits<double>::max();
    std::vector<dvec2> wide = uniform(200, 12);
    wide.insert(wide.end(), {{-big, 0.0}, {big, 0.5}, {0.0, -big}, {0.3, big}});
    expectValid(run(wide, 64), wide);
}

TEST(Delaunay, DuplicatesAreLeftOutAndNamed) {
    std::vector<dvec2> pts = uniform(500, 13);
    jfa::SplitMix64 rng(14);
    for (int i = 0; i < 300; ++i) pts.push_back(pts[rng.below(pts.size())]);
    for (const int size : {16, 1024}) {
        const DelaunayResult r = run(pts, size);
        expectValid(r, pts);
        EXPECT_EQ(r.counts.duplicates, 300u);
        EXPECT_EQ(triangleSet(r.mesh.triangles), triangleSet(delaunayReference(pts).triangles));
    }
    const DelaunayResult r = run({{0, 0}, {1, 0}, {0, 0}, {0, 1}, {1, 0}, {0, 0}}, 16);
    EXPECT_EQ(r.duplicateOf, (std::vector<std::uint32_t>{0, 1, 0, 3, 1, 0}));
    EXPECT_EQ(r.counts.duplicates, 3u);
    EXPECT_EQ(r.mesh.triangleCount(), 1u);
}

void expectRejected(const std::vector<dvec2>& pts, const std::string& message) {
    try {
        (void)run(pts, 64);
        ADD_FAILURE() << "accepted; expected: " << message;
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
}

TEST(Delaunay, BadInputIsRejectedWithAMessage) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    expectRejected({}, "at least 3 distinct points, got 0");
    expectRejected({{0, 0}, {1, 1}}, "at least 3 distinct points, got 2");
    expectRejected({{0, 0}, {1, 1}, {0, 0}, {1, 1}}, "at least 3 distinct points, got 2");
    expectRejected({{0, 0}, {1, 1}, {2, 2}, {3, 3}, {1, 1}}, "all 4 distinct points are collinear");
    expectRejected({{0, 0}, {1, 0}, {0, 1}, {nan, 1}}, "point 3 has a non-finite coordinate");
    expectRejected({{0, 0}, {1, 0}, {inf, 1}}, "point 2 has a non-finite coordinate");
    DelaunayOptions bad;
    bad.discrete.size = 1;
    EXPECT_THROW((void)delaunay(uniform(10, 1), bad), std::invalid_argument);
}

TEST(Delaunay, StagesFollowTheSteps) {
    const std::vector<dvec2> pts = uniform(2000, 15);
    const DelaunayResult r = run(pts, 64, true);
    ASSERT_EQ(r.stages.size(), 5u);
    EXPECT_EQ(r.stages[0], r.discrete.triangles());
    EXPECT_EQ(r.stages[1].size(), r.stages[0].size() + 3 * r.counts.hullTriangles);
    EXPECT_EQ(r.stages[4], r.mesh.triangles);
    // T' and C1 on the pixels, C2 on the continuous sites of S', C3 on all: counterclockwise.
    const auto& px = r.discrete.snapped.pixels;
    for (std::size_t s = 0; s < 5; ++s)
        for (std::size_t i = 0; i < r.stages[s].size(); i += 3) {
            const std::uint32_t a = r.stages[s][i], b = r.stages[s][i + 1], c = r.stages[s][i + 2];
            if (s < 2)
                ASSERT_GT(pixelOrient(px[a], px[b], px[c]), 0) << "stage " << s;
            else
                ASSERT_GT(orient2dSign(pts[a], pts[b], pts[c]), 0) << "stage " << s;
        }
    // After C3 the mesh is already a triangulation of every site, only not yet Delaunay.
    Triangulation c3{pts, r.stages[3], {}};
    buildHalfedges(c3);
    TriangulationCheckOptions loose;
    loose.requireDelaunay = false;
    EXPECT_TRUE(checkTriangulation(c3, loose).ok()) << checkTriangulation(c3, loose).summary();
    EXPECT_TRUE(run(pts, 64).stages.empty());
}

TEST(Delaunay, RunsAreDeterministic) {
    const std::vector<dvec2> pts = gaussian(3000, 16);
    DelaunayOptions one, two;
    one.discrete.size = two.discrete.size = 128;
    one.discrete.threads = 1;
    two.discrete.threads = 2;
    one.check = true;
    const DelaunayResult a = delaunay(pts, one), b = delaunay(pts, two), c = delaunay(pts, two);
    EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
    EXPECT_EQ(b.mesh.triangles, c.mesh.triangles);
    EXPECT_EQ(a.mesh.halfedges, c.mesh.halfedges);
    EXPECT_EQ(a.counts.flips, c.counts.flips);
    EXPECT_EQ(a.counts.badShifts, c.counts.badShifts);
}

TEST(Delaunay, UsesTheGivenBackend) {
    int calls = 0;
    DelaunayOptions options;
    options.discrete.size = 32;
    options.discreteBackend = [&](const std::vector<dvec2>& sites,
                                  const DiscreteDelaunayOptions& o) {
        ++calls;
        return discreteDelaunay(sites, o);
    };
    const std::vector<dvec2> pts = uniform(300, 17);
    expectValid(delaunay(pts, options), pts);
    EXPECT_EQ(calls, 1);
}

TEST(Delaunay, RepairsRatherThanRebuilds) {
    // Small textures: many collisions and bad shifts, all handled by the thesis' steps.
    const DelaunayResult r = run(uniform(5000, 18), 32);
    EXPECT_EQ(r.counts.rebuilds, 0u);
    EXPECT_GT(r.counts.badShifts, 50u);
    EXPECT_GT(r.counts.hullTriangles, 0u);
    EXPECT_GT(r.counts.missingInserted, 3000u);
    // All pixels of S' on one row (the middle one of an odd texture): no T', no hull to
    // complete, so the fallback triangulates.
    std::vector<dvec2> flat;
    for (int i = 0; i < 100; ++i) flat.emplace_back(i, 1e-9 * double(i % 7));
    const DelaunayResult f = run(flat, 65);
    expectValid(f, flat);
    EXPECT_EQ(f.counts.rebuilds, 1u);
}

// Regression: the sites' start positions came from TextureMapping::toWorld, whose rounding bent
// collinear diagonal pixel runs (on the hull of nearly collinear input) into reflex chains, so
// T' + C1 failed certification and every such input fell back to rebuild().
TEST(Delaunay, DiagonalPixelHullsStayConvexInWorldCoordinates) {
    jfa::SplitMix64 rng(1);
    std::vector<dvec2> pts(250);
    for (dvec2& p : pts) {
        const double x = rng.unit();
        p = dvec2(x, 0.5 * x + 1e-12 * rng.unit());
    }
    for (const int size : {64, 150}) {
        const DelaunayResult r = run(pts, size);
        expectValid(r, pts);
        EXPECT_EQ(r.counts.rebuilds, 0u) << "size " << size;
    }
}

// Regression: a zero-area triangle of G6 (a four-colour corner whose both diagonals are flat or
// clockwise, §6.4) failed certification; it is flipped away before it now.
TEST(Delaunay, FlatTriangleOfAFourColourCornerIsFlippedAway) {
    jfa::SplitMix64 rng(2);
    std::vector<dvec2> pts(200);
    for (dvec2& p : pts) {
        const double a = 2.0 * std::numbers::pi * rng.unit();
        p = dvec2(std::cos(a), std::sin(a));
    }
    const DelaunayResult r = run(pts, 32);
    ASSERT_GT(r.discrete.mesh.stats.degenerate, 0);
    expectValid(r, pts);
    EXPECT_EQ(r.counts.rebuilds, 0u);
}

TEST(DelaunayMesh, FastPredicatesAgreeWithTheLibrary) {
    jfa::SplitMix64 rng(21);
    const auto compare = [](dvec2 a, dvec2 b, dvec2 c, dvec2 d) {
        ASSERT_EQ(detail::fastOrientSign(a, b, c), orient2dSign(a, b, c));
        ASSERT_EQ(detail::fastIncircleSign(a, b, c, d), incircleSign(a, b, c, d));
    };
    for (int i = 0; i < 20000; ++i) {
        const auto pick = [&] {
            switch (i % 4) {
            case 0:
                return dvec2(rng.unit(), rng.unit()); // generic
            case 1:
                return dvec2(double(rng.below(4)), double(rng.below(4))); // cocircular
            case 2:
                return dvec2(rng.unit(), rng.unit()) * 0x1p-1060; // subnormal
            default:
                return dvec2(rng.unit() - 0.5, rng.unit() - 0.5) * 0x1p1000; // huge
            }
        };
        compare(pick(), pick(), pick(), pick());
    }
}

// --- the private mesh's local edits ---------------------------------------------------------

// A triangulation of `pts` (some collinear, some on the hull) as a WorkMesh.
detail::WorkMesh workMesh(const std::vector<dvec2>& pts) {
    const Triangulation t = delaunayReference(pts);
    detail::WorkMesh mesh(pts);
    EXPECT_TRUE(mesh.setTriangles(t.triangles));
    EXPECT_TRUE(mesh.isTriangulation(pts.size()));
    return mesh;
}

// The mesh with its unused points moved onto a used one (so the checker calls them duplicates).
TriangulationReport checkLoosely(const detail::WorkMesh& mesh) {
    detail::WorkMesh copy = mesh;
    copy.compact();
    Triangulation t{copy.points, copy.triangles, copy.halfedges};
    for (std::size_t v = 0; v < t.points.size(); ++v)
        if (!copy.inMesh(std::uint32_t(v))) t.points[v] = t.points[copy.triangles[0]];
    TriangulationCheckOptions loose;
    loose.requireDelaunay = false;
    return checkTriangulation(t, loose);
}

TEST(DelaunayMesh, RemovingAnyVertexLeavesATriangulation) {
    // Grid points (collinear hull runs, cocircular quads) plus a few random ones.
    std::vector<dvec2> pts = gridPoints(6, 5, 1.0);
    const std::vector<dvec2> extra = uniform(12, 19);
    for (const dvec2& p : extra) pts.push_back(p * 5.0);
    for (std::uint32_t v = 0; v < pts.size(); ++v) {
        detail::WorkMesh mesh = workMesh(pts);
        ASSERT_TRUE(mesh.removeVertex(v));
        EXPECT_FALSE(mesh.inMesh(v));
        const TriangulationReport report = checkLoosely(mesh);
        ASSERT_TRUE(report.ok()) << "vertex " << v << "\n" << report.summary();
    }
    // A single triangle cannot lose a vertex.
    detail::WorkMesh one = workMesh({{0, 0}, {1, 0}, {0, 1}});
    EXPECT_FALSE(one.removeVertex(0));
    EXPECT_EQ(one.liveTriangles(), 1u);
}

TEST(DelaunayMesh, ShiftingSitesKeepsATriangulation) {
    // Sites on a grid (the pixels) move to random points up to a cell away: good moves, bad
    // ones of every kind, hull sites moving in and out, targets on other sites' old positions.
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        jfa::SplitMix64 rng(100 + seed);
        std::vector<dvec2> pts;
        for (int y = 0; y < 7; ++y)
            for (int x = 0; x < 7; ++x)
                if (rng.unit() < 0.7) pts.emplace_back(x, y);
        std::vector<dvec2> targets = pts;
        for (std::size_t i = 0; i < targets.size(); ++i) {
            const double r = rng.unit();
            if (r < 0.1 && i > 0)
                targets[i] = pts[rng.below(i)]; // onto an earlier old position
            else
                targets[i] += dvec2(rng.unit() - 0.5, rng.unit() - 0.5) * (r < 0.6 ? 1.0 : 2.5);
        }
        std::sort(targets.begin(), targets.end(),
                  [](dvec2 a, dvec2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
        if (std::unique(targets.begin(), targets.end()) != targets.end()) continue;
        std::shuffle(targets.begin(), targets.end(), std::mt19937(unsigned(seed)));
        detail::WorkMesh mesh = workMesh(pts);
        std::vector<std::uint32_t> order(pts.size());
        for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
        const detail::ShiftStats stats = detail::shiftSites(mesh, targets, order);
        ASSERT_FALSE(stats.stuck);
        detail::insertSites(mesh, stats.deferred, stats.deferred);
        EXPECT_EQ(mesh.points, targets);
        const TriangulationReport report = checkLoosely(mesh);
        ASSERT_TRUE(report.ok()) << "seed " << seed << "\n" << report.summary();
        EXPECT_EQ(report.vertices, pts.size());
    }
}

} // namespace
} // namespace fl::geom
