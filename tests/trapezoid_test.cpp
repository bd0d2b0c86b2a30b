// Trapezoidal shadow map fit: N_T keeps the eye frustum inside the map, gives the near plane
// more texels, honours the 80% rule, and degrades smoothly (never NaN) in degenerate setups.
// The stability measures (quantize, snapTexels, hysteresis): small camera moves leave the map
// unchanged, large ones change it, and the frustum stays inside the map either way.

#include <geometry/Trapezoid.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace fl::geom {
namespace {

constexpr float kSlack = 1e-4f;

// The eye: at (0, 2, 0) looking horizontally along -z, 60 degree fov, depth 0.5 .. 20.
glm::mat4 eyeInverse(glm::vec3 pos = {0, 2, 0}, glm::vec3 dir = {0, 0, -1}, float fov = 60.0f,
                     float zn = 0.5f, float zf = 20.0f) {
    const glm::mat4 view = glm::lookAt(pos, pos + dir, glm::vec3(0, 1, 0));
    const glm::mat4 proj = glm::perspective(glm::radians(fov), 1.0f, zn, zf);
    return glm::inverse(proj * view);
}

// An orthographic light travelling along `dir` (in the y-z plane, so +x is a safe up vector)
// centred on the eye frustum and wide enough to contain all of it.
glm::mat4 orthoLight(glm::vec3 dir) {
    const glm::vec3 centre(0, 2, -10.25f);
    const glm::vec3 d = glm::normalize(dir);
    const glm::mat4 view = glm::lookAt(centre - 50.0f * d, centre, glm::vec3(1, 0, 0));
    return glm::ortho(-22.0f, 22.0f, -22.0f, 22.0f, 1.0f, 100.0f) * view;
}

glm::vec4 applyClip(const glm::mat4& nt, glm::vec2 ndc) {
    return nt * glm::vec4(ndc, 0, 1);
}

glm::vec2 apply(const glm::mat4& nt, glm::vec2 ndc) {
    const glm::vec4 c = applyClip(nt, ndc);
    return glm::vec2(c) / c.w;
}

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

void expectHullInside(const TrapezoidFit& fit, float slack = kSlack) {
    for (const glm::vec2& p : fit.hull) {
        const glm::vec4 c = applyClip(fit.nt, p);
        ASSERT_GT(c.w, 0.0f) << p.x << ", " << p.y;
        const glm::vec2 m = glm::vec2(c) / c.w;
        EXPECT_LE(std::abs(m.x), 1.0f + slack) << p.x << ", " << p.y;
        EXPECT_LE(std::abs(m.y), 1.0f + slack) << p.x << ", " << p.y;
    }
}

// Texel density: the Jacobian determinant of the 2D map at p (map area per light-NDC area).
float density(const glm::mat4& nt, glm::vec2 p) {
    const float h = 1e-3f;
    const glm::vec2 dx = (apply(nt, p + glm::vec2(h, 0)) - apply(nt, p - glm::vec2(h, 0))) / 2.0f;
    const glm::vec2 dy = (apply(nt, p + glm::vec2(0, h)) - apply(nt, p - glm::vec2(0, h))) / 2.0f;
    return (dx.x * dy.y - dx.y * dy.x) / (h * h);
}

TEST(Trapezoid, ConvexHullDropsInteriorAndCollinearPoints) {
    const std::vector<glm::dvec2> hull =
        convexHull2d({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}, {0.5, 0.5}, {2, 2}, {0, 1}});
    ASSERT_EQ(hull.size(), 4u);
    double area = 0.0; // positive: counter-clockwise
    for (size_t i = 0; i < hull.size(); ++i) {
        const glm::dvec2 a = hull[i];
        const glm::dvec2 b = hull[(i + 1) % hull.size()];
        area += 0.5 * (a.x * b.y - a.y * b.x);
    }
    EXPECT_DOUBLE_EQ(area, 4.0);
}

