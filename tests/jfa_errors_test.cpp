// Error analysis of JFA Voronoi diagrams (thesis §4.4-4.5): error pixels, 8-connected clusters,
// discrete Voronoi vertices (Property 4.1), the estimate E (Properties 4.2-4.3), the convex hull
// behind R, and end to end on random sites with the CPU kernel.
#include <jfa/CpuKernel.h>
#include <jfa/ErrorAnalysis.h>
#include <jfa/Hull.h>
#include <jfa/NearestSite.h>
#include <jfa/Plan.h>
#include <jfa/Reference.h>
#include <jfa/Sites.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fl::jfa {
namespace {

// ---- hand-made exact diagrams -------------------------------------------------------------------

// A small diagram computed by brute force (independent of jfa/Reference.h): sites as cells
// (x, y, id), the exact squared distance per grid point and NearestSite's winner per grid point.
struct Diagram {
    int width = 0, height = 0;
    bool integer = true;
    std::vector<Cell> sites;
    std::vector<double> squared;
    Grid winners; // an error-free flood

    Diagram(int w, int h, std::vector<Cell> s, bool integerSites = true)
        : width(w), height(h), integer(integerSites), sites(std::move(s)), winners(w, h) {
        const NearestSite criterion{integer};
        squared.assign(std::size_t(w) * std::size_t(h), std::numeric_limits<double>::infinity());
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const Cell* best = nullptr;
                for (const Cell& c : sites)
                    if (best == nullptr || criterion.better(x, y, c, *best)) best = &c;
                if (best == nullptr) continue;
                winners.at(x, y) = *best;
                squared[std::size_t(y) * std::size_t(w) + std::size_t(x)] =
                    integer ? double(NearestSite::squaredInt(x, y, *best))
                            : double(NearestSite::squaredFloat(x, y, *best));
            }
        }
    }
    [[nodiscard]] ExactDiagramView view() const { return {width, height, sites, squared, integer}; }
};

Cell site(float x, float y, int id) {
    return Cell{x, y, float(id), 0.0f};
}

// Three sites whose circumcentre (7, 8) is a grid point at squared distance 25 from all three.
Diagram threeSites() {
    return Diagram(16, 16, {site(3, 5, 0), site(11, 5, 1), site(7, 13, 2)});
}

// ---- error pixels -------------------------------------------------------------------------------

TEST(JfaErrorPixels, WrongPixelAtVertexAndInInteriorTiesCorrectEmptyWrong) {
    const Diagram d = threeSites();
    const ErrorReport clean = analyzeErrors(d.winners, d.view()); // an error-free flood
    EXPECT_EQ(clean.errorPixels + clean.clusters + clean.singles, 0);
    EXPECT_EQ(clean.pixels, 256);
    Grid flooded = d.winners;
    // (7, 9): nearest is C (16) and A, B are at 32; recording A is an error. It neighbours the
    // circumcentre (7, 8), where A, B, C tie: a Voronoi vertex.
    ASSERT_EQ(flooded.at(7, 9).z, 2.0f);
    flooded.at(7, 9) = d.sites[0];
    // (3, 6) lies deep inside A's region (distance 1); recording C (distance 65) is an error.
    flooded.at(3, 6) = d.sites[2];
    // (7, 2) is equidistant (25) from A and B; the exact winner is A, recording B is a tie.
    ASSERT_EQ(flooded.at(7, 2).z, 0.0f);
    flooded.at(7, 2) = d.sites[1];
    // The circumcentre itself records C instead of the winner A: a three-way tie, correct.
    flooded.at(7, 8) = d.sites[2];
    // An empty cell is an error.
    flooded.at(15, 15) = kEmptyCell;

    const std::vector<std::uint8_t> mask = errorPixelMask(flooded, d.view());
    EXPECT_EQ(mask[9 * 16 + 7], 1);
    EXPECT_EQ(mask[6 * 16 + 3], 1);
    EXPECT_EQ(mask[2 * 16 + 7], 0);
    EXPECT_EQ(mask[8 * 16 + 7], 0);
    EXPECT_EQ(mask[15 * 16 + 15], 1);

    const ErrorReport r = analyzeErrors(flooded, d.view(), "hand-made");
    EXPECT_EQ(r.errorPixels, 3);
    EXPECT_EQ(r.clusters, 3);
    EXPECT_EQ(r.singles, 3);
    EXPECT_EQ(r.singlesAtVertices, 1); // only (7, 9)
    EXPECT_NEAR(r.singleVertexShare, 1.0 / 3.0, 1e-12);
    EXPECT_EQ(r.singlesOffVertices, (std::vector<IntPoint>{{3, 6}, {15, 15}}));
    EXPECT_EQ(r.clusterSizes, (std::map<std::int64_t, std::int64_t>{{1, 3}}));
    std::cout << r.describe() << "\n";
}

