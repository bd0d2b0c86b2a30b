// The ray-traced truth's terminator offset (raytrace/Terminator.h, Hanika 2021): flat triangles do
// not move, curved ones move out towards the smooth surface their normals describe and never in;
// Cycles' amount per ray (0 facing the light, 1 facing away, a ramp between); and through the
// shadow rays: flat scenes give the same visibility with the offset on or off,
// off is the flat triangle's answer exactly, and on lights the terminator of a low-poly sphere.

#include "RayScenes.h"

#include <raytrace/ShadowRays.h>
#include <raytrace/Terminator.h>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace {

using fl::rt::Disk;
using fl::rt::RayScene;
using fl::rt::Receiver;
using fl::rt::terminatorOffset;
using fl::rt::Triangles;
using fl::rt::VisibilitySettings;
using fl::test::lowPolySphere;

using Corners = std::array<glm::vec3, 3>;

// Barycentrics (u, v) over the triangle, corners and edges included.
std::vector<glm::vec2> barycentricGrid() {
    std::vector<glm::vec2> out;
    for (int i = 0; i <= 8; ++i)
        for (int j = 0; i + j <= 8; ++j) out.emplace_back(i / 8.0f, j / 8.0f);
    return out;
}

glm::vec3 at(const Corners& c, glm::vec2 uv) {
    return (1.0f - uv.x - uv.y) * c[0] + uv.x * c[1] + uv.y * c[2];
}

TEST(TerminatorOffset, AFlatTriangleDoesNotMove) {
    const Corners c{glm::vec3(0.3f, -1.2f, 2.0f), glm::vec3(4.1f, 0.7f, -1.0f),
                    glm::vec3(-2.0f, 3.3f, 0.5f)};
    const glm::vec3 n = glm::normalize(glm::cross(c[1] - c[0], c[2] - c[0]));
    // The face's normal as a file or a transform gives it: off the plane's by float rounding.
    const glm::vec3 rounded = glm::normalize(n + glm::vec3(3e-7f, -2e-7f, 1e-7f));
    for (const glm::vec3 side : {n, -n}) // seen from the front, and from behind
        for (const glm::vec2 uv : barycentricGrid()) {
            SCOPED_TRACE(testing::Message() << "u " << uv.x << " v " << uv.y);
            EXPECT_FALSE(terminatorOffset(at(c, uv), c, {n, n, n}, uv.x, uv.y, side));
            EXPECT_FALSE(terminatorOffset(at(c, uv), c, {rounded, n, rounded}, uv.x, uv.y, side));
        }
}

TEST(TerminatorOffset, ACurvedTriangleMovesOutTowardsTheSmoothSurfaceNeverIn) {
    // An octahedron's face of the unit sphere, with the sphere's normals: the flat triangle lies
    // inside the sphere (its centre at 0.577 of the radius).
    const Corners c{glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)};
    const glm::vec3 plane = glm::normalize(glm::vec3(1));
    for (const glm::vec2 uv : barycentricGrid()) {
        SCOPED_TRACE(testing::Message() << "u " << uv.x << " v " << uv.y);
        const glm::vec3 p = at(c, uv);
        const auto s = terminatorOffset(p, c, c, uv.x, uv.y, plane);
        ASSERT_TRUE(s.has_value());
        const glm::vec3 move = s->position - p;
        EXPECT_GE(glm::dot(move, plane), 0.0f) << "moved inward";
        EXPECT_NEAR(glm::length(s->normal), 1.0f, 1e-5f);
        EXPECT_GT(glm::dot(s->normal, plane), 0.0f);
        const bool corner = std::max({uv.x, uv.y, 1.0f - uv.x - uv.y}) > 0.999f;
        if (corner) {
            EXPECT_LT(glm::length(move), 1e-6f) << "a vertex lies on the smooth surface already";
            continue;
        }
        // Off the corners, strictly out, and nearer the sphere than the flat triangle is.
        EXPECT_GT(glm::dot(move, plane), 1e-3f);
        EXPECT_LT(std::abs(glm::length(s->position) - 1.0f), 1.0f - glm::length(p));
    }
    // At the centre Hanika's blend gives (5/9, 5/9, 5/9): 0.962 of the radius.
    const auto centre =
        terminatorOffset(glm::vec3(1.0f / 3.0f), c, c, 1.0f / 3.0f, 1.0f / 3.0f, plane);
    ASSERT_TRUE(centre.has_value());
    EXPECT_NEAR(centre->position.x, 5.0f / 9.0f, 1e-5f);
    EXPECT_NEAR(centre->position.z, 5.0f / 9.0f, 1e-5f);
}

