// Triangulations: the reference Delaunay triangulator passes the invariant checker on random,
// cocircular (grids, circles), collinear, duplicated and extreme-magnitude inputs; the checker
// catches each kind of broken mesh (fixtures named after what they break); legalize() turns
// bad triangulations into Delaunay ones and terminates on cocircular input.

#include <geometry/Predicates.h>
#include <geometry/Triangulation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace fl::geom {
namespace {

using glm::dvec2;

std::vector<dvec2> uniformPoints(std::size_t n, unsigned seed, double lo = 0.0, double hi = 1.0) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(lo, hi);
    std::vector<dvec2> pts(n);
    for (dvec2& p : pts) p = dvec2(u(rng), u(rng));
    return pts;
}

std::vector<dvec2> gridPoints(int w, int h, double step = 1.0) {
    std::vector<dvec2> pts;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) pts.emplace_back(x * step, y * step);
    return pts;
}

// Number of points on the strict convex hull plus those on its edges: a Delaunay triangulation
// of n points with b of them on the hull boundary has 2n - 2 - b triangles.
std::size_t expectedTriangles(const Triangulation& t, std::size_t used) {
    std::size_t boundary = 0;
    for (const std::uint32_t h : t.halfedges) boundary += h == kNoHalfedge;
    return 2 * used - 2 - boundary;
}

void expectDelaunay(const Triangulation& t, std::size_t distinct) {
    const TriangulationReport report = checkTriangulation(t);
    EXPECT_TRUE(report.ok()) << report.summary();
    EXPECT_EQ(report.vertices, distinct);
    EXPECT_EQ(t.triangleCount(), expectedTriangles(t, distinct));
}

// Flips the edge of halfedge e if its quadrilateral is strictly convex; a test-side helper that
// shares no code with the library (it rebuilds all halfedges afterwards).
bool flipIfConvex(Triangulation& t, std::uint32_t e) {
    const std::uint32_t o = t.halfedges[e];
    if (o == kNoHalfedge) return false;
    const std::uint32_t p0 = t.triangles[e], p1 = t.triangles[nextHalfedge(e)];
    const std::uint32_t a = t.triangles[prevHalfedge(e)], b = t.triangles[prevHalfedge(o)];
    const auto& P = t.points;
    if (orient2dSign(P[p0], P[b], P[a]) <= 0 || orient2dSign(P[p1], P[a], P[b]) <= 0) return false;
    const std::uint32_t te = e / 3 * 3, to = o / 3 * 3;
    t.triangles[te] = p0, t.triangles[te + 1] = b, t.triangles[te + 2] = a;
    t.triangles[to] = p1, t.triangles[to + 1] = a, t.triangles[to + 2] = b;
    buildHalfedges(t);
    return true;
}

// Scrambles a valid triangulation with random flips (keeping it a valid triangulation).
std::size_t scramble(Triangulation& t, std::size_t flips, unsigned seed) {
    std::mt19937 rng(seed);
    std::size_t done = 0;
    for (std::size_t attempt = 0; attempt < 20 * flips && done < flips; ++attempt)
        done += flipIfConvex(t, static_cast<std::uint32_t>(rng() % t.triangles.size()));
    return done;
}

TEST(DelaunayReference, RandomUniformPoints) {
    for (const std::size_t n : {3u, 4u, 10u, 100u, 5000u}) {
        const Triangulation t = delaunayReference(uniformPoints(n, 100 + static_cast<unsigned>(n)));
        expectDelaunay(t, n);
    }
}

TEST(DelaunayReference, GridIsCocircularEverywhere) {
    const Triangulation t = delaunayReference(gridPoints(40, 25));
    expectDelaunay(t, 1000);
    EXPECT_EQ(t.triangleCount(), 2u * 39 * 24);
}

TEST(DelaunayReference, ShuffledGridWithTinySpacing) {
    std::vector<dvec2> pts = gridPoints(20, 20, std::ldexp(1.0, -1040)); // subnormal spacing
    std::shuffle(pts.begin(), pts.end(), std::mt19937(5));
    expectDelaunay(delaunayReference(pts), 400);
}

