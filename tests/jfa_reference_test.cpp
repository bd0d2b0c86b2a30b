// Exact references (jfa/Reference.h): the integer EDT and the bucket search agree with brute
// force on random inputs; error counting treats ties as correct.
#include <jfa/CpuKernel.h>
#include <jfa/Reference.h>
#include <jfa/Sites.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace fl::jfa {
namespace {

Cell site(float x, float y, int id) {
    return Cell{x, y, float(id), 0.0f};
}

// Every recorded site is at the recorded distance.
void expectConsistent(const ExactField& field, const NearestSite& crit) {
    for (int y = 0; y < field.nearest.height; ++y) {
        for (int x = 0; x < field.nearest.width; ++x) {
            ASSERT_EQ(squaredDistance(crit, x, y, field.nearest.at(x, y)), field.at(x, y))
                << x << ", " << y;
        }
    }
}

TEST(Reference, IntegerEdtMatchesBruteForceDistances) {
    const std::vector<std::tuple<int, int, int>> cases{
        {1, 1, 1},    {7, 1, 2},     {1, 9, 3},    {2, 2, 4},      {16, 16, 1},  {31, 17, 5},
        {40, 30, 60}, {64, 48, 300}, {33, 9, 200}, {50, 50, 2500}, {128, 3, 10}, {5, 77, 9}};
    const NearestSite crit{true};
    std::uint64_t seed = 100;
    for (auto [w, h, count] : cases) {
        for (int rep = 0; rep < 3; ++rep, ++seed) {
            const Grid seeds = seedPoints(randomIntegerSites(count, w, h, seed), w, h, true).grid;
            const ExactField edt = exactIntegerEdt(seeds);
            const ExactField brute = bruteForceNearest(seeds, crit);
            ASSERT_EQ(edt.distSq, brute.distSq) << w << "x" << h << ", " << count << " sites";
            expectConsistent(edt, crit);
        }
    }
}

TEST(Reference, IntegerEdtOfMasksAndLabels) {
    // Generalized sites: a ring of pixels and a bar, labelled 1 and 2.
    const int w = 41, h = 29;
    std::vector<std::uint8_t> mask(std::size_t(w * h), 0);
    std::vector<std::int32_t> labels(mask.size(), 0);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double r = std::hypot(x - 12.0, y - 14.0);
            const std::size_t i = std::size_t(y * w + x);
            const int label = (r > 6.0 && r < 8.0) ? 1 : (x == 33 && y > 4 && y < 25) ? 2 : 0;
            mask[i] = label > 0 ? 1 : 0;
            labels[i] = label;
        }
    }
    const Grid seeds = seedMask(mask, w, h, &labels);
    const ExactField edt = exactIntegerEdt(seeds);
    EXPECT_EQ(edt.distSq, bruteForceNearest(seeds, NearestSite{true}).distSq);
    expectConsistent(edt, NearestSite{true});
    EXPECT_EQ(edt.at(33, 10), 0.0);
    EXPECT_EQ(edt.at(33, 0), 25.0);
}

TEST(Reference, SearchMatchesBruteForceExactly) {
    // Same nearest site (NearestSite's tie rule) and same distance at every grid point.
    const std::vector<std::tuple<int, int, int>> cases{
        {1, 1, 1}, {9, 1, 3}, {1, 9, 3}, {20, 20, 1}, {37, 23, 40}, {64, 48, 500}, {30, 30, 900}};
    std::uint64_t seed = 7;
    for (bool integer : {true, false}) {
        const NearestSite crit{integer};
        for (auto [w, h, count] : cases) {
            for (int rep = 0; rep < 3; ++rep, ++seed) {
                const std::vector<Site> sites = integer ? randomIntegerSites(count, w, h, seed)
                                                        : randomFloatSites(count, w, h, seed);
                const Grid seeds = seedPoints(sites, w, h, integer).grid;
                const ExactField search = exactNearestSearch(seeds, crit);
                const ExactField brute = bruteForceNearest(seeds, crit);
                ASSERT_EQ(search.nearest, brute.nearest) << w << "x" << h << " " << integer;
                ASSERT_EQ(search.distSq, brute.distSq);
                expectConsistent(search, crit);
            }
        }
    }
}

TEST(Reference, SearchHandlesClusteredAndOutlyingSites) {
    // Sites far outside the grid (allowed in a seed cell: the grid position is only where a
    // flood starts), a tight cluster, and float sites on half-integers (many exact ties).
    Grid seeds(30, 20);
    seeds.at(0, 0) = site(-40.0f, -3.5f, 0);
    seeds.at(29, 19) = site(70.25f, 90.0f, 1);
    for (int i = 0; i < 12; ++i)
        seeds.at(10 + i % 4, 10 + i / 4) = site(10.5f + i % 4, 10.5f, 2 + i);
    seeds.at(5, 15) = site(5.5f, 15.5f, 20);
    const NearestSite crit{false};
    const ExactField search = exactNearestSearch(seeds, crit);
    const ExactField brute = bruteForceNearest(seeds, crit);
    EXPECT_EQ(search.nearest, brute.nearest);
    EXPECT_EQ(search.distSq, brute.distSq);
    EXPECT_EQ(exactNearest(seeds, crit).nearest, brute.nearest);
}