TEST(TerminatorOffset, SeenFromBehindItMovesOnTheSeenSideOrNotAtAll) {
    // The same face seen from inside the sphere (a double-sided material): the normals are
    // flipped to the seen side, where the smooth surface is concave: no projection moves out.
    const Corners c{glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)};
    const glm::vec3 inside = -glm::normalize(glm::vec3(1));
    for (const glm::vec2 uv : barycentricGrid()) {
        const auto s = terminatorOffset(at(c, uv), c, c, uv.x, uv.y, inside);
        ASSERT_TRUE(s.has_value());
        EXPECT_EQ(s->position, at(c, uv));
        EXPECT_GT(glm::dot(s->normal, inside), 0.0f);
    }
}

TEST(TerminatorOffset, NoSmoothSurfaceWithoutUnitNormalsOrArea) {
    const Corners c{glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)};
    const glm::vec3 p(1.0f / 3.0f), up = glm::normalize(glm::vec3(1));
    const float nan = std::nanf("");
    EXPECT_FALSE(terminatorOffset(p, c, {c[0], c[1], glm::vec3(nan)}, 0.3f, 0.3f, up));
    EXPECT_FALSE(terminatorOffset(p, c, {c[0], c[1], 2.0f * c[2]}, 0.3f, 0.3f, up));
    const Corners line{glm::vec3(0), glm::vec3(1, 0, 0), glm::vec3(2, 0, 0)};
    EXPECT_FALSE(terminatorOffset(glm::vec3(0.5f, 0, 0), line, c, 0.25f, 0.0f, up));
}

TEST(TerminatorOffset, CyclesAmountIsZeroFacingTheLightOneFacingAwayARampBetween) {
    using fl::rt::offsetAmount;
    constexpr float c = fl::rt::kGeometryOffset;
    // Both normals face the light by c or more: no offset (most rays).
    EXPECT_EQ(offsetAmount(0.5f, 0.5f, c), 0.0f);
    EXPECT_EQ(offsetAmount(c, c, c), 0.0f);
    EXPECT_EQ(offsetAmount(1.0f, c, c), 0.0f);
    // The triangle faces away while its smooth surface faces the light: the whole offset.
    EXPECT_EQ(offsetAmount(0.5f, 0.0f, c), 1.0f);
    EXPECT_EQ(offsetAmount(0.05f, -0.2f, c), 1.0f);
    // Between: 1 - Ng.L / c above N.L = c, 2 - (Ng.L + N.L) / c below, equal at N.L = c.
    EXPECT_NEAR(offsetAmount(0.5f, 0.25f * c, c), 0.75f, 1e-6f);
    EXPECT_NEAR(offsetAmount(0.5f * c, 0.75f * c, c), 0.75f, 1e-6f);
    EXPECT_NEAR(offsetAmount(c, 0.5f * c, c), offsetAmount(std::nextafter(c, 0.0f), 0.5f * c, c),
                1e-5f);
    // A cut-off of 0 is Cycles' "off".
    EXPECT_EQ(offsetAmount(0.5f, -0.5f, 0.0f), 0.0f);
}

// A receiver on the sphere's flat triangles, with the eye that sees it (out along the plane).
struct SpherePoint {
    Receiver receiver;
    glm::vec3 eye;
    glm::vec3 smooth; // the normals blended at the point
};

std::vector<SpherePoint> spherePoints(const Triangles& t) {
    std::vector<SpherePoint> out;
    for (std::size_t i = 0; i < t.indices.size(); i += 3) {
        const Corners c{t.vertices[t.indices[i]], t.vertices[t.indices[i + 1]],
                        t.vertices[t.indices[i + 2]]};
        glm::vec3 n = glm::normalize(glm::cross(c[1] - c[0], c[2] - c[0]));
        if (glm::dot(n, c[0] + c[1] + c[2]) < 0.0f) n = -n; // outward, seen from outside
        for (const glm::vec2 uv : barycentricGrid()) {
            if (std::min({uv.x, uv.y, 1.0f - uv.x - uv.y}) < 0.1f) continue; // inside, off edges
            const glm::vec3 p = at(c, uv);
            const glm::vec3 smooth = glm::normalize((1.0f - uv.x - uv.y) * t.normals[t.indices[i]] +
                                                    uv.x * t.normals[t.indices[i + 1]] +
                                                    uv.y * t.normals[t.indices[i + 2]]);
            out.push_back({{p, n, true}, p + 2.0f * n, smooth});
        }
    }
    return out;
}

