// The occluder intensity of thesis §5.2 against numerical integration over the disk light.

#include <scene/DiskLight.h>

#include <gtest/gtest.h>

#include <cmath>

namespace fl {
namespace {

// Fraction of the disk's area with (x - c) . u > t * r, by a fine grid over the disk.
double integrateBeyondChord(double t, int n = 1200) {
    std::size_t inside = 0, beyond = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x = -1.0 + (i + 0.5) * 2.0 / n, y = -1.0 + (j + 0.5) * 2.0 / n;
            if (x * x + y * y >= 1.0) continue;
            ++inside;
            beyond += x > t;
        }
    return static_cast<double>(beyond) / static_cast<double>(inside);
}

TEST(DiskLight, SegmentFractionMatchesIntegration) {
    for (double t : {0.0, 0.1, 0.25, 0.5, 0.75, 0.9, 0.99, 1.0})
        EXPECT_NEAR(segmentFraction(static_cast<float>(t)), integrateBeyondChord(t), 2e-3)
            << "t = " << t;
    EXPECT_FLOAT_EQ(segmentFraction(0.0f), 0.5f);
    EXPECT_FLOAT_EQ(segmentFraction(1.0f), 0.0f);
    EXPECT_FLOAT_EQ(segmentFraction(2.0f), 0.0f); // clamped
}

// A half-plane occluder (y = h, x > e) between a horizontal disk light above and a receiver p
// below. The exact visible fraction of the disk from p (sampling the disk and testing each ray
// against the half-plane) equals the intensity of the occluder edge point that minimises it
// (outside the hard shadow) or maximises it (inside): the criterion JFA propagates.
TEST(DiskLight, StraightEdgeOccluderIntensityIsExact) {
    DiskLight light{{0.0f, 10.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 1.0f};
    const float h = 5.0f, e = 0.0f;
    for (float px : {-0.9f, -0.5f, -0.2f, 0.0f, 0.2f, 0.5f, 0.9f}) {
        const glm::vec3 p{px, 0.0f, 0.3f};
        // Exact: disk points x_l such that the segment p -> x_l passes the plane y = h at x <= e.
        const int n = 1000;
        std::size_t inside = 0, visible = 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const float lx = -1.0f + (i + 0.5f) * 2.0f / n, lz = -1.0f + (j + 0.5f) * 2.0f / n;
                if (lx * lx + lz * lz >= 1.0f) continue;
                ++inside;
                const float s = h / 10.0f; // parameter where the segment crosses y = h
                const float x = p.x + s * (lx - p.x);
                visible += x <= e;
            }
        const double exact = static_cast<double>(visible) / static_cast<double>(inside);
        // The receiver sees the light's centre iff the ray to it passes left of the edge.
        const bool insideHard = p.x + (h / 10.0f) * (0.0f - p.x) > e;
        std::optional<float> best;
        for (float oz = -20.0f; oz <= 20.0f; oz += 0.01f) {
            const std::optional<float> in = occluderIntensity(light, p, {e, h, oz}, insideHard);
            if (!in) continue;
            if (!best || (insideHard ? *in > *best : *in < *best)) best = in;
        }
        ASSERT_TRUE(best.has_value()) << "px " << px;
        EXPECT_NEAR(*best, exact, 3e-3) << "px " << px << (insideHard ? " (inside)" : "");
    }
}

TEST(DiskLight, RaysThatMissTheLightAreRejected) {
    DiskLight light{{0.0f, 10.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 1.0f};
    // Occluder far to the side: the ray reaches the plane outside the disk.
    EXPECT_FALSE(occluderHit(light, {0, 0, 0}, {3, 5, 0}).has_value());
    // Occluder behind the receiver (farther from the light).
    EXPECT_FALSE(occluderHit(light, {0, 5, 0}, {0.1f, 2, 0}).has_value());
    // Parallel to the plane.
    EXPECT_FALSE(occluderHit(light, {0, 5, 0}, {1, 5, 0}).has_value());
    // Straight up through the centre: d = 0, intensity 1/2 outside and inside.
    EXPECT_FLOAT_EQ(*occluderIntensity(light, {0, 0, 0}, {0, 5, 0}, false), 0.5f);
    // Zero radius: nothing is ever hit (hard shadows).
    DiskLight point = light;
    point.radius = 0.0f;
    EXPECT_FALSE(occluderHit(point, {0, 0, 0}, {0, 5, 0}).has_value());
}

TEST(DiskLight, MakeDiskLightFacesTheScene) {
    geom::Aabb b;
    b.extend(glm::vec3(-1));
    b.extend(glm::vec3(1));
    Light spot;
    spot.type = Light::Type::Spot;
    spot.position = {0, 5, 0};
    spot.direction = {0, -2, 0};
    spot.radius = 0.3f;
    DiskLight d = makeDiskLight(spot, b);
    EXPECT_NEAR(d.normal.y, -1.0f, 1e-6f);
    EXPECT_EQ(d.radius, 0.3f);
    Light point = spot;
    point.type = Light::Type::Point;
    point.position = {5, 0, 0};
    d = makeDiskLight(point, b);
    EXPECT_NEAR(d.normal.x, -1.0f, 1e-6f);
    Light sun = spot;
    sun.type = Light::Type::Directional;
    d = makeDiskLight(sun, b);
    EXPECT_GT(d.center.y, 1.0f); // above the scene, facing down
}

} // namespace
} // namespace fl