TEST(DelaunayReference, PointsOnACircle) {
    std::vector<dvec2> pts;
    for (int i = 0; i < 200; ++i) {
        const double th = 6.283185307179586 * i / 200;
        pts.emplace_back(std::cos(th), std::sin(th)); // rounded: nearly, not exactly, cocircular
    }
    expectDelaunay(delaunayReference(pts), 200);

    // Exactly cocircular: the 36 lattice points of x^2 + y^2 = 65^2, plus the centre.
    std::vector<dvec2> lattice{{0, 0}};
    for (int x = -65; x <= 65; ++x)
        for (int y = -65; y <= 65; ++y)
            if (x * x + y * y == 65 * 65) lattice.emplace_back(x, y);
    ASSERT_EQ(lattice.size(), 37u);
    const Triangulation t = delaunayReference(lattice);
    expectDelaunay(t, 37);
    EXPECT_EQ(t.triangleCount(), 36u);
}

TEST(DelaunayReference, CollinearPlusOne) {
    std::vector<dvec2> pts;
    for (int i = 0; i < 50; ++i) pts.emplace_back(0.1 * i, 0.2 * i); // rounded: not all collinear
    pts.emplace_back(1.0, -3.0);
    const Triangulation t = delaunayReference(pts);
    expectDelaunay(t, 51);

    std::vector<dvec2> exact;
    for (int i = 0; i < 50; ++i) exact.emplace_back(3.0 * i, -2.0 * i); // exactly collinear
    exact.emplace_back(7.0, 100.0);
    const Triangulation u = delaunayReference(exact);
    expectDelaunay(u, 51);
    EXPECT_EQ(u.triangleCount(), 49u);
}

TEST(DelaunayReference, DuplicatesAreSkippedKeepingTheLowestIndex) {
    std::vector<dvec2> pts = uniformPoints(50, 7);
    pts.push_back(pts[3]);      // 50 duplicates 3
    pts.push_back(pts[10]);     // 51 duplicates 10
    pts.push_back(pts[3]);      // 52 duplicates 3
    pts.push_back({-0.0, 2.0}); // 53
    pts.push_back({0.0, 2.0});  // 54 duplicates 53: signed zeros are one point
    std::vector<DuplicatePoint> dups;
    const Triangulation t = delaunayReference(pts, &dups);
    ASSERT_EQ(dups.size(), 4u);
    EXPECT_EQ(dups[0].index, 50u);
    EXPECT_EQ(dups[0].kept, 3u);
    EXPECT_EQ(dups[1].index, 51u);
    EXPECT_EQ(dups[1].kept, 10u);
    EXPECT_EQ(dups[2].index, 52u);
    EXPECT_EQ(dups[2].kept, 3u);
    EXPECT_EQ(dups[3].index, 54u);
    EXPECT_EQ(dups[3].kept, 53u);

    const TriangulationReport report = checkTriangulation(t);
    EXPECT_TRUE(report.ok()) << report.summary();
    EXPECT_EQ(report.duplicatePoints, (std::vector<std::uint32_t>{50, 51, 52, 54}));
    TriangulationCheckOptions strict;
    strict.allowDuplicatePoints = false;
    EXPECT_EQ(checkTriangulation(t, strict).problemCount, 4u);
}

TEST(DelaunayReference, RejectsDegenerateInput) {
    EXPECT_THROW((void)delaunayReference({}), std::invalid_argument);
    EXPECT_THROW((void)delaunayReference({{0, 0}, {1, 1}}), std::invalid_argument);
    EXPECT_THROW((void)delaunayReference({{0, 0}, {1, 1}, {0, 0}, {1, 1}}), std::invalid_argument);
    EXPECT_THROW((void)delaunayReference({{0, 0}, {1, 1}, {2, 2}, {-5, -5}}),
                 std::invalid_argument);
    EXPECT_THROW((void)delaunayReference({{0, 0}, {1, 0}, {0, std::nan("")}}),
                 std::invalid_argument);
    try {
        (void)delaunayReference({{0, 0}, {1, 2}, {2, 4}, {3, 6}});
        FAIL() << "collinear input accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("collinear"), std::string::npos) << e.what();
    }
}

TEST(DelaunayReference, ExtremeAndMixedMagnitudes) {
    for (const double s : {1e-300, 1e-150, 1e150, 1e300}) {
        std::vector<dvec2> pts = uniformPoints(300, 11);
        for (dvec2& p : pts) p *= s;
        expectDelaunay(delaunayReference(pts), 300);
    }
    // A tight cluster near the origin inside a huge ring: coordinates span ~500 binades.
    std::vector<dvec2> mixed = uniformPoints(200, 12, -1e-120, 1e-120);
    for (int i = 0; i < 40; ++i) {
        const double th = 6.283185307179586 * i / 40;
        mixed.emplace_back(1e120 * std::cos(th), 1e120 * std::sin(th));
    }
    expectDelaunay(delaunayReference(mixed), 240);
}

