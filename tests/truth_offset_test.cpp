// The ray-traced truth's terminator offset where Blender Cycles applies it (issue 41 item 5): a
// receiver's answer does not depend on the ray epsilon, and the offset stays off where the
// light is not grazing, so a coarse lit terrain's cast shadows stay put (the smooth sphere's
// terminator, which the offset is for: terminator_test's TerminatorRays).

#include "RayScenes.h"

#include <raytrace/ShadowRays.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace fl::test {
namespace {

using rt::Disk;
using rt::RayScene;
using rt::Receiver;
using rt::Triangles;
using rt::VisibilitySettings;

std::vector<float> visibility(const RayScene& scene, const Disk& disk,
                              const std::vector<Receiver>& receivers, glm::vec3 eye, bool offset,
                              float epsilon) {
    VisibilitySettings s;
    s.samples = 64;
    s.terminatorOffset = offset;
    s.eye = eye;
    s.epsilon = epsilon;
    return rt::diskVisibility(scene, disk, receivers, s);
}

float maxDifference(const std::vector<float>& a, const std::vector<float>& b) {
    float worst = 0.0f;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
        worst = std::max(worst, std::abs(a[i] - b[i]));
    return worst;
}

TEST(TruthOffset, EachReceiverIsTheSameForAnyRayEpsilon) {
    // A smooth 12-segment sphere standing on a flat ground, lit from 5.7 degrees above the
    // horizon: rays leave the sphere nearly parallel to its triangles, the ground's nearly
    // parallel to it. Receivers on every triangle, corners and edges included.
    const glm::vec3 centre(0.0f, 1.0f, 0.0f);
    Triangles t = lowPolySphere(6, 12, centre);
    append(t, flatGround(0.0f, {-4, -4}, {12, 4}));
    const RayScene scene(t);
    std::vector<Receiver> receivers =
        pointsOn(lowPolySphere(6, 12, centre), 16,
                 [&](glm::vec3 p, glm::vec3 n) { return glm::dot(n, p - centre) > 0.0f; });
    const std::size_t onSphere = receivers.size();
    for (int i = 0; i <= 130; ++i)
        for (int j = 0; j <= 60; ++j)
            receivers.push_back(
                {{-3.0f + 0.1f * static_cast<float>(i), 0.0f, -3.0f + 0.1f * static_cast<float>(j)},
                 {0, 1, 0},
                 true});
    const glm::vec3 lightAt(-30.0f, 3.0f, 4.0f);
    const Disk disk{lightAt, centre - lightAt, 1.5f};
    const glm::vec3 eye(-6.0f, 5.0f, 9.0f);
    for (const bool offset : {true, false}) {
        const std::vector<float> coarse = visibility(scene, disk, receivers, eye, offset, 1e-5f);
        const std::vector<float> fine = visibility(scene, disk, receivers, eye, offset, 1e-7f);
        std::size_t differ = 0, differOnSphere = 0;
        for (std::size_t i = 0; i < coarse.size(); ++i)
            if (std::abs(coarse[i] - fine[i]) > 0.001f) {
                ++differ;
                differOnSphere += i < onSphere;
            }
        std::printf("offset %s: %zu of %zu receivers differ by more than 0.001 (%zu on the "
                    "sphere), at most %.4f\n",
                    offset ? "on" : "off", differ, coarse.size(), differOnSphere,
                    maxDifference(coarse, fine));
        EXPECT_EQ(differ, 0u) << "offset " << (offset ? "on" : "off");
        // The case holds the sphere's lit side, its terminator and its shadow on the ground.
        EXPECT_GT(std::count(coarse.begin(), coarse.end(), 0.0f), 1000);
        EXPECT_GT(std::count(coarse.begin(), coarse.end(), 1.0f), 1000);
    }
}

// A coarse terrain: 6 x 6 cells over [-4, 4]^2 (72 triangles) of a smooth height field whose
// slopes stay under 35 degrees, with the field's own normals at the vertices (its triangles are
// far from them: Hanika's offset lifts their starts by up to a tenth of a unit).
float height(float x, float z) {
    return 0.45f * std::sin(0.8f * x + 0.3f) * std::cos(0.6f * z) + 0.2f * std::sin(1.1f * z);
}
glm::vec3 heightNormal(float x, float z) {
    const float dx = 0.45f * 0.8f * std::cos(0.8f * x + 0.3f) * std::cos(0.6f * z);
    const float dz = -0.45f * 0.6f * std::sin(0.8f * x + 0.3f) * std::sin(0.6f * z) +
                     0.2f * 1.1f * std::cos(1.1f * z);
    return glm::normalize(glm::vec3(-dx, 1.0f, -dz));
}

Triangles terrain() {
    constexpr int n = 6;
    Triangles t;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const float x = -4.0f + 8.0f * static_cast<float>(i) / n;
            const float z = -4.0f + 8.0f * static_cast<float>(j) / n;
            t.vertices.emplace_back(x, height(x, z), z);
            t.normals.push_back(heightNormal(x, z));
        }
    for (std::uint32_t j = 0; j < n; ++j)
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            t.indices.insert(t.indices.end(), {a, c, b, b, c, d});
        }
    return t;
}