float visibility(const RayScene& scene, const Disk& disk, const SpherePoint& p, bool offset) {
    VisibilitySettings s;
    s.samples = 64;
    s.terminatorOffset = offset;
    s.eye = p.eye;
    const std::vector<Receiver> one{p.receiver};
    return fl::rt::diskVisibility(scene, disk, one, s)[0];
}

// A light far to the side of the sphere (its disk 1.4 degrees wide seen from it).
const Disk kSideLight{{20, 0.3f, 0.2f}, {-1, 0, 0}, 0.5f};

TEST(TerminatorRays, OffIsTheFlatTriangleExactly) {
    // Off, the normals are not read: the same visibility as a scene without them, for which the
    // offset cannot apply.
    const Triangles curved = lowPolySphere(6, 8);
    Triangles bare = curved;
    bare.normals.clear();
    const RayScene withNormals(curved), without(bare);
    int compared = 0;
    for (const SpherePoint& p : spherePoints(curved)) {
        EXPECT_EQ(visibility(withNormals, kSideLight, p, false),
                  visibility(without, kSideLight, p, true));
        ++compared;
    }
    EXPECT_GT(compared, 500);
}

TEST(TerminatorRays, OnLightsTheTerminatorOfALowPolySphere) {
    // 4 rings of 6 segments: 45 and 60 degrees between neighbouring normals, so that points off
    // the triangles' edges (spherePoints) still sit on both sides of the terminator.
    const Triangles t = lowPolySphere(4, 6);
    const RayScene scene(t);
    int terminator = 0, litOn = 0, litOff = 0, front = 0;
    for (const SpherePoint& p : spherePoints(t)) {
        const glm::vec3 toLight = glm::normalize(kSideLight.center - p.receiver.position);
        const float flat = glm::dot(p.receiver.normal, toLight);
        const float smooth = glm::dot(p.smooth, toLight);
        if (flat < 0.0f && smooth > 0.1f) {
            // The terminator: the triangle faces away, its smooth surface faces the light.
            ++terminator;
            litOff += visibility(scene, kSideLight, p, false) > 0.0f ? 1 : 0;
            litOn += visibility(scene, kSideLight, p, true) > 0.5f ? 1 : 0;
        } else if (flat > 0.05f && smooth > 0.05f) {
            // Facing the light both ways: lit, offset or not (a convex body shades nothing).
            ++front;
            EXPECT_EQ(visibility(scene, kSideLight, p, false), 1.0f);
            EXPECT_EQ(visibility(scene, kSideLight, p, true), 1.0f);
        }
    }
    ASSERT_GT(terminator, 20) << "the sphere must show a terminator";
    ASSERT_GT(front, 100);
    EXPECT_EQ(litOff, 0) << "off: the triangle's plane blocks the light";
    EXPECT_EQ(litOn, terminator) << "on: the smooth surface sees more than half the disk";
}

TEST(TerminatorRays, FlatScenesAreTheSameOnAndOff) {
    // The closed-form cases' kind of geometry: a ground and a floating square, every vertex
    // normal the face's. The offset must change nothing, bit for bit.
    Triangles t;
    t.vertices = {{-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5},
                  {-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}};
    t.indices = {0, 2, 1, 0, 3, 2, 4, 6, 5, 4, 7, 6};
    t.normals.assign(t.vertices.size(), glm::vec3(0, 1, 0));
    const RayScene scene(t);
    std::vector<Receiver> receivers;
    for (int i = 0; i <= 40; ++i)
        for (int j = 0; j <= 40; ++j)
            receivers.push_back({{-4.0f + 0.2f * i, 0.0f, -4.0f + 0.2f * j}, {0, 1, 0}, true});
    VisibilitySettings s;
    s.samples = 64;
    s.eye = glm::vec3(0.5f, 8.0f, 6.0f);
    const Disk disk{{0.3f, 5, 0.1f}, {0, -1, 0}, 1.0f};
    s.terminatorOffset = false;
    const std::vector<float> off = fl::rt::diskVisibility(scene, disk, receivers, s);
    s.terminatorOffset = true;
    const std::vector<float> on = fl::rt::diskVisibility(scene, disk, receivers, s);
    EXPECT_EQ(on, off);
    // The case holds shadow, penumbra and light.
    EXPECT_NE(std::count(off.begin(), off.end(), 0.0f), 0);
    EXPECT_NE(std::count(off.begin(), off.end(), 1.0f), 0);
    EXPECT_NE(std::count_if(off.begin(), off.end(), [](float v) { return v > 0 && v < 1; }), 0);
}

} // namespace