// Brute force, independent of the checker's local test: no point strictly inside any
// triangle's circumcircle.
void expectEmptyCircumcircles(const Triangulation& t) {
    for (std::size_t k = 0; k < t.triangleCount(); ++k) {
        const dvec2 a = t.points[t.triangles[3 * k]], b = t.points[t.triangles[3 * k + 1]],
                    c = t.points[t.triangles[3 * k + 2]];
        for (std::size_t i = 0; i < t.points.size(); ++i)
            ASSERT_LE(incircleSign(a, b, c, t.points[i]), 0) << "triangle " << k << ", point " << i;
    }
}

TEST(DelaunayReference, CircumcirclesAreEmptyByBruteForce) {
    expectEmptyCircumcircles(delaunayReference(uniformPoints(300, 19)));
    expectEmptyCircumcircles(delaunayReference(gridPoints(15, 15)));
}

// Points on a 6 x 6 integer lattice: collinear runs, cocircular quadruples and duplicates
// everywhere, in hundreds of random orders and subsets.
TEST(DelaunayReference, HeavilyDegenerateSmallLattices) {
    std::mt19937 rng(20);
    for (int round = 0; round < 400; ++round) {
        std::vector<dvec2> pts(3 + rng() % 40);
        for (dvec2& p : pts) p = dvec2(rng() % 6, rng() % 6);
        std::size_t distinct = 0;
        std::vector<dvec2> sorted = pts;
        std::sort(sorted.begin(), sorted.end(),
                  [](dvec2 a, dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
        distinct =
            static_cast<std::size_t>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
        bool collinear = true;
        for (std::size_t i = 2; i < distinct && collinear; ++i)
            collinear = orient2dSign(sorted[0], sorted[1], sorted[i]) == 0;
        if (distinct < 3 || collinear) {
            EXPECT_THROW((void)delaunayReference(pts), std::invalid_argument);
            continue;
        }
        const Triangulation t = delaunayReference(pts);
        const TriangulationReport r = checkTriangulation(t);
        ASSERT_TRUE(r.ok()) << "round " << round << ": " << r.summary();
        ASSERT_EQ(r.vertices, distinct);
        expectEmptyCircumcircles(t);
    }
}

TEST(DelaunayReference, HalfedgesMatchARebuild) {
    Triangulation t = delaunayReference(uniformPoints(2000, 13));
    const std::vector<std::uint32_t> built = t.halfedges;
    buildHalfedges(t);
    EXPECT_EQ(t.halfedges, built);
}

TEST(DelaunayReference, HundredThousandUniformPoints) {
    const std::vector<dvec2> pts = uniformPoints(100000, 14);
    const auto start = std::chrono::steady_clock::now();
    const Triangulation t = delaunayReference(pts);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    RecordProperty("seconds", std::to_string(seconds));
    std::printf("delaunayReference(100k uniform): %.3f s\n", seconds);
    expectDelaunay(t, 100000);
}

// --- The checker catches broken meshes -----------------------------------------------------

// The unit square split along 0-2; (0, 1, 2), (0, 2, 3) is Delaunay (cocircular: either
// diagonal is), so the fixtures below use a kite whose long diagonal is the wrong one.
Triangulation kiteWithWrongDiagonal() {
    Triangulation t;
    t.points = {{0, 0}, {2, -1}, {4, 0}, {2, 1}};
    t.triangles = {0, 1, 2, 0, 2, 3}; // diagonal 0-2 is long: 1 and 3 are inside the circles
    buildHalfedges(t);
    return t;
}

TEST(Checker, AcceptsAValidMesh) {
    Triangulation t = kiteWithWrongDiagonal();
    EXPECT_EQ(legalize(t), 1u);
    const TriangulationReport r = checkTriangulation(t);
    EXPECT_TRUE(r.ok()) << r.summary();
    EXPECT_EQ(r.vertices, 4u);
    EXPECT_EQ(r.edges, 5u);
    EXPECT_EQ(r.boundaryEdges, 4u);
    EXPECT_EQ(r.triangles, 2u);
}

TEST(Checker, CatchesNonDelaunayEdge) {
    const Triangulation t = kiteWithWrongDiagonal();
    const TriangulationReport r = checkTriangulation(t);
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.nonDelaunayEdges, 1u) << r.summary();
    EXPECT_EQ(r.problemCount, 1u) << r.summary();
    TriangulationCheckOptions structural;
    structural.requireDelaunay = false;
    EXPECT_TRUE(checkTriangulation(t, structural).ok());
}

TEST(Checker, CatchesClockwiseTriangle) {
    Triangulation t = delaunayReference(uniformPoints(30, 15));
    std::swap(t.triangles[4], t.triangles[5]); // triangle 1 now clockwise
    const TriangulationReport r = checkTriangulation(t);
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.badOrientation, 1u) << r.summary();
    EXPECT_GT(r.badHalfedges, 0u); // the stored halfedges no longer match either
}