TEST(Trapezoid, ClipToSquareCutsAndDropsOutside) {
    const auto cut = clipToSquare({{0, 0}, {3, 0}, {3, 0.5}, {0, 0.5}});
    for (const glm::dvec2& p : cut) EXPECT_LE(p.x, 1.0);
    EXPECT_EQ(cut.size(), 4u);
    EXPECT_TRUE(clipToSquare({{2, 2}, {3, 2}, {3, 3}}).empty());
}

TEST(Trapezoid, LightFromAboveFitsWholeFrustumInsideTheSquare) {
    const glm::mat4 light = orthoLight({0, -1, 0});
    const TrapezoidFit fit = fitTrapezoid(light, eyeInverse());
    EXPECT_FALSE(fit.degenerate);
    EXPECT_FLOAT_EQ(fit.weight, 1.0f);
    ASSERT_TRUE(finite(fit.nt));
    ASSERT_GE(fit.hull.size(), 3u);
    expectHullInside(fit);
    // Every frustum corner too (the light contains the whole frustum, nothing was clipped).
    for (const glm::dvec4& c : projectFrustumCorners(light, eyeInverse())) {
        const glm::vec2 m = apply(fit.nt, glm::vec2(glm::dvec2(c) / c.w));
        EXPECT_LE(std::abs(m.x), 1.0f + kSlack);
        EXPECT_LE(std::abs(m.y), 1.0f + kSlack);
    }
}

TEST(Trapezoid, CornersMapToSquareCorners) {
    const TrapezoidFit fit = fitTrapezoid(orthoLight({0, -1, 0.3f}), eyeInverse());
    ASSERT_FALSE(fit.degenerate);
    const std::array<glm::vec2, 4> expected{glm::vec2(-1, 1), glm::vec2(1, 1), glm::vec2(1, -1),
                                            glm::vec2(-1, -1)};
    for (size_t i = 0; i < 4; ++i) {
        const glm::vec2 m = apply(fit.nt, fit.corners[i]);
        EXPECT_NEAR(m.x, expected[i].x, 1e-4f) << "corner " << i;
        EXPECT_NEAR(m.y, expected[i].y, 1e-4f) << "corner " << i;
    }
    // The near-plane centre is close to the top edge (the tilted light sees a near-plane corner
    // slightly nearer), the far-plane centre on the base side.
    EXPECT_GT(apply(fit.nt, fit.nearCenter).y, 0.9f);
    EXPECT_GT(apply(fit.nt, fit.nearCenter).y, apply(fit.nt, fit.farCenter).y);
}

TEST(Trapezoid, NearPlaneGetsMoreTexelsThanFarPlane) {
    const TrapezoidFit fit = fitTrapezoid(orthoLight({0, -1, 0.2f}), eyeInverse());
    ASSERT_FALSE(fit.degenerate);
    // Sample just inside the hull along the centre line, 5% and 95% of the way.
    const glm::vec2 nearP = glm::mix(fit.nearCenter, fit.farCenter, 0.05f);
    const glm::vec2 farP = glm::mix(fit.nearCenter, fit.farCenter, 0.95f);
    const float dNear = density(fit.nt, nearP);
    const float dFar = density(fit.nt, farP);
    EXPECT_GT(dFar, 0.0f); // orientation preserved: face culling keeps working
    EXPECT_GT(dNear, 4.0f * dFar);

    // More texels near the eye than the uniform fallback (forced by a huge rLow) gives there.
    TrapezoidParams uniformOnly;
    uniformOnly.rLow = 1e6f;
    uniformOnly.rHigh = 2e6f;
    const TrapezoidFit uni = fitTrapezoid(orthoLight({0, -1, 0.2f}), eyeInverse(), uniformOnly);
    EXPECT_TRUE(uni.degenerate);
    EXPECT_GT(dNear, 2.0f * density(uni.nt, nearP));
}