TEST(JfaErrorPixels, FloatSitesUseFloatArithmeticAndSizesAreChecked) {
    const Diagram d(4, 4, {site(0.25f, 0.5f, 0), site(3.0f, 2.75f, 1)}, false);
    Grid flooded = d.winners;
    flooded.at(0, 0) = d.sites[1];
    const ErrorReport r = analyzeErrors(flooded, d.view());
    EXPECT_EQ(r.errorPixels, 1);
    EXPECT_TRUE(isErrorPixel(d.sites[1], 0, 0, d.squared[0], false));
    EXPECT_FALSE(isErrorPixel(d.sites[0], 0, 0, d.squared[0], false));
    EXPECT_TRUE(isErrorPixel(kEmptyCell, 0, 0, d.squared[0], false));
    const Diagram t = threeSites(); // and sizes are checked
    EXPECT_THROW((void)errorPixelMask(Grid(4, 4), t.view()), std::invalid_argument);
    ExactDiagramView bad = t.view();
    bad.squared = bad.squared.subspan(1);
    EXPECT_THROW((void)analyzeErrors(t.winners, bad), std::invalid_argument);
}

// ---- clusters -----------------------------------------------------------------------------------

std::vector<std::uint8_t> parseMask(const std::vector<std::string>& rows) {
    std::vector<std::uint8_t> mask;
    for (const std::string& row : rows)
        for (char c : row) mask.push_back(c == '#' ? 1 : 0);
    return mask;
}

TEST(JfaErrorClusters, EightConnectedShapes) {
    const std::vector<std::string> rows{
        "#.....#.", // (0,0) starts a diagonal chain; (6,0)-(7,1) a diagonal pair
        ".#.....#", //
        "..#.....", // chain of 3 ends here
        "......#.", // single (6,3)
        "##......", // horizontal pair
        "........", //
        "..###...", // an L of 4 (3 across, 1 down)
        "....#..#", // (7,7): single in the corner
    };
    const ClusterStats s = errorClusters(parseMask(rows), 8, 8);
    EXPECT_EQ(s.errorPixels, 13);
    EXPECT_EQ(s.clusters, 6);
    EXPECT_EQ(s.singles, 2);
    const std::map<std::int64_t, std::int64_t> histogram{{1, 2}, {2, 2}, {3, 1}, {4, 1}};
    EXPECT_EQ(s.sizeHistogram, histogram);
    const std::vector<std::int64_t> singles{3 * 8 + 6, 7 * 8 + 7};
    EXPECT_EQ(s.singleIndices, singles);
}

TEST(JfaErrorClusters, DiagonalTouchJoinsAndRingIsOneCluster) {
    // Two blocks touching only at a corner are one 8-connected cluster.
    const ClusterStats corner = errorClusters(parseMask({"##..", "##..", "..##", "..##"}), 4, 4);
    EXPECT_EQ(corner.clusters, 1);
    EXPECT_EQ(corner.errorPixels, 8);
    const ClusterStats ring = errorClusters(parseMask({".#.", "#.#", ".#."}), 3, 3);
    EXPECT_EQ(ring.clusters, 1);
    EXPECT_EQ(ring.singles, 0);
    const ClusterStats none = errorClusters(parseMask({"...", "..."}), 3, 2);
    EXPECT_EQ(none.clusters, 0);
    EXPECT_TRUE(none.sizeHistogram.empty());
    EXPECT_THROW((void)errorClusters(parseMask({"..."}), 2, 2), std::invalid_argument);
}

// ---- Voronoi vertices ---------------------------------------------------------------------------