TEST(Checker, CatchesDegenerateTriangle) {
    Triangulation t;
    t.points = {{0, 0}, {1, 1}, {2, 2}};
    t.triangles = {0, 1, 2};
    buildHalfedges(t);
    const TriangulationReport r = checkTriangulation(t);
    EXPECT_EQ(r.badOrientation, 1u) << r.summary();
}

TEST(Checker, CatchesMissingPoint) {
    Triangulation t = kiteWithWrongDiagonal();
    legalize(t);
    t.points.push_back({2, 0}); // inside the kite, in no triangle
    const TriangulationReport r = checkTriangulation(t);
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.unusedPoints, (std::vector<std::uint32_t>{4})) << r.summary();
}

TEST(Checker, CatchesPointOutsideTheMesh) {
    Triangulation t = kiteWithWrongDiagonal();
    legalize(t);
    t.points.push_back({10, 0}); // unused and outside: the boundary is not the hull either
    const TriangulationReport r = checkTriangulation(t);
    EXPECT_EQ(r.unusedPoints, (std::vector<std::uint32_t>{4})) << r.summary();
    EXPECT_GT(r.hullProblems, 0u) << r.summary();
}

TEST(Checker, CatchesNonConvexHull) {
    // An arrowhead: all triangles fine, but the boundary has a reflex vertex at 3.
    Triangulation t;
    t.points = {{0, 0}, {4, 0}, {2, 4}, {2, 1}};
    t.triangles = {0, 3, 2, 3, 1, 2};
    buildHalfedges(t);
    const TriangulationReport r = checkTriangulation(t);
    EXPECT_FALSE(r.ok());
    EXPECT_GT(r.hullProblems, 0u) << r.summary();
    EXPECT_EQ(r.badOrientation, 0u);
}

TEST(Checker, CatchesHoleAndEulerMismatch) {
    Triangulation t = delaunayReference(gridPoints(5, 5));
    // Remove one interior triangle (one whose three edges are all interior).
    for (std::uint32_t tri = 0; tri < t.triangleCount(); ++tri) {
        const std::uint32_t e = 3 * tri;
        if (t.halfedges[e] != kNoHalfedge && t.halfedges[e + 1] != kNoHalfedge &&
            t.halfedges[e + 2] != kNoHalfedge) {
            t.triangles.erase(t.triangles.begin() + e, t.triangles.begin() + e + 3);
            break;
        }
    }
    buildHalfedges(t);
    const TriangulationReport r = checkTriangulation(t);
    EXPECT_TRUE(r.eulerMismatch) << r.summary();
    EXPECT_GT(r.hullProblems, 0u) << r.summary(); // two boundary cycles
}

TEST(Checker, CatchesStaleHalfedges) {
    Triangulation t = delaunayReference(uniformPoints(40, 16));
    std::swap(t.halfedges[0], t.halfedges[1]);
    const TriangulationReport r = checkTriangulation(t);
    EXPECT_GT(r.badHalfedges, 0u) << r.summary();
    t.halfedges.pop_back();
    EXPECT_EQ(checkTriangulation(t).badHalfedges, 1u);
}

TEST(Checker, CatchesNonManifoldEdgeAndBadIndices) {
    Triangulation t;
    t.points = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0.5, -1}};
    t.triangles = {0, 1, 2, 1, 0, 4, 0, 1, 3};
    EXPECT_THROW(buildHalfedges(t), std::invalid_argument);
    EXPECT_GT(checkTriangulation(t).nonManifoldEdges, 0u);
    t.triangles = {0, 1, 7};
    EXPECT_THROW(buildHalfedges(t), std::invalid_argument);
    EXPECT_EQ(checkTriangulation(t).badIndices, 1u);
    t.triangles = {0, 1, 1};
    EXPECT_THROW(buildHalfedges(t), std::invalid_argument);
    EXPECT_EQ(checkTriangulation(t).badIndices, 1u);
}

