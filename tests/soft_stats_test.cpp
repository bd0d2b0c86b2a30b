// Soft-shadow comparison statistics on synthetic images with known answers.

#include <renderer/metrics/SoftStats.h>

#include <gtest/gtest.h>

namespace fl {
namespace {

FloatImage row(std::vector<float> v) {
    return FloatImage{static_cast<int>(v.size()), 1, 1, std::move(v)};
}

TEST(SoftStats, BucketsParityAndDeltas) {
    // pixel: method, reference
    //   0: 1.00, 1.00  lit in both (ignored by buckets)
    //   1: 0.50, 0.52  penumbra both, |dI| 0.02 -> bucket 0
    //   2: 0.50, 0.58  |dI| 0.08 -> bucket 1
    //   3: 0.30, 0.45  |dI| 0.15 -> bucket 2
    //   4: 1.00, 0.60  parity differs, |dI| 0.4 -> bucket 3
    //   5: 0.00, 0.00  umbra in both
    const SoftStats s = compareSoftShadows(row({1.0f, 0.5f, 0.5f, 0.3f, 1.0f, 0.0f}),
                                           row({1.0f, 0.52f, 0.58f, 0.45f, 0.6f, 0.0f}));
    EXPECT_EQ(s.pixels, 6u);
    EXPECT_EQ(s.penumbraReference, 4u);
    EXPECT_EQ(s.penumbraMethod, 3u);
    EXPECT_EQ(s.penumbraEither, 4u);
    EXPECT_DOUBLE_EQ(s.deltaBuckets[0], 0.25);
    EXPECT_DOUBLE_EQ(s.deltaBuckets[1], 0.25);
    EXPECT_DOUBLE_EQ(s.deltaBuckets[2], 0.25);
    EXPECT_DOUBLE_EQ(s.deltaBuckets[3], 0.25);
    EXPECT_DOUBLE_EQ(s.parityShare, 1.0 / 6.0);
    EXPECT_NEAR(s.maxDelta, 0.4, 1e-6);
}

TEST(SoftStats, IdenticalImagesAgreeCompletely) {
    const FloatImage a = row({0.0f, 0.25f, 1.0f});
    const SoftStats s = compareSoftShadows(a, a);
    EXPECT_EQ(s.parityShare, 0.0);
    EXPECT_EQ(s.deltaBuckets[0], 1.0);
    EXPECT_EQ(s.maxDelta, 0.0);
}

TEST(SoftStats, NoPenumbraGivesZeroBucketsAndMismatchedSizesThrow) {
    const SoftStats s = compareSoftShadows(row({0.0f, 1.0f}), row({0.0f, 1.0f}));
    EXPECT_EQ(s.penumbraEither, 0u);
    EXPECT_EQ(s.deltaBuckets[0], 0.0);
    EXPECT_THROW(compareSoftShadows(row({0.0f}), row({0.0f, 1.0f})), std::invalid_argument);
}

TEST(SoftStats, DifferencePictureScalesByGain) {
    const ByteImage d = differencePicture(row({0.5f, 0.0f}), row({0.4f, 1.0f}), 4.0f);
    EXPECT_EQ(d.data[0], 102); // 0.1 * 4 = 0.4 -> 102
    EXPECT_EQ(d.data[4], 255); // clamped
}

TEST(SoftStats, SignedDifferencePictureIsRedWhereTooBrightBlueWhereTooDark) {
    // method - reference: +0.25 (half red), -0.5 (full blue), 0 (white), +0.2 off the mask.
    const FloatImage m = row({0.75f, 0.0f, 0.3f, 0.7f}), r = row({0.5f, 0.5f, 0.3f, 0.5f});
    const ByteImage d = signedDifferencePicture(m, r, 0.5f, row({1.0f, 1.0f, 1.0f, 0.0f}));
    const auto px = [&](int i) {
        return std::vector<int>(d.data.begin() + 4 * i, d.data.begin() + 4 * i + 3);
    };
    EXPECT_EQ(px(0), (std::vector<int>{255, 128, 128}));
    EXPECT_EQ(px(1), (std::vector<int>{0, 0, 255}));
    EXPECT_EQ(px(2), (std::vector<int>{255, 255, 255}));
    EXPECT_EQ(px(3), (std::vector<int>{0, 0, 0})); // not a receiver
    EXPECT_THROW((void)signedDifferencePicture(row({0.0f}), r), std::invalid_argument);
}

} // namespace
} // namespace fl