TEST(JfaVoronoiVertex, ThreeSitesVerticesSitAroundTheCircumcentre) {
    const Diagram d = threeSites();
    const SiteIndex index(d.sites, true);
    EXPECT_EQ(index.sitesAt(7, 8, 25.0).size(), 3u); // the circumcentre: a three-way tie
    EXPECT_EQ(index.sitesAt(7, 2, 25.0).size(), 2u); // on the A-B bisector
    EXPECT_TRUE(index.sitesAt(7, 2, 24.0).empty());
    std::vector<IntPoint> vertices;
    for (int y = 0; y < d.height; ++y)
        for (int x = 0; x < d.width; ++x)
            if (isDiscreteVoronoiVertex(d.view(), index, x, y)) vertices.push_back({x, y});
    // Every grid point whose window holds the circumcentre is a vertex...
    for (int y = 7; y <= 9; ++y)
        for (int x = 6; x <= 8; ++x)
            EXPECT_NE(std::find(vertices.begin(), vertices.end(), IntPoint{x, y}), vertices.end())
                << x << "," << y;
    // ...and vertices stay next to it (edges and interiors are not vertices).
    for (const IntPoint& v : vertices)
        EXPECT_LE(std::max(std::abs(v.x - 7), std::abs(v.y - 8)), 2) << v.x << "," << v.y;
    EXPECT_FALSE(isDiscreteVoronoiVertex(d.view(), index, 7, 2)); // A-B edge
    EXPECT_FALSE(isDiscreteVoronoiVertex(d.view(), index, 3, 6)); // interior of A
    EXPECT_FALSE(isDiscreteVoronoiVertex(d.view(), index, 0, 0)); // grid corner
    std::cout << vertices.size() << " vertex grid points around the circumcentre\n";
}

TEST(JfaVoronoiVertex, TiesMakeTheVertexNotTheTieBreak) {
    // Circumcentre (4, 5) of A (1, 1), B (7, 1), C (4, 10), squared radius 25. NearestSite gives
    // (4, 5) to A (smallest id), so the winners around (4, 4) show only A and B; C belongs to the
    // nearest-site set of (4, 5) all the same, which makes (4, 4) a vertex.
    const Diagram d(9, 12, {site(1, 1, 0), site(7, 1, 1), site(4, 10, 2)});
    std::set<float> winnerIds;
    for (int y = 3; y <= 5; ++y)
        for (int x = 3; x <= 5; ++x) winnerIds.insert(d.winners.at(x, y).z);
    EXPECT_EQ(winnerIds, (std::set<float>{0.0f, 1.0f}));
    const SiteIndex index(d.sites, true);
    EXPECT_TRUE(isDiscreteVoronoiVertex(d.view(), index, 4, 4));
    EXPECT_FALSE(isDiscreteVoronoiVertex(d.view(), index, 4, 3));
}

TEST(JfaVoronoiVertex, SiteIndexReturnsOneSitePerPositionAndAllTies) {
    // Four sites on a circle of squared radius 25 around (10, 10), one duplicated (id 4), one far.
    const std::vector<Cell> sites{site(13, 14, 3), site(10, 15, 0), site(5, 10, 1),
                                  site(15, 10, 2), site(10, 15, 4), site(0, 0, 5)};
    const SiteIndex index(sites, true);
    EXPECT_EQ(index.distinctSites().size(), 5u);
    const std::vector<Cell> ties = index.sitesAt(10, 10, 25.0);
    ASSERT_EQ(ties.size(), 4u);
    EXPECT_EQ(ties[0].z, 0.0f); // the duplicate keeps the smaller id, results sorted by id
    EXPECT_EQ(ties[3].z, 3.0f);
    EXPECT_TRUE(SiteIndex({}, true).sitesAt(0, 0, 1.0).empty());
}

// ---- the estimate E -----------------------------------------------------------------------------

