// Light-frustum fitting and camera framing: every corner of the bounds ends up inside the volume.

#include <base/Framing.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <vector>

namespace fl::geom {
namespace {

Aabb box(glm::vec3 lo, glm::vec3 hi) {
    Aabb b;
    b.extend(lo);
    b.extend(hi);
    return b;
}

void expectCornersInside(const ViewVolume& v, const Aabb& b, float slack = 1e-4f) {
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 c{(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                          (i & 4) ? b.max.z : b.min.z};
        const glm::vec4 clip = v.viewProj() * glm::vec4(c, 1.0f);
        ASSERT_GT(clip.w, 0.0f);
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(ndc[k], -1.0f - slack) << "corner " << i << " axis " << k;
            EXPECT_LE(ndc[k], 1.0f + slack) << "corner " << i << " axis " << k;
        }
    }
}

TEST(Aabb, TransformedContainsTransformedCorners) {
    const Aabb b = box({-1, 0, 2}, {3, 1, 4});
    const glm::mat4 t =
        glm::mat4(glm::vec4(0, 1, 0, 0), glm::vec4(-1, 0, 0, 0), glm::vec4(0, 0, 1, 0),
                  glm::vec4(5, 0, 0, 1)); // 90° about z, then +5 x
    const Aabb r = b.transformed(t);
    EXPECT_FLOAT_EQ(r.min.x, 4.0f);
    EXPECT_FLOAT_EQ(r.max.x, 5.0f);
    EXPECT_FLOAT_EQ(r.min.y, -1.0f);
    EXPECT_FLOAT_EQ(r.max.y, 3.0f);
    EXPECT_FALSE(Aabb{}.valid());
    EXPECT_FALSE(Aabb{}.transformed(t).valid());
}

TEST(Framing, DirectionalLightContainsBounds) {
    const Aabb b = box({-10, -1, -7}, {12, 6, 9});
    for (glm::vec3 dir : {glm::vec3(0, -1, 0), glm::vec3(1, -1, 0.3f), glm::vec3(0, 0, 1),
                          glm::vec3(0.001f, -1, 0)})
        expectCornersInside(fitDirectionalLight(b, dir), b);
}

TEST(Framing, PerspectiveLightContainsBoundsWhenOutside) {
    const Aabb b = box({-10, -1, -7}, {12, 6, 9});
    for (glm::vec3 pos : {glm::vec3(0, 30, 0), glm::vec3(-20, 25, 10), glm::vec3(40, 1, 0)})
        expectCornersInside(fitPerspectiveLight(b, pos), b);
}

TEST(Framing, PerspectiveLightInsideBoundsIsCappedAndFinite) {
    const Aabb b = box({-10, -1, -7}, {12, 6, 9});
    const ViewVolume v = fitPerspectiveLight(b, {0, 2, 0});
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) ASSERT_TRUE(std::isfinite(v.proj[c][r]));
    EXPECT_GT(v.znear, 0.0f);
    EXPECT_GT(v.zfar, v.znear);
    // Capped at 150°: the horizontal/vertical scale is 1/tan(75°).
    EXPECT_NEAR(v.proj[1][1], 1.0f / std::tan(glm::radians(75.0f)), 1e-4f);
}

// The bug: a spot light above a scene that extends far to one side (the closed-form half-plane
// at 30 degrees) was aimed at the bounds' centre, which left corners behind the light; the map
// then got the capped fov and a near plane at 1/1000 of the diagonal, and PCSS's blocker search,
// looking through that plane, left the map and found nothing (the umbra came out lit).
TEST(Framing, SpotLightWithCornersBehindTheCentreAxisLooksAlongItsOwnAxis) {
    const Aabb b = box({-10.93f, 0, -10.93f}, {4, 1, 6.93f});
    const glm::vec3 spot(0, 5, 0), down(0, -1, 0);
    const ViewVolume centre = fitPerspectiveLight(b, spot);
    EXPECT_LT(centre.znear, 0.01f * 2.0f * b.radius()) << "the bug's condition";
    const ViewVolume fixedVolume = fitPerspectiveLight(b, spot, down);
    expectCornersInside(fixedVolume, b);
    EXPECT_NEAR(fixedVolume.znear, 0.99f * 4.0f, 1e-3f); // the nearest corner, 4 below the light
    // Where aiming at the centre leaves nothing behind, the axis changes nothing.
    const Aabb inFront = box({-4, 0, -4}, {4, 1, 4});
    const ViewVolume a = fitPerspectiveLight(inFront, spot);
    const ViewVolume s = fitPerspectiveLight(inFront, spot, {0.3f, -1, 0});
    EXPECT_EQ(a.viewProj(), s.viewProj());
}

TEST(Framing, FramingShowsWholeBounds) {
    const Aabb b = box({-3, 0, -2}, {5, 4, 6});
    for (float aspect : {0.5f, 1.0f, 2.0f})
        expectCornersInside(frameBounds(b, {1, 0.5f, 1}, glm::radians(50.0f), aspect), b);
}

