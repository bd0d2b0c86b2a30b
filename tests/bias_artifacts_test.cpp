// Acne and peter-panning as figures (renderer/metrics/BiasArtifacts.h) on synthetic frames whose
// answers are counted by hand: a floor meeting a wall (a contact), a wall floating above the
// floor (none), a method that darkens lit pixels (acne) and one that lights the umbra next to the
// contact (peter-panning).

#include <renderer/metrics/BiasArtifacts.h>

#include <gtest/gtest.h>

#include <stdexcept>

namespace {

using fl::BiasArtifactCounts;
using fl::FloatImage;
using fl::SurfaceGeometry;

constexpr int kW = 16, kH = 40, kWallRow = 20; // rows 0..19 floor, 20..39 wall
constexpr float kStep = 0.1f;                  // world units between pixel centres

// The floor (y = 0, normal up) runs towards the wall at z = 0; the wall (normal -z) rises from
// the floor's edge, or from `gap` above it. The eye sits so that a footprint is one step.
SurfaceGeometry floorAndWall(float gap) {
    SurfaceGeometry g;
    g.positions = {kW, kH, 4, std::vector<float>(kW * kH * 4, 0.0f)};
    g.planes = g.positions;
    g.receivers = {kW, kH, 1, std::vector<float>(kW * kH, 1.0f)};
    g.eye = {0.0f, 0.0f, -1000.0f};
    g.pixelAngle = kStep / 1000.0f;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const std::size_t i = (static_cast<std::size_t>(y) * kW + x) * 4;
            const bool wall = y >= kWallRow;
            const float px = kStep * static_cast<float>(x);
            const float py = wall ? gap + kStep * static_cast<float>(y - kWallRow + 1) : 0.0f;
            const float pz = wall ? 0.0f : -kStep * static_cast<float>(kWallRow - y);
            const float n[3] = {0.0f, wall ? 0.0f : 1.0f, wall ? -1.0f : 0.0f};
            for (int c = 0; c < 3; ++c) g.planes.data[i + c] = n[c];
            g.positions.data[i] = px;
            g.positions.data[i + 1] = py;
            g.positions.data[i + 2] = pz;
            g.positions.data[i + 3] = 1.0f;
        }
    // The footprint at the floor and wall is about kStep: the eye is 1000 away, pixelAngle
    // kStep / 1000.
    return g;
}

FloatImage rows(float inside, float outside, int first, int last) {
    FloatImage v{kW, kH, 1, std::vector<float>(kW * kH, outside)};
    for (int y = first; y <= last; ++y)
        for (int x = 0; x < kW; ++x) v.data[static_cast<std::size_t>(y) * kW + x] = inside;
    return v;
}

int contactRows(const FloatImage& contact) {
    int n = 0;
    for (int y = 0; y < kH; ++y) n += contact.data[static_cast<std::size_t>(y) * kW + 3] > 0.5f;
    return n;
}

TEST(BiasArtifacts, AFloorMeetingAWallIsAContactAFloatingWallIsNot) {
    const glm::vec3 light(0.5f, 50.0f, -50.0f); // above the floor, in front of the wall
    const fl::BiasMasks touching = fl::biasMasks(floorAndWall(0.0f), light);
    // The floor's last row and the wall's first: each rises off the other's plane by one step,
    // within 1.5 steps of it.
    EXPECT_EQ(touching.contact.data[(kWallRow - 1) * kW + 3], 1.0f);
    EXPECT_EQ(touching.contact.data[kWallRow * kW + 3], 1.0f);
    EXPECT_EQ(contactRows(touching.contact), 2);
    // Both planes face the light.
    for (float f : touching.facingLight.data) EXPECT_EQ(f, 1.0f);
    // The wall 10 steps above the floor: its pixels are 10 footprints away, no contact.
    EXPECT_EQ(contactRows(fl::biasMasks(floorAndWall(10.0f * kStep), light).contact), 0);
    // A light behind the wall: the wall faces away from it.
    const fl::BiasMasks behind = fl::biasMasks(floorAndWall(0.0f), {0.5f, 50.0f, 50.0f});
    EXPECT_EQ(behind.facingLight.data[kWallRow * kW], 0.0f);
    EXPECT_EQ(behind.facingLight.data[0], 1.0f);
}

