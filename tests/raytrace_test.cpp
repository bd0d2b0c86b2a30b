// The ray-traced ground truth (raytrace/ShadowRays.h) against answers known in closed form: a
// straight occluder edge under a disk light, full occlusion and none, convergence in N, and the
// same result for any thread count.

#include <raytrace/ShadowRays.h>
#include <scene/ClosedForm.h>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace {

using fl::rt::Disk;
using fl::rt::RayScene;
using fl::rt::Receiver;
using fl::rt::Triangles;
using fl::rt::VisibilitySettings;

// A square at height `h` covering the half-plane on the far side of a line through the origin:
// the points (x, h, z) with dot((x, z), out) < 0, out = (cos a, sin a); 200 units wide.
Triangles halfPlane(float h, float angle) {
    const glm::vec2 out(std::cos(angle), std::sin(angle)), along(-out.y, out.x);
    const auto at = [&](float o, float a) {
        const glm::vec2 p = o * out + a * along;
        return glm::vec3(p.x, h, p.y);
    };
    return {{at(0, -100), at(0, 100), at(-200, 100), at(-200, -100)}, {0, 1, 2, 0, 2, 3}};
}

struct EdgeCase {
    float h, H, r, angle;
};

// RMSE and max error along a line across the penumbra (201 ground points through the edge's
// shadow, across the whole penumbra and a little lit and shadowed ground on each side).
struct LineError {
    double rmse = 0, maxAbs = 0;
};
LineError edgeError(const EdgeCase& c, const VisibilitySettings& s) {
    const RayScene scene(halfPlane(c.h, c.angle));
    const Disk disk{{0, c.H, 0}, {0, -1, 0}, c.r};
    const double half = 1.5 * c.r * c.h / (c.H - c.h); // the penumbra's half-width, with margin
    const glm::vec2 out(std::cos(c.angle), std::sin(c.angle));
    std::vector<Receiver> receivers;
    std::vector<double> exact;
    for (int i = 0; i <= 200; ++i) {
        const double x = -half + 2.0 * half * i / 200.0;
        const glm::vec2 p = static_cast<float>(x) * out;
        receivers.push_back({{p.x, 0.0f, p.y}, {0, 1, 0}, true});
        exact.push_back(fl::straightEdgeVisibility(x, c.h, c.H, c.r));
    }
    const std::vector<float> v = fl::rt::diskVisibility(scene, disk, receivers, s);
    LineError e;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const double d = v[i] - exact[i];
        e.rmse += d * d;
        e.maxAbs = std::max(e.maxAbs, std::abs(d));
    }
    e.rmse = std::sqrt(e.rmse / static_cast<double>(v.size()));
    return e;
}

// A stratified estimate's error comes from the strata the chord crosses: at most about 2 sqrt(N)
// of the N cells (the concentric map bends the chord's image in the square), each a coin flip of
// variance <= 1/4 and weight 1/N, so the standard deviation is <= sqrt(2 sqrt(N) / 4) / N.
double stratifiedSigma(int n) {
    return std::sqrt(2.0 * std::sqrt(static_cast<double>(n)) / 4.0) / n;
}

TEST(RayTraceTest, StraightEdgeMatchesTheClosedFormAtEveryAngleAndHeight) {
    for (const EdgeCase c :
         {EdgeCase{1.0f, 5.0f, 0.5f, 0.0f}, EdgeCase{2.0f, 5.0f, 1.0f, 0.5f},
          EdgeCase{0.5f, 8.0f, 1.5f, 0.785398f}, EdgeCase{3.0f, 4.0f, 0.25f, 2.0f}}) {
        VisibilitySettings s;
        s.samples = 256;
        const LineError e = edgeError(c, s);
        SCOPED_TRACE(::testing::Message()
                     << "h " << c.h << " H " << c.H << " r " << c.r << " angle " << c.angle);
        // RMSE within one sigma-bound, each point within 4.5 (201 points: 4.5 sigma is
        // exceeded by chance about once in 10^3 runs of 201, and the hash is fixed).
        EXPECT_LT(e.rmse, stratifiedSigma(s.samples));
        EXPECT_LT(e.maxAbs, 4.5 * stratifiedSigma(s.samples));
    }
}

TEST(RayTraceTest, DiskOccluderMatchesTheClosedForm) {
    // The closed-form case's own occluder (a 128-gon of the disk's area) cast on the CPU, points
    // along a radius from under the centre to past the penumbra.
    const fl::ClosedFormCase c = fl::diskOccluderCase(0.6f, 1.5f, 5.0f, 1.0f);
    Triangles t;
    const fl::Mesh& m = c.scene.meshes[1];
    t.vertices = m.positions;
    t.indices = m.indices;
    const RayScene scene(t);
    std::vector<Receiver> r;
    for (int i = 0; i <= 150; ++i) r.push_back({{0.01f * i, 0, 0.004f * i}, {0, 1, 0}, true});
    VisibilitySettings s;
    s.samples = 1024;
    const std::vector<float> v = fl::rt::diskVisibility(scene, {{0, 5, 0}, {0, -1, 0}, 1.0f}, r, s);
    double worst = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i)
        worst = std::max(worst, std::abs(v[i] - c.exact(r[i].position)));
    EXPECT_LT(worst, 4.5 * stratifiedSigma(s.samples));
    // Under the centre the occluder hides the whole light (it covers a disk of radius 2 there).
    EXPECT_EQ(fl::diskOccluderVisibility(0.0, 0.6, 1.5, 5.0, 1.0), 0.0);
    EXPECT_EQ(fl::diskOccluderVisibility(10.0, 0.6, 1.5, 5.0, 1.0), 1.0);
}

