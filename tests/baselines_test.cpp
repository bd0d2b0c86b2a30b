// The baselines' CPU parts: PCSS presets, tap patterns, the ground truth's disk samples and the
// visibility difference it reports its sampling error with.

#include <renderer/soft/FilteredShadow.h>
#include <renderer/soft/ReferenceShadow.h>

#include <gtest/gtest.h>

#include <cmath>

namespace fl {
namespace {

TEST(Baselines, PcssPresetsParse) {
    ASSERT_TRUE(parsePcssPreset("16/16"));
    EXPECT_EQ(parsePcssPreset("16/24")->filterSamples, 24);
    EXPECT_EQ(parsePcssPreset("32/64")->blockerSamples, 32);
    EXPECT_FALSE(parsePcssPreset("8/8"));
    EXPECT_FALSE(parsePcssPreset(""));
}

TEST(Baselines, VogelDiskFillsTheUnitDiskEvenly) {
    const std::vector<glm::vec2> d = vogelDisk(64);
    ASSERT_EQ(d.size(), 64u);
    glm::vec2 mean(0.0f);
    int inner = 0;
    for (glm::vec2 p : d) {
        EXPECT_LE(glm::length(p), 1.0f);
        mean += p / 64.0f;
        inner += glm::length(p) < std::sqrt(0.5f); // half the disk's area
    }
    EXPECT_LT(glm::length(mean), 0.05f);
    EXPECT_EQ(inner, 32);
}

TEST(Baselines, PcfOffsetsAreACentredGrid) {
    const std::vector<glm::vec2> o = pcfOffsets(5);
    ASSERT_EQ(o.size(), 25u);
    EXPECT_EQ(o.front(), glm::vec2(-2.0f, -2.0f));
    EXPECT_EQ(o.back(), glm::vec2(2.0f, 2.0f));
    EXPECT_EQ(pcfOffsets(1), std::vector<glm::vec2>{glm::vec2(0.0f)});
    EXPECT_EQ(pcfOffsets(2).front(), glm::vec2(-0.5f, -0.5f));
}

TEST(Baselines, ReferenceSamplesAreStratifiedOnTheDisk) {
    DiskLight disk;
    disk.center = {1.0f, 5.0f, -2.0f};
    disk.normal = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
    disk.radius = 1.5f;
    EXPECT_EQ(referenceDiskSamples(disk, 1), std::vector<glm::vec3>{disk.center});
    for (int n : {2, 7, 16, 64, 256, 512}) {
        const std::vector<glm::vec3> s = referenceDiskSamples(disk, n);
        ASSERT_EQ(s.size(), static_cast<std::size_t>(n));
        glm::vec3 mean(0.0f);
        for (glm::vec3 q : s) {
            EXPECT_LE(glm::length(q - disk.center), disk.radius * 1.0001f) << n;
            EXPECT_NEAR(glm::dot(q - disk.center, disk.normal), 0.0f, 1e-5f) << n;
            mean += q / static_cast<float>(n);
        }
        // Symmetric strata: the samples' mean is the centre.
        EXPECT_LT(glm::length(mean - disk.center), 1e-4f) << n;
    }
    // Equal-area strata: the fraction within half the area is one half up to one ring of cells
    // (64 x 64 cells: rings 1/32 of the radius wide, about 0.044 of the area at r = sqrt(1/2);
    // the cell centres of rings 0..22 lie inside: (46/64)^2 = 0.517).
    const std::vector<glm::vec3> s = referenceDiskSamples(disk, 4096);
    int inner = 0;
    for (glm::vec3 q : s) inner += glm::length(q - disk.center) < disk.radius * std::sqrt(0.5f);
    EXPECT_NEAR(inner / 4096.0, 0.5, 0.03);
    EXPECT_THROW((void)referenceDiskSamples(disk, 0), std::invalid_argument);
}

TEST(Baselines, VisibilityDifferenceOverMaskedPixels) {
    const FloatImage a{2, 2, 1, {0.0f, 0.5f, 1.0f, 1.0f}};
    const FloatImage b{2, 2, 1, {0.0f, 0.25f, 1.0f, 0.0f}};
    const FloatImage mask{2, 2, 1, {1.0f, 1.0f, 1.0f, 0.0f}};
    const VisibilityDifference d = visibilityDifference(a, b, mask);
    EXPECT_EQ(d.pixels, 3u);
    EXPECT_DOUBLE_EQ(d.maxAbs, 0.25);
    EXPECT_NEAR(d.rmse, std::sqrt(0.0625 / 3.0), 1e-12);
    EXPECT_DOUBLE_EQ(visibilityDifference(a, b).maxAbs, 1.0);
}

} // namespace
} // namespace fl