TEST(JfaErrorEstimate, MatchesHandComputedValues) {
    // "log n" is the JFA pass count.
    EXPECT_EQ(jfaPassCount(0), 0);
    EXPECT_EQ(jfaPassCount(1), 0);
    EXPECT_EQ(jfaPassCount(2), 1);
    EXPECT_EQ(jfaPassCount(512), 9);
    EXPECT_EQ(jfaPassCount(513), 10);
    for (int n : {2, 3, 100, 256, 300, 512, 1000, 4096})
        EXPECT_EQ(jfaPassCount(n), static_cast<int>(jfaSteps(n).size())) << n;
    // n = 512: S = sum_{k=0}^{7} 4^{-3(k+1)} = (1 - 64^-8) / 63. R = 10, x = 1/(10 pi):
    // E1 = 2 S (1/3 - 2x + 2x^2), E2 = S (1/12 - x + 2x^2), E = (2*1000 - 60 - 2)(E1 + E2).
    // Values from a separate double-precision evaluation of the thesis' formulas.
    const ErrorEstimate e = estimateErrors(1000, 60, 10.0, 512);
    EXPECT_NEAR(e.e1, 0.00862532634188638, 1e-15);
    EXPECT_NEAR(e.e2, 0.0008496629902825528, 1e-16);
    EXPECT_DOUBLE_EQ(e.vertices, 1938.0);
    EXPECT_NEAR(e.e, 18.36252932574339, 1e-11);
    // The combined form 2m (3/4 - 5/(pi R) + 6/(pi^2 R^2)) S equals (E1 + E2) per vertex.
    const double s = (1.0 - std::pow(64.0, -8.0)) / 63.0;
    for (double r : {3.5, 5.0, 10.0, 40.0, 300.0}) {
        const double x = 1.0 / (std::numbers::pi * r);
        const ErrorEstimate q = estimateErrors(500, 40, r, 512);
        EXPECT_NEAR(q.e1 + q.e2, (0.75 - 5.0 * x + 6.0 * x * x) * s, 1e-15) << r;
        EXPECT_NEAR(q.e, 958.0 * (q.e1 + q.e2), 1e-12);
    }
    // R -> infinity: E1 -> 2S/3, E2 -> S/12.
    const ErrorEstimate inf = estimateErrors(10, 4, std::numeric_limits<double>::infinity(), 512);
    EXPECT_NEAR(inf.e1, 2.0 * s / 3.0, 1e-16);
    EXPECT_NEAR(inf.e2, s / 12.0, 1e-16);
    // Tiny grids: log n - 2 < 0 leaves the sum empty.
    EXPECT_EQ(estimateErrors(10, 4, 5.0, 2).e, 0.0);
    EXPECT_NEAR(estimateErrors(10, 4, 1e9, 4).e1, 2.0 / 3.0 / 64.0, 1e-9); // n = 4: k = 0 only
}

TEST(JfaErrorEstimate, ClampedForTinyRAndDegenerateCounts) {
    double previous = 0.0;
    for (int i = 0; i <= 4000; ++i) {
        const double r = i * 0.005;
        const ErrorEstimate e = estimateErrors(1000, 50, r, 512);
        ASSERT_TRUE(std::isfinite(e.e)) << r;
        ASSERT_GE(e.e1, 0.0) << r;
        ASSERT_GE(e.e2, 0.0) << r;
        ASSERT_GE(e.e, previous) << "E must not decrease with R; R = " << r;
        previous = e.e;
        if (r <= 1.5) { // F1's root: 6 / (pi (3 - sqrt 3)) = 1.506
            EXPECT_EQ(e.e1, 0.0) << r;
        }
        if (r <= 3.0) { // F2's root: 12 / (pi (3 - sqrt 3)) = 3.013
            EXPECT_EQ(e.e2, 0.0) << r;
        }
    }
    EXPECT_GT(estimateErrors(1000, 50, 1.51, 512).e1, 0.0);
    EXPECT_GT(estimateErrors(1000, 50, 3.02, 512).e2, 0.0);
    EXPECT_EQ(estimateErrors(1000, 50, std::nan(""), 512).e, 0.0);
    EXPECT_EQ(estimateErrors(1000, 50, -3.0, 512).e, 0.0);
    for (std::int64_t m : {0, 1, 2}) {
        const ErrorEstimate e = estimateErrors(m, m, 20.0, 512);
        EXPECT_EQ(e.vertices, 0.0) << m;
        EXPECT_EQ(e.e, 0.0) << m;
    }
    EXPECT_EQ(estimateErrors(3, 3, 20.0, 512).vertices, 1.0);
    EXPECT_EQ(estimateErrors(5, 100, 20.0, 512).vertices, 0.0); // h > 2m - 2: clamped
}

TEST(JfaErrorEstimate, PerSiteEstimateDecreasesAsSitesGrow) {
    // §4.5.2: more sites -> smaller R -> smaller E / m (for m >> h; here h = 0, 8 hull sites).
    double previousPerSite = std::numeric_limits<double>::infinity();
    double previousPerVertex = previousPerSite;
    for (std::int64_t m : {100, 200, 500, 1000, 2000, 5000, 10000, 20000}) {
        const double r = estimateCircumradius(512, 512, 2 * m - 2 - 8);
        const ErrorEstimate e = estimateErrors(m, 0, r, 512);
        EXPECT_LT(e.e / double(m), previousPerSite) << m;
        EXPECT_LT(e.e1 + e.e2, previousPerVertex) << m;
        previousPerSite = e.e / double(m);
        previousPerVertex = e.e1 + e.e2;
    }
}

