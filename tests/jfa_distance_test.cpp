// Distance transforms of masks (jfa/DistanceTransform.h): JFA variants against the exact
// transforms, the exact ones against brute force, and the signed convention at the boundary.
#include <jfa/DistanceTransform.h>
#include <jfa/Sites.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace fl::jfa {
namespace {

using Mask = std::vector<std::uint8_t>;

// Up to `count` random discs.
Mask blobs(int w, int h, int count, std::uint64_t seed) {
    SplitMix64 rng(seed);
    Mask mask(std::size_t(w * h), 0);
    for (int k = 0; k < count; ++k) {
        const double cx = rng.unit() * w, cy = rng.unit() * h, r = 1.0 + rng.unit() * w / 8.0;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                if (std::hypot(x - cx, y - cy) < r) mask[std::size_t(y * w + x)] = 1;
            }
        }
    }
    return mask;
}

// Each pixel set with probability p.
Mask noise(int w, int h, double p, std::uint64_t seed) {
    SplitMix64 rng(seed);
    Mask mask(std::size_t(w * h), 0);
    for (auto& v : mask) v = rng.unit() < p ? 1 : 0;
    return mask;
}

// Brute-force distance from (x, y) to the nearest pixel with mask value == want.
float bruteDistance(const Mask& mask, int w, int h, int x, int y, bool want) {
    std::int64_t best = -1;
    for (int v = 0; v < h; ++v) {
        for (int u = 0; u < w; ++u) {
            if ((mask[std::size_t(v * w + u)] != 0) != want) continue;
            const std::int64_t d = std::int64_t(u - x) * (u - x) + std::int64_t(v - y) * (v - y);
            if (best < 0 || d < best) best = d;
        }
    }
    return best < 0 ? float(std::hypot(double(w), double(h))) : distanceFromSquared(best);
}

TEST(DistanceTransform, OneFeaturePixel) {
    Mask mask(7 * 5, 0);
    mask[2 * 7 + 3] = 1; // (3, 2)
    for (const DistanceField& d :
         {distanceTransform(mask, 7, 5, "jfa"), exactDistanceTransform(mask, 7, 5)}) {
        ASSERT_EQ(d.width, 7);
        ASSERT_EQ(d.height, 5);
        EXPECT_EQ(d.at(3, 2), 0.0f);
        EXPECT_EQ(d.at(4, 2), 1.0f);
        EXPECT_EQ(d.at(4, 3), std::sqrt(2.0f));
        EXPECT_EQ(d.at(0, 0), float(std::sqrt(13.0)));
        EXPECT_EQ(d.at(6, 4), float(std::sqrt(13.0)));
    }
}

// No pixel of the other kind: the nearest one lies beyond the grid, hypot(W, H) (5 for 4 x 3),
// with the sign of the side; never infinite (issue 16: an all-site mask wrote -inf into the
// .sdf.exr).
TEST(DistanceTransform, EmptyAndFullMasks) {
    const Mask none(12, 0), all(12, 1);
    EXPECT_EQ(noFeatureDistance(4, 3), 5.0f);
    for (float v : distanceTransform(none, 4, 3, "jfa").values) EXPECT_EQ(v, 5.0f);
    for (float v : exactDistanceTransform(none, 4, 3).values) EXPECT_EQ(v, 5.0f);
    for (float v : distanceTransform(all, 4, 3, "jfa").values) EXPECT_EQ(v, 0.0f);
    for (float v : signedDistanceTransform(none, 4, 3, "jfa").values) EXPECT_EQ(v, 5.0f);
    for (float v : signedDistanceTransform(all, 4, 3, "jfa").values) EXPECT_EQ(v, -5.0f);
    for (float v : exactSignedDistanceTransform(all, 4, 3).values) EXPECT_EQ(v, -5.0f);
}

// Every plan and the exact transform agree on all-site and no-site masks of any shape, every value
// is finite, and |value| is beyond every real distance of the grid.
TEST(DistanceTransform, AllSiteMaskGivesFiniteSignedDistance) {
    for (const auto& [w, h] : {std::pair{1, 1}, {1, 9}, {16, 16}, {37, 5}, {128, 3}}) {
        const Mask all(std::size_t(w * h), 1), none(std::size_t(w * h), 0);
        const float d = noFeatureDistance(w, h);
        EXPECT_GT(d, std::hypot(float(w - 1), float(h - 1)));
        for (const char* plan : {"jfa", "1+jfa", "jfa+2", "flood", "half:jfa"}) {
            const DistanceField in = signedDistanceTransform(all, w, h, plan);
            const DistanceField out = signedDistanceTransform(none, w, h, plan);
            for (float v : in.values) ASSERT_EQ(v, -d) << plan << " " << w << "x" << h;
            for (float v : out.values) ASSERT_EQ(v, d) << plan << " " << w << "x" << h;
            EXPECT_EQ(countDifferences(in, exactSignedDistanceTransform(all, w, h)), 0);
            EXPECT_EQ(countDifferences(out, exactSignedDistanceTransform(none, w, h)), 0);
        }
    }
}

TEST(DistanceTransform, ExactTransformsMatchBruteForce) {
    for (std::uint64_t seed = 0; seed < 6; ++seed) {
        const int w = 23 + int(seed), h = 17;
        const Mask mask = seed % 2 == 0 ? blobs(w, h, 3, seed) : noise(w, h, 0.05, seed);
        const DistanceField unsignedExact = exactDistanceTransform(mask, w, h);
        const DistanceField signedExact = exactSignedDistanceTransform(mask, w, h);
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const bool inside = mask[std::size_t(y * w + x)] != 0;
                ASSERT_EQ(unsignedExact.at(x, y), bruteDistance(mask, w, h, x, y, true));
                const float s = inside ? -bruteDistance(mask, w, h, x, y, false)
                                       : bruteDistance(mask, w, h, x, y, true);
                ASSERT_EQ(signedExact.at(x, y), s) << x << ", " << y;
            }
        }
    }
}