TEST(Trapezoid, FocusPointMapsToXi) {
    for (const float fraction : {0.05f, 0.3f, 0.5f, 0.7f}) {
        TrapezoidParams params;
        params.focusFraction = fraction;
        const TrapezoidFit fit = fitTrapezoid(orthoLight({0, -1, 0}), eyeInverse(), params);
        ASSERT_FALSE(fit.degenerate);
        EXPECT_NEAR(apply(fit.nt, fit.focusPoint).y, params.xi, 1e-3f) << fraction;
        // The focus region [top, focus] covers 80% of the map's rows.
        EXPECT_NEAR((1.0f - params.xi) / 2.0f, 0.8f, 1e-6f);
    }
    // Another xi, another row.
    TrapezoidParams params;
    params.xi = 0.2f;
    params.focusFraction = 0.2f;
    const TrapezoidFit fit = fitTrapezoid(orthoLight({0, -1, 0.1f}), eyeInverse(), params);
    EXPECT_NEAR(apply(fit.nt, fit.focusPoint).y, 0.2f, 1e-3f);
}

TEST(Trapezoid, UnreachableFocusCapsEtaWithoutNaN) {
    TrapezoidParams params;
    params.focusFraction = 1.0f; // beyond 80% of the trapezoid: the rule cannot be met
    const TrapezoidFit fit = fitTrapezoid(orthoLight({0, -1, 0}), eyeInverse(), params);
    ASSERT_TRUE(finite(fit.nt));
    EXPECT_FALSE(fit.degenerate);
    EXPECT_NEAR(fit.eta, 50.0f * fit.lambda, 1e-3f * fit.lambda);
    expectHullInside(fit);
}

void expectDegenerateButSafe(const TrapezoidFit& fit) {
    EXPECT_TRUE(fit.degenerate);
    EXPECT_LT(fit.weight, 1.0f);
    ASSERT_TRUE(finite(fit.nt));
    expectHullInside(fit);
}

TEST(Trapezoid, LightAlongViewDirectionFallsBack) {
    // Light behind the camera shining forward, light facing the camera, and nearly parallel.
    for (const glm::vec3 dir : {glm::vec3(0, 0, -1), glm::vec3(0, 0, 1), glm::vec3(0, -0.01f, -1),
                                glm::vec3(0.001f, 0, 1)}) {
        const TrapezoidFit fit = fitTrapezoid(orthoLight(dir), eyeInverse());
        SCOPED_TRACE(testing::Message() << dir.x << " " << dir.y << " " << dir.z);
        expectDegenerateButSafe(fit);
        EXPECT_FLOAT_EQ(fit.weight, 0.0f);
    }
}

TEST(Trapezoid, PerspectiveLightBehindCameraFallsBack) {
    const glm::mat4 light =
        glm::perspective(glm::radians(90.0f), 1.0f, 1.0f, 100.0f) *
        glm::lookAt(glm::vec3(0, 2, 5), glm::vec3(0, 2, -10), glm::vec3(0, 1, 0));
    expectDegenerateButSafe(fitTrapezoid(light, eyeInverse()));
}

TEST(Trapezoid, EyeFrustumCrossingThePerspectiveLightPlaneFallsBack) {
    // A spot light at (0, 2, -5) pointing down: part of the frustum is behind it (w <= 0).
    const glm::mat4 light =
        glm::perspective(glm::radians(120.0f), 1.0f, 0.1f, 50.0f) *
        glm::lookAt(glm::vec3(0, 2, -5), glm::vec3(0, -10, -5), glm::vec3(1, 0, 0));
    const TrapezoidFit fit = fitTrapezoid(light, eyeInverse());
    EXPECT_LT(fit.wRel, 0.0f);
    expectDegenerateButSafe(fit);
    EXPECT_FLOAT_EQ(fit.weight, 0.0f);
}

TEST(Trapezoid, EyeBetweenLightAndItsNearPlaneStaysValid) {
    // In front of the light but closer than its near plane: w > 0, so x and y project fine;
    // only depth would be clipped, and depth does not go through N_T.
    const glm::mat4 light =
        glm::perspective(glm::radians(90.0f), 1.0f, 29.0f, 100.0f) *
        glm::lookAt(glm::vec3(0, 30, -10), glm::vec3(0, -10, -10), glm::vec3(1, 0, 0));
    const TrapezoidFit fit = fitTrapezoid(light, eyeInverse());
    ASSERT_TRUE(finite(fit.nt));
    EXPECT_GT(fit.wRel, 0.0f);
    expectHullInside(fit);
}

