// The shadow-diagnostics summaries on synthetic images with known answers.

#include <renderer/metrics/ShadowStats.h>

#include <gtest/gtest.h>

#include <array>

namespace fl {
namespace {

// A diagnostics image from per-pixel (footprint, depth, visibility, previous) tuples.
FloatImage image(const std::vector<std::array<float, 4>>& px) {
    FloatImage d{static_cast<int>(px.size()), 1, 4, {}};
    for (const auto& p : px) d.data.insert(d.data.end(), p.begin(), p.end());
    return d;
}

TEST(ShadowStats, PercentileIsNearestRank) {
    std::vector<float> v{5, 1, 4, 2, 3};
    EXPECT_EQ(percentile(v, 0.5), 3.0);
    EXPECT_EQ(percentile(v, 0.95), 5.0);
    EXPECT_EQ(percentile(v, 0.0), 1.0);
    std::vector<float> empty;
    EXPECT_EQ(percentile(empty, 0.5), 0.0);
}

TEST(ShadowStats, SummaryOverReceiversOnly) {
    // Four receivers at depths 1..4 with footprints 8, 6, 2, 1; two background pixels.
    const FloatImage d =
        image({{8, 1, 1, 1}, {0, 0, 1, 1}, {6, 2, 0, 1}, {2, 3, 0, 0}, {0, 0, 1, 0}, {1, 4, 1, 1}});
    const ShadowMapStats s = summarizeShadowDiagnostics(d);
    EXPECT_EQ(s.receivers, 4u);
    EXPECT_EQ(s.footprint.median, 2.0); // nearest rank of {1, 2, 6, 8} at 50%
    EXPECT_EQ(s.footprint.p95, 8.0);
    // Nearest 25% by depth: the receiver at depth 1 alone.
    EXPECT_EQ(s.nearDepth, 1.0);
    EXPECT_EQ(s.footprintNear.median, 8.0);
    // One receiver of four changed visibility; the background pixel that "changed" does not count.
    EXPECT_DOUBLE_EQ(s.flickerShare, 0.25);
    EXPECT_DOUBLE_EQ(s.litShare, 0.5);
}

TEST(ShadowStats, NoReceiversGivesZeros) {
    const ShadowMapStats s = summarizeShadowDiagnostics(image({{0, 0, 1, 1}, {0, 0, 1, 1}}));
    EXPECT_EQ(s.receivers, 0u);
    EXPECT_EQ(s.footprint.median, 0.0);
    EXPECT_EQ(s.flickerShare, 0.0);
}

TEST(ShadowStats, SideBySidePlacesImagesWithAGutter) {
    ByteImage a{2, 1, 4, {1, 1, 1, 1, 2, 2, 2, 2}}, b{1, 1, 4, {3, 3, 3, 3}};
    const ByteImage s = sideBySide({a, b}, 1);
    ASSERT_EQ(s.width, 4);
    EXPECT_EQ(s.data[0], 1);
    EXPECT_EQ(s.data[4], 2);
    EXPECT_EQ(s.data[8], 255); // gutter
    EXPECT_EQ(s.data[12], 3);
    ByteImage tall{1, 2, 4, std::vector<std::uint8_t>(8)};
    EXPECT_THROW(sideBySide({a, tall}), std::invalid_argument);
}

TEST(ShadowStats, HeatMapIsBlackForBackgroundAndGreenAtOnePixelPerTexel) {
    const ByteImage h = footprintHeatMap(image({{0, 0, 1, 1}, {1, 1, 1, 1}, {64, 1, 1, 1}}));
    EXPECT_EQ(h.data[0] + h.data[1] + h.data[2], 0);
    EXPECT_EQ(h.data[5], 255); // green at 1
    EXPECT_EQ(h.data[8], 255); // red at >= 16
}

TEST(ShadowStats, TileGridFillsRowsWithAGutter) {
    const auto tile = [](std::uint8_t v) { return ByteImage{1, 1, 4, {v, v, v, v}}; };
    const ByteImage g = tileGrid({tile(1), tile(2), tile(3)}, 2, 1);
    ASSERT_EQ(g.width, 3);
    ASSERT_EQ(g.height, 3);
    EXPECT_EQ(g.data[0], 1);
    EXPECT_EQ(g.data[4], 255); // gutter
    EXPECT_EQ(g.data[8], 2);
    EXPECT_EQ(g.data[(2 * 3 + 0) * 4], 3);   // second row
    EXPECT_EQ(g.data[(2 * 3 + 2) * 4], 255); // no fourth tile: white
    EXPECT_THROW((void)tileGrid({tile(1), ByteImage{2, 1, 4, std::vector<std::uint8_t>(8)}}, 2),
                 std::invalid_argument);
}

} // namespace
} // namespace fl