TEST(DistanceTransform, SignedConventionAtTheBoundary) {
    // A 5x5 square (2..6) inside a 9x9 grid.
    const int n = 9;
    Mask mask(std::size_t(n * n), 0);
    for (int y = 2; y <= 6; ++y)
        for (int x = 2; x <= 6; ++x) mask[std::size_t(y * n + x)] = 1;
    for (const DistanceField& d :
         {signedDistanceTransform(mask, n, n, "jfa+1"), exactSignedDistanceTransform(mask, n, n)}) {
        EXPECT_EQ(d.at(2, 4), -1.0f); // inside, next to the boundary
        EXPECT_EQ(d.at(2, 2), -1.0f); // inside corner: an outside pixel is 1 away
        EXPECT_EQ(d.at(3, 3), -2.0f);
        EXPECT_EQ(d.at(4, 4), -3.0f);           // centre
        EXPECT_EQ(d.at(1, 4), 1.0f);            // outside, next to the boundary
        EXPECT_EQ(d.at(1, 1), std::sqrt(2.0f)); // across the corner
        EXPECT_EQ(d.at(0, 0), std::sqrt(8.0f));
        for (float v : d.values) EXPECT_NE(v, 0.0f); // the zero level lies between pixels
        for (int i = 0; i < n * n; ++i)
            EXPECT_EQ(d.values[std::size_t(i)] < 0.0f, mask[std::size_t(i)] != 0);
    }
}

TEST(DistanceTransform, JfaVariantsAgainstExact) {
    // Differences from the exact transform, summed over 60 masks (64x48) of each kind. JFA makes
    // a few errors; JFA+2 and 1+JFA fewer; JFA^2 and standard flooding none on these inputs.
    const int w = 64, h = 48;
    for (int kind = 0; kind < 2; ++kind) {
        std::int64_t jfa = 0, jfaPlus2 = 0, onePlusJfa = 0, jfaSquared = 0, flooded = 0,
                     signedJfaPlus2 = 0;
        for (std::uint64_t seed = 0; seed < 60; ++seed) {
            const Mask mask = kind == 0 ? blobs(w, h, 6, seed) : noise(w, h, 0.01, seed);
            const DistanceField exact = exactDistanceTransform(mask, w, h);
            auto diff = [&](const char* spec) {
                return countDifferences(distanceTransform(mask, w, h, spec), exact);
            };
            jfa += diff("jfa");
            jfaPlus2 += diff("jfa+2");
            onePlusJfa += diff("1+jfa");
            jfaSquared += diff("jfa2");
            flooded += diff("flood");
            signedJfaPlus2 += countDifferences(signedDistanceTransform(mask, w, h, "jfa+2"),
                                               exactSignedDistanceTransform(mask, w, h));
        }
        const std::int64_t pixels = 60LL * w * h;
        std::cout << (kind == 0 ? "discs" : "noise") << ": JFA " << jfa << ", JFA+2 " << jfaPlus2
                  << ", 1+JFA " << onePlusJfa << ", signed JFA+2 " << signedJfaPlus2 << " of "
                  << pixels << " pixels\n";
        EXPECT_GT(jfa, 0);
        EXPECT_LT(jfaPlus2, jfa);
        EXPECT_LT(onePlusJfa, jfa);
        EXPECT_LT(jfaPlus2 * 1000, pixels); // < 0.1 %
        EXPECT_LT(onePlusJfa * 1000, pixels);
        EXPECT_LT(signedJfaPlus2 * 500, pixels);
        EXPECT_EQ(jfaSquared, 0);
        EXPECT_EQ(flooded, 0);
    }
}

TEST(DistanceTransform, HalfResolutionRecoversFeaturePixelsOfABlock) {
    // Downsampling keeps one seed per 2x2 block; the expansion lets each pixel choose among all
    // the seeds its representative stands for (thesis §4.3.2), so a feature pixel that was not
    // its block's representative is still at distance 0.
    const int w = 8, h = 4;
    Mask mask(std::size_t(w * h), 0);
    mask[0] = mask[1] = 1; // (0,0) and (1,0): one block
    const DistanceField half = distanceTransform(mask, w, h, "half:jfa");
    EXPECT_EQ(half.at(0, 0), 0.0f);
    EXPECT_EQ(half.at(1, 0), 0.0f);
    EXPECT_EQ(half, exactDistanceTransform(mask, w, h));
}

TEST(DistanceTransform, PlansAndSizesAreChecked) {
    const Mask mask = noise(20, 10, 0.1, 1);
    EXPECT_THROW(distanceTransform(mask, 20, 10, Plan::jfa(10, 20)), std::invalid_argument);
    EXPECT_THROW(signedDistanceTransform(mask, 20, 10, Plan::jfa(20, 11)), std::invalid_argument);
    EXPECT_THROW(distanceTransform(mask, 10, 10, "jfa"), std::invalid_argument);
    EXPECT_THROW(distanceTransform(mask, 20, 10, "nonsense"), std::invalid_argument);
    EXPECT_EQ(distanceTransform(mask, 20, 10, "jfa+1"),
              distanceTransform(mask, 20, 10, Plan::jfaPlus(1, 20, 10), {1, {}}));
    EXPECT_EQ(countDifferences(exactDistanceTransform(mask, 20, 10),
                               exactDistanceTransform(mask, 20, 10)),
              0);
}

} // namespace
} // namespace fl::jfa