TEST(JfaErrorEstimate, CircumradiusOfTheEquilateralTriangle) {
    // Side 2: area sqrt 3, circumradius 2 / sqrt 3.
    EXPECT_NEAR(circumradiusFromArea(std::sqrt(3.0)), 2.0 / std::sqrt(3.0), 1e-15);
    EXPECT_EQ(circumradiusFromArea(0.0), 0.0);
    EXPECT_EQ(circumradiusFromArea(-1.0), 0.0);
    EXPECT_EQ(circumradiusFromArea(std::nan("")), 0.0);
    // 512 x 512 with 1998 - 10 triangles: A = 131.87, R = 12.33.
    EXPECT_NEAR(estimateCircumradius(512, 512, 1988),
                std::sqrt(4.0 * 262144.0 / 1988.0 / (3.0 * std::sqrt(3.0))), 1e-12);
    EXPECT_EQ(estimateCircumradius(512, 512, 0), 0.0);
}

// ---- convex hull --------------------------------------------------------------------------------

TEST(JfaHull, SquareWithEdgePointsCentreAndDuplicates) {
    std::vector<IntPoint> pts;
    for (int y = 0; y <= 2; ++y)
        for (int x = 0; x <= 2; ++x) pts.push_back({x, y});
    pts.push_back({2, 2}); // duplicates
    pts.push_back({0, 0});
    const std::vector<IntPoint> corners{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    EXPECT_EQ(convexHull(pts), corners);
    const std::vector<IntPoint> boundary{{0, 0}, {1, 0}, {2, 0}, {2, 1},
                                         {2, 2}, {1, 2}, {0, 2}, {0, 1}};
    EXPECT_EQ(convexHull(pts, HullBoundary::KeepCollinear), boundary);
    EXPECT_EQ(triangulationTriangleCount(pts), 8); // 4 unit squares, 2 triangles each
}

TEST(JfaHull, CollinearAndTinyInputs) {
    const std::vector<IntPoint> line{{4, 4}, {0, 0}, {2, 2}, {2, 2}, {1, 1}, {3, 3}};
    EXPECT_EQ(convexHull(line), (std::vector<IntPoint>{{0, 0}, {4, 4}}));
    EXPECT_EQ(convexHull(line, HullBoundary::KeepCollinear),
              (std::vector<IntPoint>{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}}));
    EXPECT_EQ(triangulationTriangleCount(line), 0);
    EXPECT_TRUE(convexHull(std::vector<IntPoint>{}).empty());
    EXPECT_EQ(convexHull(std::vector<IntPoint>{{5, 5}, {5, 5}}).size(), 1u);
    EXPECT_EQ(triangulationTriangleCount(std::vector<IntPoint>{{0, 0}, {1, 0}}), 0);
    EXPECT_EQ(triangulationTriangleCount(std::vector<IntPoint>{{0, 0}, {1, 0}, {0, 1}}), 1);
    // Vertical runs at both ends (the monotone chain's tricky case).
    const std::vector<IntPoint> box{{0, 0}, {0, 1}, {0, 2}, {5, 0}, {5, 1}, {5, 2}, {2, 1}};
    EXPECT_EQ(convexHull(box, HullBoundary::KeepCollinear),
              (std::vector<IntPoint>{{0, 0}, {5, 0}, {5, 1}, {5, 2}, {0, 2}, {0, 1}}));
    EXPECT_EQ(triangulationTriangleCount(box), 2 * 7 - 2 - 6);
    const std::vector<RealPoint> real{{0.5, 0.25}, {1.5, 0.75}, {2.5, 1.25}, {0.5, 3.0}};
    EXPECT_EQ(convexHull(real).size(), 3u);
    EXPECT_EQ(convexHull(real, HullBoundary::KeepCollinear).size(), 4u);
    EXPECT_EQ(triangulationTriangleCount(real), 2);
    EXPECT_THROW((void)convexHull(std::vector<IntPoint>{{std::int64_t(1) << 30, 0}}),
                 std::invalid_argument);
    EXPECT_EQ(orientation(IntPoint{0, 0}, IntPoint{1, 0}, IntPoint{0, 1}), 1);
    EXPECT_EQ(orientation(RealPoint{0, 0}, RealPoint{0, 1}, RealPoint{1, 0}), -1);
}

