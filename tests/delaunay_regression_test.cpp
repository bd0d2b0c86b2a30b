// Regression fixtures of the Delaunay pipeline (geometry/Delaunay.h), each named after the bug it
// reproduces, at sizes small enough for a unit test. The work counters (C3's walk steps and
// flips, C4's flips) are deterministic, so a bound on them catches a return of quadratic
// behaviour without timing anything.
#include <geometry/Delaunay.h>

#include <jfa/Sites.h>

#include "TriangleSet.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace fl::geom {
namespace {

using glm::dvec2;
using test::triangleSet;

DelaunayResult run(const std::vector<dvec2>& points, int size) {
    DelaunayOptions options;
    options.discrete.size = size;
    options.check = true; // throws if the result is not the Delaunay triangulation
    return delaunay(points, options);
}

// The bench's kuzmin disc: heavy-tailed, so the bounding box is huge and nearly every site
// shares the few centre pixels.
std::vector<dvec2> kuzmin(std::size_t n, std::uint64_t seed) {
    jfa::SplitMix64 rng(seed);
    std::vector<dvec2> pts(n);
    for (dvec2& p : pts) {
        const double u = rng.unit(), v = rng.unit();
        const double r = std::sqrt(1.0 / ((1.0 - u) * (1.0 - u)) - 1.0);
        p = dvec2(r * std::cos(2.0 * std::numbers::pi * v),
                  r * std::sin(2.0 * std::numbers::pi * v));
    }
    return pts;
}

// The bench's two-lines: half on y = x, half on y = 1 - x, exactly collinear.
std::vector<dvec2> twoLines(std::size_t n, std::uint64_t seed) {
    jfa::SplitMix64 rng(seed);
    std::vector<dvec2> pts(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double u = rng.unit();
        pts[i] = dvec2(u, i % 2 == 0 ? u : 1.0 - u);
    }
    return pts;
}

// Linear work: per inserted site a bounded number of walk steps and flips (the expected values
// of a randomized incremental insertion are small constants; the bounds leave a wide margin).
void expectLinearWork(const DelaunayResult& r, std::size_t n) {
    const std::size_t inserted = std::max<std::size_t>(r.counts.missingInserted, 1);
    EXPECT_LT(r.counts.walkSteps, 40 * inserted) << "C3 walks";
    EXPECT_LT(r.counts.insertFlips + r.counts.flips, 12 * n) << "C3 + C4 flips";
}

// Bug: C3 inserted the missing sites without flips, each located from the site that kept its
// pixel, in pixel order. On kuzmin nearly all sites share the centre pixels, so each walk
// crossed a fan of ever thinner triangles: quadratic C3 (12.5 s at 100k points).
TEST(DelaunayRegression, KuzminSitesCrowdingOnePixelInsertInLinearWork) {
    const std::vector<dvec2> pts = kuzmin(6000, 3);
    const DelaunayResult r = run(pts, 64);
    EXPECT_EQ(r.counts.rebuilds, 0u);
    EXPECT_GT(r.counts.missingInserted, 3000u); // the crowding the bug needs
    expectLinearWork(r, pts.size());
    EXPECT_EQ(triangleSet(r.mesh.triangles), triangleSet(delaunayReference(pts).triangles));
}

// Bug: on two crossing lines of exactly collinear sites the flip-free C3 left long skinny fans
// that C4 undid with cascades of flips: 319M flips at 100k points.
TEST(DelaunayRegression, TwoCrossingLinesNeedNoFlipCascades) {
    const std::vector<dvec2> pts = twoLines(6000, 4);
    for (const int size : {32, 128}) {
        const DelaunayResult r = run(pts, size);
        EXPECT_EQ(r.counts.rebuilds, 0u) << "size " << size;
        EXPECT_GT(r.counts.missingInserted, 4000u) << "size " << size;
        expectLinearWork(r, pts.size());
    }
}

// The same for a gaussian cloud at a texture far too small: many sites per pixel everywhere.
TEST(DelaunayRegression, OvercrowdedPixelsOfAGaussianCloudInsertInLinearWork) {
    jfa::SplitMix64 rng(9);
    std::vector<dvec2> pts(6000);
    for (dvec2& p : pts) {
        const double r = std::sqrt(-2.0 * std::log(1.0 - rng.unit()));
        const double a = 2.0 * std::numbers::pi * rng.unit();
        p = dvec2(r * std::cos(a), r * std::sin(a));
    }
    const DelaunayResult r = run(pts, 16);
    expectLinearWork(r, pts.size());
    EXPECT_EQ(triangleSet(r.mesh.triangles), triangleSet(delaunayReference(pts).triangles));
}

// Bug (issue 16): `delaunay` crashed in snapSites when the points' extent was tiny (1e-307 ..
// 1e-309): (N-1) / extent overflowed and a NaN pixel index wrote outside the texture. Every
// finite extent must now triangulate, subnormal and huge ones included, and exactly (check).
TEST(DelaunayRegression, SnapOfSubnormalExtentDoesNotCrash) {
    for (const double unit : {1e-305, 1e-307, 1e-308, 1e-309, 1e-320, 5e-324, 1.0, 1e300}) {
        jfa::SplitMix64 rng(16);
        std::vector<dvec2> pts(400);
        for (dvec2& p : pts) p = dvec2(rng.unit(), rng.unit()) * (1000.0 * unit);
        // Subnormal coordinates have few bits: duplicates and cocircular points are common, so
        // the exact checker (run's options.check) is the judge, not a triangle set.
        const DelaunayResult r = run(pts, 64);
        EXPECT_EQ(r.mesh.points.size(), pts.size()) << "unit " << unit;
    }
    // Three points around the smallest normal double, in a box of a few subnormal ulps.
    const double m = std::numeric_limits<double>::min();
    const std::vector<dvec2> tiny{{m, m}, {std::nextafter(m, 1.0), m}, {m, std::nextafter(m, 0.0)}};
    EXPECT_EQ(run(tiny, 16).mesh.triangles.size(), 3u);
}

} // namespace
} // namespace fl::geom