TEST(RayTraceTest, GridSamplesBandAlongStraightEdgesJitteredOnesDoNot) {
    // The shadow-map reference places its point lights at the strata's centres; along a straight
    // edge parallel to the grid that is a staircase with steps of 1/cols of the disk. Jittered
    // strata (the ray tracer's default) have no such bias.
    const EdgeCase c{1.0f, 5.0f, 1.0f, 0.0f};
    VisibilitySettings grid;
    grid.samples = 256;
    grid.jitter = false;
    VisibilitySettings jittered = grid;
    jittered.jitter = true;
    const LineError g = edgeError(c, grid), j = edgeError(c, jittered);
    // Half a step of the staircase is up to 1/32 of the disk near its middle (0.024 measured).
    EXPECT_GT(g.maxAbs, 0.015);
    EXPECT_LT(j.rmse, g.rmse);
}

TEST(RayTraceTest, ConvergesInN) {
    const EdgeCase c{1.0f, 5.0f, 1.0f, 0.3f};
    double previous = 1.0;
    for (int n : {16, 64, 256, 1024}) {
        VisibilitySettings s;
        s.samples = n;
        const LineError e = edgeError(c, s);
        SCOPED_TRACE(n);
        EXPECT_LT(e.rmse, previous);
        EXPECT_LT(e.rmse, stratifiedSigma(n));
        previous = e.rmse;
    }
}

TEST(RayTraceTest, FullyOccludedIsZeroUnoccludedIsOne) {
    const RayScene scene(halfPlane(1.0f, 0.0f));
    const Disk disk{{0, 5, 0}, {0, -1, 0}, 0.5f};
    // Deep under the occluder; far out on the lit side; background (not a receiver); a surface
    // facing away from the light (its own surface blocks every ray).
    const std::vector<Receiver> r = {{{-10, 0, 0}, {0, 1, 0}, true},
                                     {{10, 0, 0}, {0, 1, 0}, true},
                                     {{-10, 0, 0}, {0, 1, 0}, false},
                                     {{10, -1, 0}, {0, 0, 0}, true},
                                     {{10, 0.5f, 0}, {-1, 0, 0}, true}};
    VisibilitySettings s;
    s.samples = 64;
    fl::rt::RayCounts rays;
    const std::vector<float> v = fl::rt::diskVisibility(scene, disk, r, s, &rays);
    EXPECT_EQ(v[0], 0.0f);
    EXPECT_EQ(v[1], 1.0f);
    EXPECT_EQ(v[2], 1.0f);
    EXPECT_EQ(v[3], 1.0f); // no normal: no surface of its own to block it
    // A wall at x = 10 whose normal is given as -x: it faces the light's centre (x = 0), and the
    // whole disk (|x| <= 0.5) is in front of it, above the occluder's edge: all lit.
    EXPECT_EQ(v[4], 1.0f);
    EXPECT_EQ(rays.cast, 4u * 64u);
    EXPECT_EQ(rays.offset, 0u);   // no normals: nothing to offset
    EXPECT_EQ(rays.unplaced, 4u); // the receivers lie on no triangle of the scene
}

// Alpha cut-outs: a hit where transmits() says so is no hit, and the ray goes on to what lies
// behind; only flagged triangles are asked.
TEST(RayTraceTest, CutOutTrianglesLetRaysThroughWhereTheyTransmit) {
    Triangles upper = halfPlane(1.0f, 0.0f), lower = halfPlane(0.5f, 0.0f);
    const Disk disk{{0, 5, 0}, {0, -1, 0}, 0.5f};
    const std::vector<Receiver> deep = {{{-10, 0, 0}, {0, 1, 0}, true}};
    VisibilitySettings s;
    s.samples = 16;
    upper.cutOut = {1, 1};
    upper.transmits = [](std::uint32_t, float, float) { return true; };
    EXPECT_EQ(fl::rt::diskVisibility(RayScene(upper), disk, deep, s)[0], 1.0f)
        << "a fully transparent occluder blocks nothing";
    upper.transmits = [](std::uint32_t, float, float) { return false; };
    EXPECT_EQ(fl::rt::diskVisibility(RayScene(upper), disk, deep, s)[0], 0.0f);
    // The transparent layer above an opaque one: traversal goes on and finds the opaque one.
    Triangles both = upper;
    both.transmits = [](std::uint32_t t, float, float) { return t < 2; };
    const auto base = static_cast<std::uint32_t>(both.vertices.size());
    both.vertices.insert(both.vertices.end(), lower.vertices.begin(), lower.vertices.end());
    for (std::uint32_t i : lower.indices) both.indices.push_back(base + i);
    both.cutOut = {1, 1, 0, 0};
    EXPECT_EQ(fl::rt::diskVisibility(RayScene(both), disk, deep, s)[0], 0.0f);
    // The hits lie in triangle 0 around (-8, 1, 0), where u + v = 0.5 + z / 200: transmitting
    // where u + v > 0.5 lets the rays with z > 0 through, so the hit's barycentrics reach the test.
    upper.transmits = [](std::uint32_t, float u, float v) { return u + v > 0.5f; };
    const float half = fl::rt::diskVisibility(RayScene(upper), disk, deep, s)[0];
    EXPECT_GT(half, 0.0f);
    EXPECT_LT(half, 1.0f);
    // Flags that are not one per triangle, or flags without a test, are refused.
    upper.cutOut = {1};
    EXPECT_THROW(RayScene{upper}, std::invalid_argument);
    upper.cutOut = {1, 0};
    upper.transmits = nullptr;
    EXPECT_THROW(RayScene{upper}, std::invalid_argument);
}