TEST(Checker, CatchesCoincidentVertices) {
    Triangulation t;
    t.points = {{0, 0}, {1, 0}, {0, 1}, {1, 0}, {1, 1}};
    t.triangles = {0, 1, 2, 2, 3, 4}; // points 1 and 3 coincide and both are used
    buildHalfedges(t);
    EXPECT_FALSE(checkTriangulation(t).ok());
}

TEST(Checker, MessagesAreCappedButCountsAreNot) {
    Triangulation t = delaunayReference(uniformPoints(300, 17));
    for (std::size_t i = 0; i + 2 < t.triangles.size(); i += 3)
        std::swap(t.triangles[i], t.triangles[i + 1]);
    TriangulationCheckOptions options;
    options.maxMessages = 5;
    const TriangulationReport r = checkTriangulation(t, options);
    EXPECT_EQ(r.problems.size(), 5u);
    EXPECT_EQ(r.badOrientation, t.triangleCount());
    EXPECT_GT(r.problemCount, r.problems.size());
    EXPECT_NE(r.summary().find("more"), std::string::npos);
}

// --- legalize ---------------------------------------------------------------------------------

TEST(Legalize, FanOfAConvexPolygonBecomesDelaunay) {
    // Points on an ellipse (convex, not cocircular), triangulated as a fan from point 0: as far
    // from Delaunay as a convex polygon gets.
    Triangulation t;
    const int n = 60;
    for (int i = 0; i < n; ++i) {
        const double th = 6.283185307179586 * i / n;
        t.points.emplace_back(3.0 * std::cos(th), std::sin(th));
    }
    for (int i = 1; i + 1 < n; ++i)
        t.triangles.insert(t.triangles.end(),
                           {0u, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i + 1)});
    Triangulation withHalfedges = t;
    buildHalfedges(withHalfedges);
    ASSERT_TRUE(checkTriangulation(withHalfedges, {.requireDelaunay = false}).ok());
    EXPECT_GT(checkTriangulation(withHalfedges).nonDelaunayEdges, 0u);
    const std::size_t flips = legalize(t); // builds the halfedges itself
    EXPECT_GT(flips, 0u);
    EXPECT_LE(flips, static_cast<std::size_t>(n * (n - 1) / 2));
    expectDelaunay(t, n);
    EXPECT_EQ(legalize(t), 0u); // idempotent
}

TEST(Legalize, SquareWithEitherDiagonalNeedsNoFlip) {
    Triangulation t;
    t.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    t.triangles = {0, 1, 2, 0, 2, 3};
    EXPECT_EQ(legalize(t), 0u); // cocircular: incircle is exactly 0, never strictly inside
    t.triangles = {0, 1, 3, 1, 2, 3};
    t.halfedges.clear();
    EXPECT_EQ(legalize(t), 0u);
    expectDelaunay(t, 4);
}

TEST(Legalize, UndoesRandomFlips) {
    Triangulation t = delaunayReference(uniformPoints(400, 18));
    ASSERT_GT(scramble(t, 300, 1), 100u);
    ASSERT_FALSE(checkTriangulation(t).ok());
    EXPECT_GT(legalize(t), 0u);
    expectDelaunay(t, 400);
}

TEST(Legalize, TerminatesOnScrambledGrids) {
    for (unsigned seed = 0; seed < 5; ++seed) {
        Triangulation t = delaunayReference(gridPoints(12, 12));
        ASSERT_GT(scramble(t, 400, seed), 50u);
        const std::size_t flips = legalize(t);
        EXPECT_LE(flips, 144u * 143u / 2);
        expectDelaunay(t, 144);
        EXPECT_EQ(legalize(t), 0u);
    }
}

TEST(Legalize, NearlyCocircularPoints) {
    std::vector<dvec2> pts;
    for (int i = 0; i < 100; ++i) {
        const double th = 6.283185307179586 * i / 100;
        pts.emplace_back(std::cos(th) + 0.5, std::sin(th) - 0.25);
    }
    Triangulation t = delaunayReference(pts);
    scramble(t, 200, 3);
    legalize(t);
    expectDelaunay(t, 100);
}

} // namespace
} // namespace fl::geom
