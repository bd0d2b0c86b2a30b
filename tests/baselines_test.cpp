// The baselines' CPU parts: PCSS presets, tap patterns, the ground truth's disk samples and the
// visibility difference it reports its sampling error with.

#include <renderer/methods/ShadowMethod.h>
#include <renderer/soft/FilteredShadow.h>
#include <renderer/soft/ReferenceShadow.h>

#include <gtest/gtest.h>

#include <geometry/DiskSampling.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

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

TEST(Baselines, ReferenceSamplesLieOnTheDiskInEveryPattern) {
    DiskLight disk;
    disk.center = {1.0f, 5.0f, -2.0f};
    disk.normal = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
    disk.radius = 1.5f;
    for (const geom::DiskPatternName& p : geom::kDiskPatterns) {
        SCOPED_TRACE(std::string(p.name));
        EXPECT_EQ(referenceDiskSamples(disk, 1, p.pattern), std::vector<glm::vec3>{disk.center});
        for (int n : {2, 7, 16, 64, 256, 512}) {
            const std::vector<glm::vec3> s = referenceDiskSamples(disk, n, p.pattern);
            ASSERT_EQ(s.size(), static_cast<std::size_t>(n));
            glm::vec3 mean(0.0f);
            for (glm::vec3 q : s) {
                EXPECT_LE(glm::length(q - disk.center), disk.radius * 1.0001f) << n;
                EXPECT_NEAR(glm::dot(q - disk.center, disk.normal), 0.0f, 1e-5f) << n;
                mean += q / static_cast<float>(n);
            }
            // Grid: symmetric strata, the mean is the centre. The others are within a few
            // samples' share of the radius of it.
            const float allowed = p.pattern == geom::DiskPattern::Grid ? 1e-4f : 4.0f / n;
            EXPECT_LT(glm::length(mean - disk.center), allowed * disk.radius) << n;
        }
        // Equal area: the share within half the disk's area is one half, up to one ring of cells
        // for the grid (64 x 64 cells: rings 1/32 of the radius wide, about 0.044 of the area at
        // r = sqrt(1/2); the cell centres of rings 0..22 lie inside: (46/64)^2 = 0.517).
        const std::vector<glm::vec3> s = referenceDiskSamples(disk, 4096, p.pattern);
        int inner = 0;
        for (glm::vec3 q : s) inner += glm::length(q - disk.center) < disk.radius * std::sqrt(0.5f);
        EXPECT_NEAR(inner / 4096.0, 0.5, 0.03);
        EXPECT_THROW((void)referenceDiskSamples(disk, 0, p.pattern), std::invalid_argument);
    }
    EXPECT_EQ(geom::diskPatternNamed("spiral"), geom::DiskPattern::Spiral);
    // --reference-pattern's choices (the method table) are exactly the patterns' names.
    const MethodOption* option = methodOrThrow("reference").option("pattern");
    ASSERT_NE(option, nullptr);
    std::string names;
    for (const geom::DiskPatternName& p : geom::kDiskPatterns)
        names += (names.empty() ? "" : "|") + std::string(p.name);
    EXPECT_EQ(std::string(option->choices), names);
    EXPECT_THROW((void)geom::diskPatternNamed("halton"), std::invalid_argument);
}

// What a straight occluder edge sees of a pattern: over lines at `angles` directions and 200
// offsets across the unit disk, the largest |share of the points beyond the line - share of the
// disk's area beyond it (the segment fraction)|, for the lines at angles in [lo, hi).
double lineDiscrepancy(const std::vector<glm::dvec2>& points, double lo, double hi) {
    constexpr double kPi = 3.14159265358979323846;
    constexpr int kAngles = 45, kOffsets = 200;
    double worst = 0.0;
    for (int a = 0; a < kAngles; ++a) {
        const double theta = lo + (hi - lo) * (a + 0.5) / kAngles;
        const glm::dvec2 n(std::cos(theta), std::sin(theta));
        for (int o = 0; o < kOffsets; ++o) {
            const double d = -1.0 + 2.0 * (o + 0.5) / kOffsets;
            const double segment = (std::acos(d) - d * std::sqrt(1.0 - d * d)) / kPi;
            std::size_t beyond = 0;
            for (glm::dvec2 p : points) beyond += glm::dot(n, p) > d;
            worst =
                std::max(worst, std::abs(static_cast<double>(beyond) / points.size() - segment));
        }
    }
    return worst;
}

// Named after the bands it removes: the grid's points sit in rows, so an edge parallel to them
// uncovers a row at a time and the maps reference's penumbra steps. Measured here (N = 64, 256,
// 1024; largest error over all angles): grid 0.058, 0.028, 0.015; spiral 0.048, 0.017, 0.0058.
TEST(Baselines, SpiralSamplesDoNotBandAlongEdgesParallelToTheGridsRows) {
    constexpr double kPi = 3.14159265358979323846;
    for (int n : {64, 256, 1024}) {
        const auto grid = geom::diskPattern(geom::DiskPattern::Grid, n);
        const auto spiral = geom::diskPattern(geom::DiskPattern::Spiral, n);
        // Lines within 2 degrees of the grid's rows: where the grid is at its worst.
        const double gridRows = lineDiscrepancy(grid, -0.035, 0.035);
        const double spiralRows = lineDiscrepancy(spiral, -0.035, 0.035);
        const double gridAll = lineDiscrepancy(grid, 0.0, kPi);
        const double spiralAll = lineDiscrepancy(spiral, 0.0, kPi);
        std::printf("N = %d: along the rows grid %.4f spiral %.4f; every angle grid %.4f spiral "
                    "%.4f\n",
                    n, gridRows, spiralRows, gridAll, spiralAll);
        EXPECT_LT(spiralRows, 0.8 * gridRows) << n;
        EXPECT_LT(spiralAll, gridAll) << n;
        // Either is within a few samples' share of the exact area.
        EXPECT_LT(spiralAll, 4.0 / std::sqrt(n)) << n;
    }
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