TEST(RayTraceTest, TheSameForAnyThreadCount) {
    const RayScene scene(halfPlane(1.0f, 0.4f));
    const Disk disk{{0, 5, 0}, {0, -1, 0}, 1.0f};
    std::vector<Receiver> r;
    for (int i = 0; i < 3000; ++i)
        r.push_back(
            {{-2.0f + 4.0f * static_cast<float>(i) / 3000.0f, 0, 0.1f * (i % 7)}, {0, 1, 0}, true});
    VisibilitySettings s;
    s.samples = 64;
    s.threads = 1;
    const std::vector<float> one = fl::rt::diskVisibility(scene, disk, r, s);
    for (int threads : {2, 3, 8}) {
        s.threads = threads;
        EXPECT_EQ(fl::rt::diskVisibility(scene, disk, r, s), one) << threads << " threads";
    }
}

TEST(RayTraceTest, ProgressRisesToOneOnTheCallersThread) {
    const RayScene scene(halfPlane(1.0f, 0.4f));
    std::vector<Receiver> r(5000, Receiver{{0.1f, 0, 0}, {0, 1, 0}, true});
    VisibilitySettings s;
    s.samples = 16;
    s.threads = 2;
    std::vector<double> seen;
    const std::thread::id caller = std::this_thread::get_id();
    s.progress = [&](double done) {
        EXPECT_EQ(std::this_thread::get_id(), caller);
        seen.push_back(done);
    };
    (void)fl::rt::diskVisibility(scene, {{0, 5, 0}, {0, -1, 0}, 1.0f}, r, s);
    ASSERT_FALSE(seen.empty());
    EXPECT_EQ(seen.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_LE(seen.size(), 102u);
}

TEST(RayTraceTest, RefitEqualsAFreshBuild) {
    RayScene moved(halfPlane(1.0f, 0.0f));
    const Triangles target = halfPlane(2.0f, 0.0f);
    moved.refit(target.vertices);
    const RayScene fresh(target);
    const Disk disk{{0, 5, 0}, {0, -1, 0}, 1.0f};
    std::vector<Receiver> r;
    for (int i = 0; i <= 100; ++i) r.push_back({{-3.0f + 0.06f * i, 0, 0}, {0, 1, 0}, true});
    VisibilitySettings s;
    s.samples = 64;
    EXPECT_EQ(fl::rt::diskVisibility(moved, disk, r, s), fl::rt::diskVisibility(fresh, disk, r, s));
}

TEST(RayTraceTest, BadInputIsRefusedWithTheElementNamed) {
    Triangles t = halfPlane(1.0f, 0.0f);
    t.vertices[2].y = std::nanf("");
    try {
        RayScene bad(t);
        FAIL() << "a NaN vertex was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("vertex 2 is not finite"), std::string::npos)
            << e.what();
    }
    t = halfPlane(1.0f, 0.0f);
    t.vertices[1].x = 1e30f;
    EXPECT_THROW(RayScene{t}, std::invalid_argument);
    t = halfPlane(1.0f, 0.0f);
    t.indices[4] = 7;
    EXPECT_THROW(RayScene{t}, std::invalid_argument);
    const RayScene scene(halfPlane(1.0f, 0.0f));
    const std::vector<Receiver> r = {{{0, 0, 0}, {0, 1, 0}, true}};
    for (int n : {0, -3, fl::rt::kMaxSamples + 1}) {
        VisibilitySettings s;
        s.samples = n;
        EXPECT_THROW((void)fl::rt::diskVisibility(scene, {{0, 5, 0}, {0, -1, 0}, 1}, r, s),
                     std::invalid_argument)
            << n;
    }
    RayScene refit(halfPlane(1.0f, 0.0f));
    EXPECT_THROW(refit.refit(std::vector<glm::vec3>(3)), std::invalid_argument);
}

} // namespace