TEST(JfaHull, RealOrientationIsExactWhereNaiveDoublesFail) {
    // a = (0.5 + i u, 0.5 + j u), u = 2^-53 (the ulp at 0.5), b = (12, 12), c = (24, 24):
    // det = 12 u (j - i) exactly, far below the rounding error of a plain double evaluation.
    const double u = std::ldexp(1.0, -53);
    int naiveWrong = 0;
    for (int i = 0; i < 32; ++i) {
        for (int j = 0; j < 32; ++j) {
            const RealPoint a{0.5 + i * u, 0.5 + j * u}, b{12, 12}, c{24, 24};
            const int expected = (j > i) - (j < i);
            EXPECT_EQ(orientation(a, b, c), expected) << i << "," << j;
            const double naive = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
            naiveWrong += ((naive > 0) - (naive < 0)) != expected ? 1 : 0;
        }
    }
    EXPECT_GT(naiveWrong, 0); // the case is a real test of exactness
    EXPECT_THROW((void)orientation(RealPoint{std::nan(""), 0}, RealPoint{}, RealPoint{1, 1}),
                 std::invalid_argument);
}

// Brute force: p is a corner iff no closed triangle or segment of other points holds it; p is on
// the boundary iff it lies on a line through two points with every point on its left or on it.
TEST(JfaHull, MatchesBruteForceOnRandomSmallSets) {
    using PointSet = std::set<std::pair<std::int64_t, std::int64_t>>;
    std::mt19937 rng(7);
    for (int trial = 0; trial < 300; ++trial) {
        std::uniform_int_distribution<int> coord(0, 4), count(1, 12);
        std::vector<IntPoint> pts(std::size_t(count(rng)));
        for (IntPoint& p : pts) p = {coord(rng), coord(rng)};
        PointSet distinct, corners, boundary, gotCorners, gotBoundary;
        for (const IntPoint& p : pts) distinct.insert({p.x, p.y});
        std::vector<IntPoint> u;
        for (const auto& [x, y] : distinct) u.push_back({x, y});
        const auto within = [](std::int64_t a, std::int64_t b, std::int64_t v) {
            return std::min(a, b) <= v && v <= std::max(a, b);
        };
        for (const IntPoint& p : u) {
            bool inside = false;
            for (const IntPoint& a : u)
                for (const IntPoint& b : u)
                    for (const IntPoint& c : u) {
                        if (a == p || b == p || c == p || inside) continue;
                        const int o1 = orientation(a, b, p), o2 = orientation(b, c, p),
                                  o3 = orientation(c, a, p);
                        inside = (orientation(a, b, c) != 0 && ((o1 >= 0 && o2 >= 0 && o3 >= 0) ||
                                                                (o1 <= 0 && o2 <= 0 && o3 <= 0))) ||
                                 (o1 == 0 && within(a.x, b.x, p.x) && within(a.y, b.y, p.y));
                    }
            if (!inside) corners.insert({p.x, p.y});
            for (const IntPoint& a : u)
                for (const IntPoint& b : u) {
                    bool leftOrOn = !(a == b);
                    for (const IntPoint& q : u) leftOrOn = leftOrOn && orientation(a, b, q) >= 0;
                    if (leftOrOn && orientation(a, b, p) == 0) boundary.insert({p.x, p.y});
                }
        }
        const std::vector<IntPoint> h = convexHull(pts);
        for (const IntPoint& p : h) gotCorners.insert({p.x, p.y});
        for (const IntPoint& p : convexHull(pts, HullBoundary::KeepCollinear))
            gotBoundary.insert({p.x, p.y});
        ASSERT_EQ(gotCorners, corners) << "trial " << trial;
        if (corners.size() <= 2) { // collinear (or tiny): the whole segment, no triangle
            ASSERT_EQ(gotBoundary, distinct) << "trial " << trial;
            ASSERT_EQ(triangulationTriangleCount(pts), 0);
            continue;
        }
        ASSERT_EQ(gotBoundary, boundary) << "trial " << trial;
        ASSERT_EQ(convexHull(pts, HullBoundary::KeepCollinear).size(), boundary.size());
        ASSERT_EQ(triangulationTriangleCount(pts),
                  std::int64_t(2 * u.size() - 2 - boundary.size()));
        for (std::size_t i = 0; i < h.size(); ++i) // strictly counter-clockwise corners
            ASSERT_EQ(orientation(h[i], h[(i + 1) % h.size()], h[(i + 2) % h.size()]), 1);
    }
}

// ---- degenerate inputs and the report line ------------------------------------------------------