TEST(Reference, ExactNearestUsesTheEdtForIntegerSitesInsideTheGrid) {
    const Grid seeds = seedPoints(randomIntegerSites(50, 40, 40, 3), 40, 40, true).grid;
    EXPECT_EQ(exactNearest(seeds, NearestSite{true}).distSq, exactIntegerEdt(seeds).distSq);
    // Integer sites outside the grid go to the search.
    Grid outside(10, 10);
    outside.at(0, 0) = site(-5.0f, 0.0f, 0);
    outside.at(9, 9) = site(12.0f, 9.0f, 1);
    EXPECT_THROW(exactIntegerEdt(outside), std::invalid_argument);
    EXPECT_EQ(exactNearest(outside, NearestSite{true}).nearest,
              bruteForceNearest(outside, NearestSite{true}).nearest);
    Grid fractional(4, 4);
    fractional.at(1, 1) = site(1.5f, 1.0f, 0);
    EXPECT_THROW(exactIntegerEdt(fractional), std::invalid_argument);
}

TEST(Reference, NoSitesGiveAnEmptyField) {
    for (const ExactField& f : {exactIntegerEdt(Grid(5, 3)), bruteForceNearest(Grid(5, 3), {}),
                                exactNearestSearch(Grid(5, 3), NearestSite{false})}) {
        EXPECT_EQ(f.nearest, Grid(5, 3, kEmptyCell));
        for (double d : f.distSq) EXPECT_EQ(d, std::numeric_limits<double>::infinity());
    }
    const ExactField none = exactIntegerEdt(Grid(5, 3));
    EXPECT_EQ(countErrors(Grid(5, 3), none, NearestSite{}), 0);
    Grid stray(5, 3);
    stray.at(2, 2) = site(0.0f, 0.0f, 0);
    EXPECT_EQ(countErrors(stray, none, NearestSite{}), 1);
}

TEST(Reference, CountErrorsComparesDistancesSoTiesAreCorrect) {
    // Sites at x = 0 (id 0) and x = 4 (id 1) on 5x1: x = 2 is a tie.
    Grid seeds(5, 1);
    seeds.at(0, 0) = site(0.0f, 0.0f, 0);
    seeds.at(4, 0) = site(4.0f, 0.0f, 1);
    const NearestSite crit{true};
    const ExactField exact = exactNearest(seeds, crit);
    Grid flooded(5, 1);
    for (int x = 0; x < 5; ++x) flooded.at(x, 0) = x < 2 ? seeds.at(0, 0) : seeds.at(4, 0);
    EXPECT_EQ(countErrors(flooded, exact, crit), 0); // x = 2 holds id 1: a tie, correct
    flooded.at(3, 0) = seeds.at(0, 0);               // 3 from site 0, 1 from site 1
    flooded.at(4, 0) = kEmptyCell;
    EXPECT_FALSE(isCorrect(flooded, exact, 3, 0, crit));
    EXPECT_FALSE(isCorrect(flooded, exact, 4, 0, crit));
    EXPECT_TRUE(isCorrect(flooded, exact, 2, 0, crit));
    EXPECT_EQ(countErrors(flooded, exact, crit), 2);
    EXPECT_EQ(errorMask(flooded, exact, crit), (std::vector<std::uint8_t>{0, 0, 0, 1, 1}));
    EXPECT_THROW(countErrors(Grid(4, 1), exact, crit), std::invalid_argument);
}

TEST(Reference, FloatDistancesUseNearestSiteArithmetic) {
    // The stored distance is NearestSite::squaredFloat exactly, not a double recomputation.
    Grid seeds(3, 1);
    seeds.at(1, 0) = site(1.1f, 0.3f, 0);
    const ExactField exact = exactNearestSearch(seeds, NearestSite{false});
    for (int x = 0; x < 3; ++x)
        EXPECT_EQ(exact.at(x, 0), double(NearestSite::squaredFloat(x, 0, seeds.at(1, 0))));
    Grid flooded(3, 1, seeds.at(1, 0));
    EXPECT_EQ(countErrors(flooded, exact, NearestSite{false}), 0);
}

TEST(Reference, SiteCellsAreTheNonEmptyCellsInRowMajorOrder) {
    Grid seeds(3, 2);
    seeds.at(2, 0) = site(2.0f, 0.0f, 4);
    seeds.at(0, 1) = site(0.0f, 1.0f, 1);
    seeds.at(1, 1) = Cell{7.0f, 7.0f, -2.0f, 0.0f}; // empty, whatever it holds
    EXPECT_EQ(siteCells(seeds), (std::vector<Cell>{seeds.at(2, 0), seeds.at(0, 1)}));
}

} // namespace
} // namespace fl::jfa