struct Sweep {
    float maxStep = 0.0f; // largest change of any N_T element between neighbouring steps
    bool sawFull = false, sawBlend = false, sawUniform = false;
};

// Tilts the light from straight down (theta = 0) to along the view direction (90 degrees).
Sweep sweepLight(int steps) {
    Sweep out;
    glm::mat4 prev{};
    for (int i = 0; i <= steps; ++i) {
        const float theta = glm::radians(90.0f) * float(i) / float(steps);
        const TrapezoidFit fit =
            fitTrapezoid(orthoLight({0, -std::cos(theta), -std::sin(theta)}), eyeInverse());
        EXPECT_TRUE(finite(fit.nt)) << i;
        expectHullInside(fit);
        out.sawFull |= fit.weight == 1.0f;
        out.sawBlend |= fit.weight > 0.0f && fit.weight < 1.0f;
        out.sawUniform |= fit.weight == 0.0f;
        if (i > 0)
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r)
                    out.maxStep = std::max(out.maxStep, std::abs(fit.nt[c][r] - prev[c][r]));
        prev = fit.nt;
    }
    return out;
}

TEST(Trapezoid, SweepAcrossDegeneracyIsContinuous) {
    const Sweep coarse = sweepLight(4000); // steps of 0.0225 degrees
    EXPECT_TRUE(coarse.sawFull && coarse.sawBlend && coarse.sawUniform);
    // A jump between the two maps would be of order 1 (measured: about 0.01).
    EXPECT_LT(coarse.maxStep, 0.03f);
    // Continuity proper: ten times finer steps give (about) ten times smaller changes; a jump
    // anywhere in the sweep would not shrink.
    const Sweep fine = sweepLight(40000);
    EXPECT_LT(fine.maxStep, 0.2f * coarse.maxStep);
}

// xorshift64*: a fixed-seed generator whose sequence does not depend on the standard library.
struct Rng {
    std::uint64_t s = 0x9E3779B97F4A7C15ull;
    float uniform() { // [0, 1)
        s ^= s >> 12;
        s ^= s << 25;
        s ^= s >> 27;
        return float((s * 0x2545F4914F6CDD1Dull) >> 40) / float(1u << 24);
    }
    float range(float lo, float hi) { return lo + (hi - lo) * uniform(); }
    glm::vec3 direction() {
        for (;;) {
            const glm::vec3 v(range(-1, 1), range(-1, 1), range(-1, 1));
            const float l = glm::length(v);
            if (l > 0.05f && l <= 1.0f) return v / l;
        }
    }
};