TEST(JfaErrorReport, DegenerateSiteCountsGiveNoNaN) {
    for (int m = 0; m <= 2; ++m) {
        std::vector<Cell> sites;
        for (int i = 0; i < m; ++i) sites.push_back(site(float(2 + 5 * i), float(3 + i), i));
        const Diagram d(8, 8, sites);
        Grid flooded = d.winners;
        if (m > 0) flooded.at(7, 7) = kEmptyCell;
        const ErrorReport r = analyzeErrors(flooded, d.view());
        EXPECT_EQ(r.m, m);
        EXPECT_EQ(r.errorPixels, m > 0 ? 1 : 0);
        EXPECT_EQ(r.delaunayTriangles, 0);
        EXPECT_EQ(r.r, 0.0);
        EXPECT_EQ(r.estimate.e, 0.0);
        EXPECT_EQ(r.h, m);
        const std::string line = r.describe();
        EXPECT_EQ(line.find("nan"), std::string::npos) << line;
        EXPECT_EQ(line.find("inf"), std::string::npos) << line;
        std::cout << line << "\n";
    }
    // No sites: an empty flood is correct, a non-empty cell is not.
    const Diagram none(4, 4, {});
    Grid flooded = none.winners;
    flooded.at(1, 1) = site(1, 1, 0);
    EXPECT_EQ(analyzeErrors(flooded, none.view()).errorPixels, 1);
}

TEST(JfaErrorReport, DescribeFormat) {
    ErrorReport r;
    r.width = r.height = 512;
    r.sites = 1000;
    r.errorPixels = 37;
    r.clusters = 31;
    r.singles = 29;
    r.singlesAtVertices = 28;
    r.singleVertexShare = 28.0 / 29.0;
    r.estimate.e = 33.1;
    r.r = 9.7;
    EXPECT_EQ(r.describe(), "JFA 512x512, 1000 sites: 37 error pixels in 31 clusters (29 single, "
                            "28 at Voronoi vertices = 96.6%); estimate E = 33.1 (R = 9.7 px)");
    r.singles = r.singlesAtVertices = 0;
    EXPECT_NE(r.describe().find("= n/a"), std::string::npos);
}

// ---- end to end: CPU kernel on random sites -----------------------------------------------------

constexpr int kSize = 512;

// One random integer-site input: its seed grid, exact field and site cells.
struct Input {
    Grid seeds;
    ExactField exact;
    std::vector<Cell> cells;
    Input(int count, std::uint64_t seed)
        : seeds(seedPoints(randomIntegerSites(count, kSize, kSize, seed), kSize, kSize, true).grid),
          exact(exactNearest(seeds, NearestSite{true})), cells(siteCells(seeds)) {}
    [[nodiscard]] ExactDiagramView view() const {
        return {kSize, kSize, cells, exact.distSq, true};
    }
};

// Floods `input` with `plan`, analyses it and cross-checks the error count with Reference.h.
ErrorReport run(const Plan& plan, const Input& input) {
    const Grid flooded = flood(plan, input.seeds, NearestSite{true});
    ErrorReport report = analyzeErrors(flooded, input.view(), plan.name());
    EXPECT_EQ(report.errorPixels, countErrors(flooded, input.exact, NearestSite{true}))
        << plan.name();
    return report;
}

// Property 4.1 away from the border: every interior single error is at a Voronoi vertex.
// Measured: 0 exceptions in 600 JFA runs (100/1000/10000 sites, seeds 1..200) and 480 runs of the
// variants; off-vertex singles all sat on the grid border, where a site can be "killed by the
// boundary" (ErrorAnalysis.h).
void expectInteriorSinglesAtVertices(const ErrorReport& r) {
    EXPECT_EQ(r.interiorSinglesAtVertices, r.interiorSingles) << r.describe();
    for (const IntPoint& p : r.singlesOffVertices) {
        const bool border = p.x == 0 || p.y == 0 || p.x == r.width - 1 || p.y == r.height - 1;
        EXPECT_TRUE(border) << r.label << ": interior single error at (" << p.x << ", " << p.y
                            << ") is not at a Voronoi vertex";
    }
}