// A box from lo to hi with flat faces (each face its own vertices and normal).
Triangles box(glm::vec3 lo, glm::vec3 hi) {
    Triangles t;
    for (int axis = 0; axis < 3; ++axis)
        for (const float side : {-1.0f, 1.0f}) {
            glm::vec3 n(0.0f);
            n[axis] = side;
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const auto base = static_cast<std::uint32_t>(t.vertices.size());
            for (int k = 0; k < 4; ++k) {
                glm::vec3 p = side > 0.0f ? hi : lo;
                p[u] = (k == 1 || k == 2) ? hi[u] : lo[u];
                p[v] = (k >= 2) ? hi[v] : lo[v];
                t.vertices.push_back(p);
                t.normals.push_back(n);
            }
            t.indices.insert(t.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        }
    return t;
}

TEST(TruthOffset, ACoarseLitTerrainsCastShadowIsTheSameOnAndOff) {
    const Triangles ground = terrain();
    Triangles t = ground;
    const glm::vec3 foot(0.4f, height(0.4f, 0.2f), 0.2f);
    append(t, box(foot + glm::vec3(-0.3f, 0.25f, -0.3f), foot + glm::vec3(0.3f, 0.85f, 0.3f)));
    const RayScene scene(t);
    // Receivers over the terrain's triangles, on their upper side.
    const std::vector<Receiver> receivers =
        pointsOn(ground, 32, [](glm::vec3, glm::vec3 n) { return n.y > 0.0f; });
    // The light 60 degrees above the horizon, a disk of radius 1.5 at 20 units.
    const float elevation = glm::radians(60.0f);
    const glm::vec3 toLight(-std::cos(elevation), std::sin(elevation), 0.0f);
    const Disk disk{foot + 20.0f * toLight, -toLight, 1.5f};
    float leastFacing = 1.0f; // the smallest Ng.L towards the disk's centre
    for (const Receiver& r : receivers)
        leastFacing =
            std::min(leastFacing, glm::dot(r.normal, glm::normalize(disk.center - r.position)));
    const glm::vec3 eye(2.0f, 12.0f, 9.0f);
    const std::vector<float> off = visibility(scene, disk, receivers, eye, false, rt::kRayEpsilon);
    const std::vector<float> on = visibility(scene, disk, receivers, eye, true, rt::kRayEpsilon);
    // The terrain faces the light everywhere (Ng.L >= 0.5 towards the disk's centre, the disk
    // 8.6 degrees wide), far above Cycles' cut-off of 0.1: no ray is offset, so the shadow is the
    // same bit for bit.
    EXPECT_GT(leastFacing, 0.5f);
    std::size_t penumbra = 0, umbra = 0;
    for (const float v : off) {
        penumbra += v > 0.0f && v < 1.0f;
        umbra += v == 0.0f;
    }
    std::printf("terrain: %zu receivers (Ng.L >= %.3f), %zu in the box's penumbra, %zu in its "
                "umbra; on vs off at most %.4f apart\n",
                off.size(), leastFacing, penumbra, umbra, maxDifference(on, off));
    EXPECT_GT(penumbra, 100u);
    EXPECT_GT(umbra, 100u);
    EXPECT_EQ(maxDifference(on, off), 0.0f);
}

} // namespace
} // namespace fl::test