// A model on a wide ground: the model's corners fill the picture (to `fill`), centred on the
// axis they fill, from the given direction; every point of the ground in view lies between the
// planes.
TEST(Framing, PointsFramedTightlyWithTheWholeInDepth) {
    const Aabb model = box({0, 0, 0}, {1, 2, 1});
    const Aabb ground = box({-20, -0.01f, -20}, {21, 2, 21});
    std::vector<glm::vec3> corners;
    for (int i = 0; i < 8; ++i)
        corners.emplace_back((i & 1) ? 1.0f : 0.0f, (i & 2) ? 2.0f : 0.0f, (i & 4) ? 1.0f : 0.0f);
    const glm::vec3 from(0.55f, 0.5f, 0.75f);
    const float fov = glm::radians(50.0f);
    for (float aspect : {1.0f, 1.5f, 0.5f})
        for (float fill : {1.0f, 0.9f}) {
            const ViewVolume v = framePointsTightly(corners, ground, from, fov, aspect, fill);
            expectCornersInside(v, model);
            // Looking along -from: the camera's z axis is `from`.
            const glm::vec3 back = glm::vec3(glm::inverse(v.view)[2]);
            EXPECT_NEAR(glm::dot(back, glm::normalize(from)), 1.0f, 1e-5f);
            // Tight and centred: the corners reach -fill and +fill on one axis.
            glm::vec2 lo(1e9f), hi(-1e9f);
            for (const glm::vec3& c : corners) {
                const glm::vec4 clip = v.viewProj() * glm::vec4(c, 1.0f);
                lo = glm::min(lo, glm::vec2(clip) / clip.w);
                hi = glm::max(hi, glm::vec2(clip) / clip.w);
            }
            const int axis = hi.x - lo.x > hi.y - lo.y ? 0 : 1;
            EXPECT_NEAR(hi[axis], fill, 1e-4f) << aspect;
            EXPECT_NEAR(lo[axis], -fill, 1e-4f) << aspect;
            // Nearer than the bounding sphere's fit.
            const ViewVolume sphere = frameBounds(model, from, fov, aspect);
            EXPECT_LT(glm::length(glm::vec3(glm::inverse(v.view)[3]) - model.center()),
                      glm::length(glm::vec3(glm::inverse(sphere.view)[3]) - model.center()));
            // The ground's top and bottom faces, sampled: the points in view are in depth range.
            int inView = 0;
            for (int i = 0; i <= 40; ++i)
                for (int k = 0; k <= 40; ++k)
                    for (float y : {ground.min.y, ground.max.y}) {
                        const glm::vec3 p(-20.0f + 41.0f * i / 40.0f, y,
                                          -20.0f + 41.0f * k / 40.0f);
                        const glm::vec3 e = glm::vec3(v.view * glm::vec4(p, 1.0f));
                        const glm::vec4 clip = v.proj * glm::vec4(e, 1.0f);
                        if (!(-e.z > 0.0f) || std::abs(clip.x) > clip.w ||
                            std::abs(clip.y) > clip.w)
                            continue;
                        ++inView;
                        EXPECT_GE(-e.z, v.znear) << p.x << " " << p.y << " " << p.z;
                        EXPECT_LE(-e.z, v.zfar) << p.x << " " << p.y << " " << p.z;
                    }
            EXPECT_GT(inView, 100);
        }
}

TEST(Framing, DegenerateBoundsStayFinite) {
    const Aabb point = box({1, 1, 1}, {1, 1, 1});
    const ViewVolume v = frameBounds(point, {0, 1, 0}, glm::radians(45.0f), 1.0f);
    const ViewVolume l = fitDirectionalLight(point, {0, -1, 0});
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            EXPECT_TRUE(std::isfinite(v.viewProj()[c][r]));
            EXPECT_TRUE(std::isfinite(l.viewProj()[c][r]));
        }
}

TEST(Framing, ClampDepthRangeTightensToTheBounds) {
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 0, 10), glm::vec3(0), glm::vec3(0, 1, 0));
    const glm::mat4 proj = glm::perspective(glm::radians(60.0f), 1.5f, 0.1f, 1000.0f);
    Aabb box;
    box.extend(glm::vec3(-1, -1, -2));
    box.extend(glm::vec3(1, 1, 3));
    const glm::mat4 p = clampDepthRange(proj, view, box);
    // Depths 7 (z = 3) and 12 (z = -2) map to the new near and far planes.
    auto ndcZ = [&](float d) {
        const glm::vec4 c = p * glm::vec4(0, 0, -d, 1);
        return c.z / c.w;
    };
    EXPECT_NEAR(ndcZ(7.0f), -1.0f, 1e-5f);
    EXPECT_NEAR(ndcZ(12.0f), 1.0f, 1e-5f);
    // x and y are untouched.
    EXPECT_EQ(p[0][0], proj[0][0]);
    EXPECT_EQ(p[1][1], proj[1][1]);
}

TEST(Framing, ClampDepthRangeNeverWidensOrBreaks) {
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 0, 10), glm::vec3(0), glm::vec3(0, 1, 0));
    const glm::mat4 proj = glm::perspective(glm::radians(60.0f), 1.0f, 8.0f, 11.0f);
    Aabb box;
    box.extend(glm::vec3(-50));
    box.extend(glm::vec3(50));
    // Bounds larger than the frustum's depth range: the original planes stay.
    const glm::mat4 p = clampDepthRange(proj, view, box);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(p[c][r], proj[c][r], 1e-5f * std::abs(proj[c][r]) + 1e-6f);
    // Bounds behind the camera: unchanged.
    Aabb behind;
    behind.extend(glm::vec3(-1, -1, 20));
    behind.extend(glm::vec3(1, 1, 30));
    EXPECT_EQ(clampDepthRange(proj, view, behind), proj);
    // Orthographic: unchanged.
    const glm::mat4 ortho = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.1f, 100.0f);
    EXPECT_EQ(clampDepthRange(ortho, view, box), ortho);
}

} // namespace
} // namespace fl::geom