glm::vec3 safeUp(glm::vec3 d) {
    return std::abs(d.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
}

TEST(Trapezoid, RandomConfigurationsNeverProduceNaN) {
    Rng rng;
    int full = 0;
    int degenerate = 0;
    for (int i = 0; i < 1000; ++i) {
        const glm::vec3 eyePos(rng.range(-20, 20), rng.range(-20, 20), rng.range(-20, 20));
        const glm::vec3 eyeDir = rng.direction();
        const float zn = rng.range(0.01f, 2.0f);
        const glm::mat4 eyeProj =
            glm::perspective(glm::radians(rng.range(10, 120)), rng.range(0.5f, 2.0f), zn,
                             zn + rng.range(1.0f, 500.0f));
        const glm::mat4 eyeInv =
            glm::inverse(eyeProj * glm::lookAt(eyePos, eyePos + eyeDir, safeUp(eyeDir)));
        const glm::vec3 lightDir = rng.direction();
        const glm::vec3 lightPos(rng.range(-60, 60), rng.range(-60, 60), rng.range(-60, 60));
        const glm::mat4 lightView = glm::lookAt(lightPos, lightPos + lightDir, safeUp(lightDir));
        const float extent = rng.range(5.0f, 600.0f);
        const glm::mat4 lightProj =
            rng.uniform() < 0.5f ? glm::ortho(-extent, extent, -extent, extent, -extent, extent)
                                 : glm::perspective(glm::radians(rng.range(20, 150)), 1.0f,
                                                    rng.range(0.1f, 5.0f), 1000.0f);
        TrapezoidParams params;
        params.focusFraction = rng.uniform();
        const TrapezoidFit fit = fitTrapezoid(lightProj * lightView, eyeInv, params);
        SCOPED_TRACE(i);
        ASSERT_TRUE(finite(fit.nt));
        ASSERT_TRUE(std::isfinite(fit.weight) && std::isfinite(fit.eta));
        expectHullInside(fit);
        if (fit.weight == 1.0f) { // the pure trapezoid: its corners are the square's corners
            ++full;
            for (size_t k = 0; k < 4; ++k) {
                const glm::vec2 m = apply(fit.nt, fit.corners[k]);
                EXPECT_NEAR(std::abs(m.x), 1.0f, 1e-3f);
                EXPECT_NEAR(std::abs(m.y), 1.0f, 1e-3f);
            }
        }
        degenerate += fit.degenerate;
    }
    // Both regimes are exercised.
    EXPECT_GT(full, 50);
    EXPECT_GT(degenerate, 50);
}

bool sameMap(const TrapezoidFit& a, const TrapezoidFit& b) {
    return a.nt == b.nt;
}

// A camera swinging slowly sideways: the eye at x, looking along -z turned by x degrees.
glm::mat4 swungEye(float x) {
    const float a = glm::radians(x);
    return eyeInverse({x, 2, 0}, {std::sin(a), 0, -std::cos(a)});
}

// How often the map changes over 50 camera steps of `step` (in swungEye's x).
int changesAlongSwing(const TrapezoidParams& params, float step) {
    const glm::mat4 light = orthoLight({0, -1, 0.3f});
    TrapezoidFit last = fitTrapezoid(light, swungEye(0.3f), params);
    int changes = 0;
    for (int i = 1; i <= 50; ++i) {
        const TrapezoidFit fit =
            fitTrapezoid(light, swungEye(0.3f + step * float(i)), params, &last);
        expectHullInside(fit);
        changes += !sameMap(fit, last);
        last = fit;
    }
    return changes;
}

TEST(TrapezoidStable, AllMeasuresOffIsThePapersFitEveryFrame) {
    TrapezoidParams off;
    const TrapezoidFit a = fitTrapezoid(orthoLight({0, -1, 0.3f}), swungEye(0.0f), off);
    const TrapezoidFit b = fitTrapezoid(orthoLight({0, -1, 0.3f}), swungEye(0.0f), off, &a);
    EXPECT_TRUE(sameMap(a, b));
    EXPECT_FALSE(b.held) << "without hysteresis the previous fit is not read";
    // Sub-texel camera steps (1e-4 units at 20 units' depth) move the paper's fit every time.
    EXPECT_EQ(changesAlongSwing(off, 1e-4f), 50);
}

TEST(TrapezoidStable, EachMeasureKeepsTheMapUnderSubTexelMoves) {
    TrapezoidParams quantize, snap, hysteresis;
    quantize.quantize = 0.05f;
    snap.snapTexels = 4.0f;
    hysteresis.hysteresis = 0.1f;
    // 50 steps of 1e-4 (0.005 units, 0.005 degrees in all): a boundary of a step may be crossed
    // once per parameter; the continuous fit changed 50 times.
    EXPECT_LE(changesAlongSwing(quantize, 1e-4f), 3);
    EXPECT_EQ(changesAlongSwing(hysteresis, 1e-4f), 0);
    // Snapping alone leaves the direction and slopes continuous: it cannot keep the map.
    EXPECT_EQ(changesAlongSwing(snap, 1e-4f), 50);
}

TEST(TrapezoidStable, LargeMovesChangeTheMap) {
    TrapezoidParams all;
    all.quantize = 0.05f;
    all.snapTexels = 1.0f;
    all.hysteresis = 0.1f;
    // Steps of 0.5 units and 0.5 degrees: the view leaves what the kept map covers well.
    const int changes = changesAlongSwing(all, 0.5f);
    EXPECT_GE(changes, 5);
    EXPECT_LT(changes, 50);
}

TEST(TrapezoidStable, SnappedLinesLieOnTheTexelGrid) {
    TrapezoidParams snap;
    snap.snapTexels = 2.0f;
    snap.mapSize = 512;
    const double step = 2.0 * 2.0 / 512.0;
    for (float x : {0.0f, 0.37f, 1.9f}) {
        const TrapezoidFit fit = fitTrapezoid(orthoLight({0, -1, 0.3f}), swungEye(x), snap);
        ASSERT_EQ(fit.weight, 1.0f);
        // Top line (corners 0, 1) and base line (2, 3): distances along the axis from the light
        // NDC origin, whole multiples of the step; and so is the centre line's offset.
        const glm::dvec2 u(fit.axis);
        for (size_t k : {0u, 2u}) {
            const double s = glm::dot(glm::dvec2(fit.corners[k]), u) / step;
            EXPECT_NEAR(s, std::round(s), 1e-3) << x << " corner " << k;
        }
        const double offset = glm::dot(glm::dvec2(fit.q), glm::dvec2(-u.y, u.x)) / step;
        EXPECT_NEAR(offset, std::round(offset), 1e-3) << x;
    }
}

TEST(TrapezoidStable, HysteresisKeepsAFitOnlyWhileItHoldsTheView) {
    TrapezoidParams h;
    h.hysteresis = 0.1f;
    const glm::mat4 light = orthoLight({0, -1, 0.3f});
    const TrapezoidFit first = fitTrapezoid(light, swungEye(0.0f), h);
    EXPECT_FALSE(first.held);
    // The same camera again: the map stays (a frame rendered twice gives the same picture).
    const TrapezoidFit again = fitTrapezoid(light, swungEye(0.0f), h, &first);
    EXPECT_TRUE(again.held);
    EXPECT_TRUE(sameMap(first, again));
    // A view turned by 30 degrees is refitted, and the refit holds it.
    const TrapezoidFit turned = fitTrapezoid(light, swungEye(30.0f), h, &first);
    EXPECT_FALSE(turned.held);
    EXPECT_FALSE(sameMap(first, turned));
    expectHullInside(turned);
    EXPECT_FALSE(keepsPreviousFit(first, turned, 0.1f));
}

TEST(TrapezoidStable, EveryMeasureKeepsRandomFrustaInsideTheMap) {
    // Random cameras and lights, each fitted from the previous one's fit: whatever is kept or
    // rounded, the hull stays inside the map and nothing is NaN.
    Rng rng;
    TrapezoidParams all;
    all.quantize = 0.05f;
    all.snapTexels = 1.0f;
    all.hysteresis = 0.2f;
    int held = 0;
    for (int i = 0; i < 150; ++i) {
        const glm::mat4 light = orthoLight({rng.range(-0.5f, 0.5f), -1.0f, rng.range(-0.5f, 0.5f)});
        const float x = rng.range(0.0f, 10.0f);
        // Pairs of frames up to 8 units and 8 degrees apart: some kept, some refitted.
        const TrapezoidFit first = fitTrapezoid(light, swungEye(x), all);
        const TrapezoidFit second =
            fitTrapezoid(light, swungEye(x + rng.range(0.0f, 8.0f)), all, &first);
        SCOPED_TRACE(i);
        for (const TrapezoidFit* fit : {&first, &second}) {
            ASSERT_TRUE(finite(fit->nt));
            expectHullInside(*fit);
        }
        held += second.held;
    }
    EXPECT_GT(held, 0);
    EXPECT_LT(held, 150);
}

} // namespace
} // namespace fl::geom
