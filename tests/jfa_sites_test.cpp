// Seeding (jfa/Sites.h): rounding to pixels, collisions and the missing list, rejected sites,
// generalized sites from masks and labels, and the deterministic random point sets.
#include <jfa/NearestSite.h>
#include <jfa/Sites.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace fl::jfa {
namespace {

int nonEmpty(const Grid& g) {
    int n = 0;
    for (const Cell& c : g.cells) n += NearestSite{}.empty(c) ? 0 : 1;
    return n;
}

std::string invalidArgumentMessage(const std::vector<Site>& sites, int w, int h) {
    try {
        seedPoints(sites, w, h, true);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return {};
}

TEST(Sites, PixelOfRoundsHalvesUp) {
    EXPECT_EQ(pixelOf(0.0f), 0);
    EXPECT_EQ(pixelOf(0.49999997f), 0);
    EXPECT_EQ(pixelOf(0.5f), 1);
    EXPECT_EQ(pixelOf(2.5f), 3);
    EXPECT_EQ(pixelOf(-0.5f), 0);
    EXPECT_EQ(pixelOf(-0.50000006f), -1);
    EXPECT_EQ(pixelOf(1e30f), 4000000000000000000LL);
    EXPECT_THROW(pixelOf(std::numeric_limits<float>::quiet_NaN()), std::invalid_argument);
}

TEST(Sites, IntegerSitesAreStoredRoundedFloatSitesExactly) {
    const std::vector<Site> sites{{1.4f, 2.6f}, {3.0f, 0.0f}, {0.5f, -0.5f}};
    const SeedResult integer = seedPoints(sites, 5, 4, true);
    EXPECT_EQ(integer.grid.at(1, 3), (Cell{1.0f, 3.0f, 0.0f, 0.0f}));
    EXPECT_EQ(integer.grid.at(3, 0), (Cell{3.0f, 0.0f, 1.0f, 0.0f}));
    EXPECT_EQ(integer.grid.at(1, 0), (Cell{1.0f, 0.0f, 2.0f, 0.0f}));
    EXPECT_EQ(nonEmpty(integer.grid), 3);
    EXPECT_TRUE(integer.missing.empty());

    const SeedResult sub = seedPoints(sites, 5, 4, false);
    EXPECT_EQ(sub.grid.at(1, 3), (Cell{1.4f, 2.6f, 0.0f, 0.0f}));
    EXPECT_EQ(sub.grid.at(1, 0), (Cell{0.5f, -0.5f, 2.0f, 0.0f}));
    EXPECT_EQ(sub.grid.width, 5);
    EXPECT_EQ(sub.grid.height, 4);
}

TEST(Sites, CollisionsKeepTheBetterSiteAndReportTheOthers) {
    // Integer sites: all three round to pixel (2, 2) and are equally near; the smallest id wins.
    const std::vector<Site> same{{5.0f, 5.0f}, {2.2f, 1.9f}, {2.0f, 2.0f}, {1.6f, 2.4f}};
    const SeedResult integer = seedPoints(same, 8, 8, true);
    EXPECT_EQ(integer.grid.at(2, 2), (Cell{2.0f, 2.0f, 1.0f, 0.0f}));
    EXPECT_EQ(integer.missing, (std::vector<int>{2, 3}));
    EXPECT_EQ(nonEmpty(integer.grid), 2);

    // Sub-pixel sites: the one nearest to the pixel's grid point wins; here site 2 (exactly on
    // it), whatever the order.
    const SeedResult sub = seedPoints(same, 8, 8, false);
    EXPECT_EQ(sub.grid.at(2, 2), (Cell{2.0f, 2.0f, 2.0f, 0.0f}));
    EXPECT_EQ(sub.missing, (std::vector<int>{1, 3}));

    // Sub-pixel tie (all 0.25 from the grid point): the smallest id wins.
    const SeedResult tie = seedPoints({{4.25f, 4.0f}, {4.0f, 3.75f}, {3.75f, 4.0f}}, 8, 8, false);
    EXPECT_EQ(tie.grid.at(4, 4).z, 0.0f);
    EXPECT_EQ(tie.missing, (std::vector<int>{1, 2}));
}

TEST(Sites, SitesOutsideTheGridAreRejectedByIndex) {
    EXPECT_NE(invalidArgumentMessage({{0.0f, 0.0f}, {4.5f, 0.0f}}, 5, 3).find("site 1"),
              std::string::npos);
    EXPECT_NE(
        invalidArgumentMessage({{1.0f, 1.0f}, {0.0f, 0.0f}, {0.0f, -0.51f}}, 5, 3).find("site 2"),
        std::string::npos);
    EXPECT_NE(invalidArgumentMessage({{std::numeric_limits<float>::infinity(), 0.0f}}, 5, 3)
                  .find("site 0"),
              std::string::npos);
    EXPECT_NE(invalidArgumentMessage({{0.0f, std::numeric_limits<float>::quiet_NaN()}}, 5, 3)
                  .find("site 0"),
              std::string::npos);
    // The last pixel's far edge is outside, its near edge inside.
    EXPECT_NO_THROW(seedPoints({{4.49f, 2.49f}, {-0.5f, -0.5f}}, 5, 3, true));
    EXPECT_THROW(seedPoints({}, 0, 3, true), std::invalid_argument);
}

TEST(Sites, EmptySiteListGivesAnEmptyGrid) {
    const SeedResult none = seedPoints({}, 3, 2, true);
    EXPECT_EQ(none.grid, Grid(3, 2));
    EXPECT_TRUE(none.missing.empty());
}

TEST(Sites, MaskPixelsBecomeSeedsAtTheirOwnPositions) {
    // 4x3 mask, row 0 first.
    const std::vector<std::uint8_t> mask{0, 1, 0, 0,   //
                                         0, 0, 0, 255, //
                                         1, 0, 0, 0};
    const Grid one = seedMask(mask, 4, 3);
    EXPECT_EQ(one.at(1, 0), (Cell{1.0f, 0.0f, 0.0f, 0.0f}));
    EXPECT_EQ(one.at(3, 1), (Cell{3.0f, 1.0f, 0.0f, 0.0f}));
    EXPECT_EQ(one.at(0, 2), (Cell{0.0f, 2.0f, 0.0f, 0.0f}));
    EXPECT_EQ(nonEmpty(one), 3);

    std::vector<std::int32_t> labels(12, 99);
    labels[1] = 4;
    labels[7] = 0;
    labels[8] = kMaxSiteId;
    const Grid labelled = seedMask(mask, 4, 3, &labels);
    EXPECT_EQ(labelled.at(1, 0).z, 4.0f);
    EXPECT_EQ(labelled.at(3, 1).z, 0.0f);
    EXPECT_EQ(labelled.at(0, 2).z, float(kMaxSiteId));
    EXPECT_EQ(nonEmpty(labelled), 3); // labels of unmasked pixels are ignored
}

TEST(Sites, MaskSizesAndLabelsAreChecked) {
    const std::vector<std::uint8_t> mask(6, 1);
    EXPECT_THROW(seedMask(mask, 4, 2), std::invalid_argument);
    std::vector<std::int32_t> labels(6, 0);
    EXPECT_NO_THROW(seedMask(mask, 3, 2, &labels));
    labels[4] = -1;
    EXPECT_THROW(seedMask(mask, 3, 2, &labels), std::invalid_argument);
    labels[4] = kMaxSiteId + 1;
    EXPECT_THROW(seedMask(mask, 3, 2, &labels), std::invalid_argument);
    std::vector<std::int32_t> shortLabels(5, 0);
    EXPECT_THROW(seedMask(mask, 3, 2, &shortLabels), std::invalid_argument);
    // An unmasked pixel may carry any label.
    std::vector<std::uint8_t> partial(6, 0);
    partial[0] = 1;
    labels[4] = -7;
    EXPECT_NO_THROW(seedMask(partial, 3, 2, &labels));
}

TEST(Sites, IdsMustFitInAFloat) {
    EXPECT_EQ(kMaxSiteId, (1 << 24) - 1);
    EXPECT_EQ(double(float(kMaxSiteId)), double(kMaxSiteId));
    const std::vector<Site> tooMany(std::size_t(kMaxSiteId) + 2);
    EXPECT_THROW(seedPoints(tooMany, 4, 4, true), std::invalid_argument);
}

TEST(Sites, SplitMix64MatchesTheReferenceSequence) {
    // Reference values of splitmix64 seeded with 0 (Vigna's splitmix64.c).
    SplitMix64 rng(0);
    EXPECT_EQ(rng.next(), 0xE220A8397B1DCDAFull);
    EXPECT_EQ(rng.next(), 0x6E789E6AA1B965F4ull);
    EXPECT_EQ(rng.next(), 0x06C45D188009454Full);
    SplitMix64 a(42), b(42);
    for (int i = 0; i < 100; ++i) {
        const std::uint64_t bound = std::uint64_t(i) * 7 + 1;
        const std::uint64_t v = a.below(bound);
        EXPECT_LT(v, bound);
        EXPECT_EQ(v, b.below(bound));
        const double u = a.unit();
        EXPECT_GE(u, 0.0);
        EXPECT_LT(u, 1.0);
        EXPECT_EQ(u, b.unit());
    }
    EXPECT_THROW(a.below(0), std::invalid_argument);
}

TEST(Sites, BelowIsUniform) {
    SplitMix64 rng(7);
    std::vector<int> counts(6, 0);
    for (int i = 0; i < 60000; ++i) ++counts[std::size_t(rng.below(6))];
    for (int c : counts) {
        EXPECT_GT(c, 9500);
        EXPECT_LT(c, 10500);
    }
}

TEST(Sites, RandomIntegerSitesAreDeterministicDistinctAndInside) {
    for (auto [count, w, h] : {std::tuple{100, 64, 48}, {3000, 64, 48}, {6, 3, 2}, {1, 1, 1}}) {
        const std::vector<Site> a = randomIntegerSites(count, w, h, 11);
        EXPECT_EQ(a, randomIntegerSites(count, w, h, 11));
        ASSERT_EQ(int(a.size()), count);
        std::set<std::pair<float, float>> distinct;
        for (const Site& s : a) {
            EXPECT_EQ(s.x, float(int(s.x)));
            EXPECT_EQ(s.y, float(int(s.y)));
            EXPECT_GE(s.x, 0.0f);
            EXPECT_LT(s.x, float(w));
            EXPECT_GE(s.y, 0.0f);
            EXPECT_LT(s.y, float(h));
            distinct.insert({s.x, s.y});
        }
        EXPECT_EQ(int(distinct.size()), count);
        EXPECT_TRUE(seedPoints(a, w, h, true).missing.empty());
    }
    EXPECT_NE(randomIntegerSites(50, 64, 64, 1), randomIntegerSites(50, 64, 64, 2));
    EXPECT_THROW(randomIntegerSites(7, 3, 2, 1), std::invalid_argument);
    EXPECT_EQ(randomIntegerSites(7, 3, 2, 1, false).size(), 7u);
    EXPECT_THROW(randomIntegerSites(-1, 3, 2, 1), std::invalid_argument);
}

TEST(Sites, RandomFloatSitesAreDeterministicAndInside) {
    const std::vector<Site> a = randomFloatSites(2000, 50, 30, 5);
    EXPECT_EQ(a, randomFloatSites(2000, 50, 30, 5));
    EXPECT_NE(a, randomFloatSites(2000, 50, 30, 6));
    int fractional = 0;
    for (const Site& s : a) {
        EXPECT_GE(s.x, 0.0f);
        EXPECT_LE(s.x, 49.0f);
        EXPECT_GE(s.y, 0.0f);
        EXPECT_LE(s.y, 29.0f);
        fractional += s.x != float(int(s.x)) ? 1 : 0;
    }
    EXPECT_GT(fractional, 1900);
    // 2000 sub-pixel sites on 1500 pixels must collide; every site is kept or reported missing.
    const SeedResult seeded = seedPoints(a, 50, 30, false);
    EXPECT_EQ(nonEmpty(seeded.grid) + int(seeded.missing.size()), 2000);
    EXPECT_GT(seeded.missing.size(), 500u);
}

} // namespace
} // namespace fl::jfa
