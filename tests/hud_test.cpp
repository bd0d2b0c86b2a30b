// HUD text layout (renderer/passes/HudPass.h): box, glyph placement, colours, and the CPU
// rasteriser that is the reference for the GL pass (hud_gltest).

#include <renderer/passes/HudPass.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace fl {
namespace {

TEST(HudLayout, NoLinesNoGeometry) {
    const HudGeometry g = layoutHud({});
    EXPECT_TRUE(g.triangles.empty());
}

TEST(HudLayout, BoxHoldsEveryGlyphAndRowsAreTwelveUnitsApart) {
    HudStyle style;
    style.scale = 2;
    style.margin = 5;
    style.padding = 3;
    const std::vector<std::string> lines{"AB", "x"};
    const HudGeometry g = layoutHud(lines, style);
    ASSERT_GT(g.triangles.size(), 6u);
    ASSERT_EQ(g.triangles.size() % 6, 0u);
    EXPECT_EQ(g.boxMin, glm::ivec2(5));
    EXPECT_EQ(g.boxMax.y, 5 + 2 * 12 * 2 + 2 * 3); // two rows of 12 units, scale 2, padding
    // The box is the first quad, in the background colour.
    EXPECT_EQ(g.triangles[0].pos, glm::vec2(g.boxMin));
    EXPECT_EQ(g.triangles[2].pos, glm::vec2(g.boxMax));
    EXPECT_EQ(g.triangles[0].color, style.background);
    bool secondRow = false;
    for (std::size_t i = 6; i < g.triangles.size(); ++i) {
        const glm::vec2 p = g.triangles[i].pos;
        EXPECT_GE(p.x, float(g.boxMin.x + style.padding));
        EXPECT_LE(p.x, float(g.boxMax.x - style.padding));
        EXPECT_GE(p.y, float(g.boxMin.y + style.padding));
        EXPECT_LE(p.y, float(g.boxMax.y - style.padding));
        EXPECT_EQ(g.triangles[i].color, style.text);
        // Integer scale and origin keep every edge on a pixel boundary (exact rasterisation).
        EXPECT_EQ(p.x, std::round(p.x));
        EXPECT_EQ(p.y, std::round(p.y));
        secondRow |= p.y >= float(g.boxMin.y + style.padding + 12 * 2);
    }
    EXPECT_TRUE(secondRow);
    // Scale 1 halves the text extent.
    style.scale = 1;
    const HudGeometry g1 = layoutHud(lines, style);
    EXPECT_EQ((g.boxMax.x - g.boxMin.x - 2 * 3), 2 * (g1.boxMax.x - g1.boxMin.x - 2 * 3));
    EXPECT_EQ(g1.triangles.size(), g.triangles.size());
}

TEST(HudLayout, WarningLinesAndUnprintableCharacters) {
    const HudStyle style;
    const HudGeometry warn = layoutHud(std::vector<std::string>{"! bad"}, style);
    ASSERT_GT(warn.triangles.size(), 6u);
    EXPECT_EQ(warn.triangles[6].color, style.warning);
    // Characters outside ' '..'~' are drawn as '?', never read outside the font's tables.
    const HudGeometry tab = layoutHud(std::vector<std::string>{"a\x01"
                                                               "b\xff"},
                                      style);
    const HudGeometry q = layoutHud(std::vector<std::string>{"a?b?"}, style);
    ASSERT_EQ(tab.triangles.size(), q.triangles.size());
    for (std::size_t i = 0; i < q.triangles.size(); ++i)
        EXPECT_EQ(tab.triangles[i].pos, q.triangles[i].pos);
}

TEST(HudRaster, BlendsTheBoxAndDrawsOpaqueText) {
    ByteImage image{40, 30, 4, std::vector<std::uint8_t>(40 * 30 * 4, 200)};
    HudStyle style;
    style.margin = 2;
    style.padding = 2;
    style.background = {0.0f, 0.0f, 0.0f, 0.5f};
    const HudGeometry g = layoutHud(std::vector<std::string>{"I"}, style);
    rasterizeHud(g, image);
    auto px = [&](int x, int y) { return image.data[(size_t(y) * 40 + x) * 4]; };
    EXPECT_EQ(px(0, 0), 200); // outside the box
    EXPECT_EQ(px(39, 29), 200);
    EXPECT_EQ(px(g.boxMin.x, g.boxMin.y), 100);         // 200 * (1 - 0.5)
    EXPECT_EQ(px(g.boxMax.x - 1, g.boxMax.y - 1), 100); // last pixel inside [min, max)
    EXPECT_EQ(px(g.boxMax.x, g.boxMax.y), 200);         // first outside
    // Some pixel of the glyph is fully white (text alpha 1 over the box).
    int white = 0;
    for (std::uint8_t v : image.data) white += v == 255;
    EXPECT_GT(white, 0);
}

TEST(HudLayout, TabsAlignTheSecondColumn) {
    const HudStyle style;
    const std::vector<std::string> lines{"x\tone", "wide label\ttwo", "no tab"};
    const HudGeometry g = layoutHud(lines, style);
    // The second cell of each tabbed line starts at the same x, right of the widest first cell.
    // Collect glyph x per row, then the second column's start as the first x past the gap.
    std::vector<std::vector<float>> xs(3);
    for (std::size_t i = 6; i < g.triangles.size(); ++i) {
        const int row = int((g.triangles[i].pos.y - float(g.boxMin.y + style.padding)) / 12.0f);
        if (row >= 0 && row < 3) xs[std::size_t(row)].push_back(g.triangles[i].pos.x);
    }
    const HudGeometry label = layoutHud(std::vector<std::string>{"wide label"}, style);
    const float column = float(label.boxMax.x - label.boxMin.x - 2 * style.padding) + 8.0f +
                         float(g.boxMin.x + style.padding);
    for (int row = 0; row < 2; ++row) {
        float second = 1e9f;
        for (float x : xs[std::size_t(row)])
            if (x >= column) second = std::min(second, x);
        EXPECT_LT(second - column, 3.0f) << "row " << row; // glyphs start within a unit or two
    }
    // Nothing of row 0 ("x") lies between its first cell and the column.
    for (float x : xs[0]) EXPECT_TRUE(x < float(g.boxMin.x + style.padding) + 8.0f || x >= column);
}

// Issue 42: in a 512-pixel window the HUD's status line ran off the right edge. With the
// window's width, a long line wraps at spaces, and every glyph stays inside the window.
TEST(HudLayout, LongLinesWrapToTheWindowsWidth) {
    const std::vector<std::string> lines{
        "method jfa-e (4/10)   shadow map uniform 1024^2   JFA passes 6 (auto)   view 31% of "
        "texels   light size 0.080 (radius 0.300)",
        "short", "wrote /a/long/path/with/no/spaces/in/it/captures/screenshot_0001.window.png"};
    HudStyle style;
    const HudGeometry unwrapped = layoutHud(lines, style);
    EXPECT_GT(unwrapped.boxMax.x, 512); // the case: wider than the window
    style.maxWidth = 512;
    const HudGeometry g = layoutHud(lines, style);
    EXPECT_LE(g.boxMax.x, 512);
    EXPECT_GT(g.boxMax.y, unwrapped.boxMax.y); // more rows
    for (const HudVertex& v : g.triangles) EXPECT_LE(v.pos.x, 512.0f);
    // The same text, only moved: as many glyph quads as before.
    EXPECT_EQ(g.triangles.size(), unwrapped.triangles.size());
    // A window narrower than any word: every piece still fits, nothing lost.
    style.maxWidth = 64;
    const HudGeometry narrow = layoutHud(lines, style);
    EXPECT_LE(narrow.boxMax.x, 64);
    EXPECT_EQ(narrow.triangles.size(), unwrapped.triangles.size());
}

} // namespace
} // namespace fl