TEST(JfaErrorsEndToEnd, JfaMeasuredVersusEstimate) {
    // The thesis' experiment (§4.5) in small: JFA on 512x512 with 100, 1000 and 10000 random
    // integer sites, three seeds each, measured errors printed beside E. E is not asserted: it
    // is a lower-bound-style estimate (it ignores border effects and clusters). Measured means
    // over seeds 1..200: 4.9 error pixels vs E = 1.8 (100 sites), 25.1 vs 17.9 (1000), 160.3 vs
    // 96.6 (10000) -- close below ~3000 sites and an underestimate above, as §4.5.2 reports.
    for (const int count : {100, 1000, 10000}) {
        std::int64_t errors = 0, singles = 0, atVertices = 0;
        double estimate = 0.0;
        for (const std::uint64_t seed : {1u, 2u, 3u}) {
            const Input input(count, seed);
            const ErrorReport r = run(Plan::jfa(kSize, kSize), input);
            std::cout << "seed " << seed << ": " << r.describe() << "\n";
            expectInteriorSinglesAtVertices(r);
            EXPECT_EQ(r.m, count);
            EXPECT_GT(r.delaunayTriangles, 0);
            EXPECT_TRUE(std::isfinite(r.estimate.e) && r.estimate.e > 0.0);
            errors += r.errorPixels;
            singles += r.singles;
            atVertices += r.singlesAtVertices;
            estimate += r.estimate.e;
        }
        std::printf("%5d sites: mean %.1f error pixels, mean E = %.1f; %lld of %lld singles at "
                    "vertices\n",
                    count, double(errors) / 3.0, estimate / 3.0, static_cast<long long>(atVertices),
                    static_cast<long long>(singles));
        // Share of all singles (border ones included) at vertices, pooled over three seeds.
        // Measured over seeds 1..60 in triples: min 0.836 (1000 sites), min 0.950 (10000 sites;
        // per run min 0.922). 100 sites have too few singles (about 2 per run) for a bound.
        const double minShare = count == 1000 ? 0.7 : count == 10000 ? 0.9 : 0.0;
        EXPECT_GE(double(atVertices), minShare * double(singles)) << count << " sites";
    }
}

TEST(JfaErrorsEndToEnd, VariantsHaveFewerErrorsThanJfa) {
    // JFA+1, JFA+2 and JFA^2 run JFA's passes and then more; an extra pass never breaks a correct
    // grid point (it reads itself), so their error pixels are a subset of JFA's. 1+JFA is not an
    // extension of JFA; measured (40 seeds per count) it always had far fewer errors (mean 0.7 vs
    // 26.1 at 1000 sites, 0.25 vs 158.5 at 10000), so a strict inequality per input is safe.
    for (const int count : {1000, 10000}) {
        for (const std::uint64_t seed : {1u, 2u}) {
            const Input input(count, seed);
            const Grid jfaGrid = flood(Plan::jfa(kSize, kSize), input.seeds, NearestSite{true});
            const std::vector<std::uint8_t> jfaMask = errorPixelMask(jfaGrid, input.view());
            const ErrorReport jfa = analyzeErrors(jfaGrid, input.view(), "JFA");
            std::cout << jfa.describe() << "\n";
            ASSERT_GT(jfa.errorPixels, 0);
            for (const Plan& plan :
                 {Plan::jfaPlus(1, kSize, kSize), Plan::jfaPlus(2, kSize, kSize),
                  Plan::jfaSquared(kSize, kSize), Plan::onePlusJfa(kSize, kSize)}) {
                const Grid flooded = flood(plan, input.seeds, NearestSite{true});
                const ErrorReport r = analyzeErrors(flooded, input.view(), plan.name());
                std::cout << r.describe() << "\n";
                EXPECT_LT(r.errorPixels, jfa.errorPixels) << plan.name();
                expectInteriorSinglesAtVertices(r);
                if (plan.name() == "1+JFA") continue;
                const std::vector<std::uint8_t> mask = errorPixelMask(flooded, input.view());
                for (std::size_t i = 0; i < mask.size(); ++i)
                    ASSERT_LE(mask[i], jfaMask[i]) << plan.name() << " broke texel " << i;
            }
        }
    }
}

TEST(JfaErrorsEndToEnd, SubPixelSitesAndReferenceAgree) {
    // Float sites: the analysis uses NearestSite's float arithmetic; its error count must equal
    // Reference.h's countErrors, and the report must be finite. (No vertex-share bound: float
    // rounding and sites lost to shared pixels make sub-pixel diagrams a different experiment.)
    const NearestSite criterion{false};
    const Grid seeds =
        seedPoints(randomFloatSites(1000, kSize, kSize, 5), kSize, kSize, false).grid;
    const ExactField exact = exactNearest(seeds, criterion);
    const std::vector<Cell> cells = siteCells(seeds);
    const Grid flooded = flood(Plan::jfa(kSize, kSize), seeds, criterion);
    const ErrorReport r =
        analyzeErrors(flooded, {kSize, kSize, cells, exact.distSq, false}, "JFA (sub-pixel)");
    std::cout << r.describe() << "\n";
    EXPECT_EQ(r.errorPixels, countErrors(flooded, exact, criterion));
    EXPECT_GT(r.errorPixels, 0);
    EXPECT_TRUE(std::isfinite(r.r) && r.r > 0.0);
    EXPECT_TRUE(std::isfinite(r.estimate.e) && r.estimate.e > 0.0);
}

} // namespace
} // namespace fl::jfa