TEST(BiasArtifacts, PeterPanningCountsTheLitUmbraNearTheContactOnly) {
    const fl::BiasMasks masks = fl::biasMasks(floorAndWall(0.0f), {0.5f, 50.0f, -50.0f});
    const FloatImage truth = rows(0.0f, 1.0f, 10, 30); // umbra over rows 10..30
    // Candidates: umbra rows within 3 of a contact row (19, 20): rows 16..23, 8 rows.
    // The method lights rows 17..19 (a shadow that starts late) and row 12, far from the
    // contact (not peter-panning: the shadow's far end).
    FloatImage method = truth;
    for (int y : {12, 17, 18, 19})
        for (int x = 0; x < kW; ++x) method.data[static_cast<std::size_t>(y) * kW + x] = 0.5f;
    const BiasArtifactCounts c = fl::biasArtifacts(method, truth, masks);
    EXPECT_EQ(c.peterPanningCandidates, 8u * kW);
    EXPECT_EQ(c.peterPanning, 3u * kW);
    EXPECT_DOUBLE_EQ(c.peterPanningShare(), 3.0 / 8.0);
    EXPECT_EQ(c.acne, 0u);
    // Lighting by exactly 0.1 or less is not counted.
    FloatImage slight = truth;
    for (int x = 0; x < kW; ++x) slight.data[18 * kW + x] = 0.1f;
    EXPECT_EQ(fl::biasArtifacts(slight, truth, masks).peterPanning, 0u);
}

TEST(BiasArtifacts, AcneCountsTheDarkenedFullyLitPixelsFacingTheLight) {
    const fl::BiasMasks masks = fl::biasMasks(floorAndWall(0.0f), {0.5f, 50.0f, -50.0f});
    FloatImage truth = rows(0.0f, 1.0f, 10, 30);
    truth.data[0] = 0.985f; // lit by the metrics' classes, but not fully: not a candidate
    // Candidates: rows 0..9 and 31..39 (19 rows), less pixel 0.
    FloatImage method = truth;
    int darkened = 0;
    for (std::size_t i = 1; i < method.data.size(); i += 7)
        if (truth.data[i] == 1.0f) {
            method.data[i] = 0.85f; // a speckle of acne
            ++darkened;
        }
    method.data[0] = 0.0f;
    const BiasArtifactCounts c = fl::biasArtifacts(method, truth, masks);
    EXPECT_EQ(c.acneCandidates, 19u * kW - 1);
    EXPECT_EQ(c.acne, static_cast<std::size_t>(darkened));
    EXPECT_DOUBLE_EQ(c.acneShare(), darkened / (19.0 * kW - 1));
    // Pixels whose plane faces away are no candidates, however dark the method makes them.
    const fl::BiasMasks behind = fl::biasMasks(floorAndWall(0.0f), {0.5f, 50.0f, 50.0f});
    EXPECT_EQ(fl::biasArtifacts(method, truth, behind).acneCandidates, 10u * kW - 1);
    BiasArtifactCounts sum = c;
    sum += c;
    EXPECT_DOUBLE_EQ(sum.acneShare(), c.acneShare());
}

TEST(BiasArtifacts, ImagesOfAnotherSizeAreRefused) {
    SurfaceGeometry g = floorAndWall(0.0f);
    g.receivers.width = 3;
    EXPECT_THROW((void)fl::biasMasks(g, {0, 1, 0}), std::invalid_argument);
    const fl::BiasMasks masks = fl::biasMasks(floorAndWall(0.0f), {0, 1, 0});
    EXPECT_THROW((void)fl::biasArtifacts(FloatImage{1, 1, 1, {1.0f}}, rows(0, 1, 0, 0), masks),
                 std::invalid_argument);
}

} // namespace
