// scene/Ground.h: `--ground auto` adds a ground under a model that stands on nothing
// and leaves a scene with its own floor or terrain as it is.

#include "TestPaths.h"
#include "TestScenes.h"

#include <scene/Camera.h>
#include <scene/DiskLight.h>
#include <scene/GltfLoader.h>
#include <scene/Ground.h>
#include <scene/SceneGenerator.h>

#include <base/Framing.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace fl {
namespace {

// An axis-aligned box from `lo` to `hi` as one more instance.
void addBox(Scene& s, glm::vec3 lo, glm::vec3 hi) {
    s.meshes.push_back(test::box(lo, hi));
    Instance inst;
    inst.mesh = static_cast<int>(s.meshes.size()) - 1;
    inst.objectId = static_cast<std::uint32_t>(s.instances.size()) + 1;
    s.instances.push_back(inst);
    s.computeBounds();
}

// A flat quad at height y over [lo, hi] in x and z, facing up.
void addFloor(Scene& s, float y, glm::vec2 lo, glm::vec2 hi) {
    Mesh m;
    m.positions = {{lo.x, y, lo.y}, {hi.x, y, lo.y}, {hi.x, y, hi.y}, {lo.x, y, hi.y}};
    m.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
    m.indices = {0, 2, 1, 0, 3, 2};
    s.meshes.push_back(m);
    Instance inst;
    inst.mesh = static_cast<int>(s.meshes.size()) - 1;
    s.instances.push_back(inst);
    s.computeBounds();
}

TEST(Ground, OurScenesHaveTheirOwn) {
    EXPECT_TRUE(hasGround(loadGltf(test::defaultAsset())));
    for (const NamedSize& size : thesisSceneSizes()) {
        if (size.triangles > 10000) continue; // the larger ones are the same layout, denser
        const Scene s = generateScene({size.triangles, 1});
        EXPECT_TRUE(hasGround(s)) << size.name << ": " << groundCoverage(s);
    }
}

TEST(Ground, AModelOnNothingGetsOneAndAFlooredOneDoesNot) {
    Scene box;
    addBox(box, {0, 0, 0}, {1, 2, 1});
    // Its top is the only upward face, at the top of the bounds: not a ground.
    EXPECT_EQ(groundCoverage(box), 0.0);
    Scene floored = box;
    addFloor(floored, 0.0f, {-3, -3}, {4, 4});
    EXPECT_GT(groundCoverage(floored), 0.99);
    EXPECT_TRUE(hasGround(floored));
    // A plinth under the whole footprint, low down, is a ground too.
    Scene plinth = box;
    addBox(plinth, {-0.2f, -0.2f, -0.2f}, {1.2f, 0.0f, 1.2f});
    EXPECT_TRUE(hasGround(plinth)) << groundCoverage(plinth);
    // A roof over nothing (a table top, high up) is not.
    Scene table;
    addBox(table, {0, 1.8f, 0}, {3, 2, 3});
    addBox(table, {0, 0, 0}, {0.2f, 1.8f, 0.2f});
    EXPECT_FALSE(hasGround(table)) << groundCoverage(table);
}

TEST(Ground, AddedUnderTheBoundsReachingPastTheFootprint) {
    Scene box;
    addBox(box, {0, 0, 0}, {1, 2, 1});
    const geom::Aabb before = box.bounds;
    ASSERT_TRUE(applyGround(box, GroundMode::Auto));
    ASSERT_EQ(box.instances.size(), 2u);
    const Mesh& g = box.meshes.at(static_cast<std::size_t>(box.instances.back().mesh));
    EXPECT_EQ(g.name, "floodlight ground");
    EXPECT_EQ(box.materials.at(static_cast<std::size_t>(g.material)).name, "floodlight ground");
    EXPECT_NE(box.instances.back().objectId, box.instances.front().objectId);
    // Just under the model; past its footprint by 0.75 x its height (2) on every side.
    EXPECT_LE(box.bounds.min.y, before.min.y);
    EXPECT_GT(box.bounds.min.y, before.min.y - 1e-3f);
    EXPECT_NEAR(box.bounds.min.x, 0.5f - 0.5f - 1.5f, 1e-5f);
    EXPECT_NEAR(box.bounds.max.z, 0.5f + 0.5f + 1.5f, 1e-5f);
    EXPECT_EQ(box.bounds.max.y, before.max.y);
    // Its face points up, and it now counts as the scene's ground.
    const glm::vec3 n = glm::cross(g.positions[g.indices[1]] - g.positions[g.indices[0]],
                                   g.positions[g.indices[2]] - g.positions[g.indices[0]]);
    EXPECT_GT(n.y, 0.0f);
    EXPECT_TRUE(hasGround(box));
    EXPECT_FALSE(applyGround(box, GroundMode::Auto)); // not twice
}

// An octahedron (vertices at +-1 on each axis) placed by a node turned 45 degrees about x, then
// 45 about z, written and loaded as a file. Its lowest vertex is at y = -0.707; the corners of its
// own box, turned the same way, reach y = -1.707 (the bounds before issue 41 item 6).
TEST(Ground, ARotatedModelsGroundTouchesItsLowestVertex) {
    Scene s;
    Mesh m;
    m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    m.normals = m.positions;
    for (std::uint32_t x : {0u, 1u})
        for (std::uint32_t y : {2u, 3u})
            for (std::uint32_t z : {4u, 5u}) {
                // Counter-clockwise seen from outside: an even number of negative axes.
                const bool outward = ((x == 0) == (y == 2)) == (z == 4);
                m.indices.insert(m.indices.end(), {x, outward ? y : z, outward ? z : y});
            }
    s.meshes.push_back(m);
    const glm::mat4 turn =
        glm::rotate(glm::rotate(glm::mat4(1.0f), glm::radians(45.0f), glm::vec3(0, 0, 1)),
                    glm::radians(45.0f), glm::vec3(1, 0, 0));
    s.instances.push_back(
        Instance{0, glm::translate(glm::mat4(1.0f), {2, 3, -1}) * turn, 1, "gem"});
    s.computeBounds();
    const auto file = test::outputDir("ground") / "turned_octahedron.glb";
    writeGlb(s, file);
    Scene loaded = loadGltf(file);
    ASSERT_EQ(loaded.instances.size(), 1u);

    // The box of the vertices as the vertex stage places them.
    geom::Aabb tight;
    for (const glm::vec3& p : loaded.meshes[0].positions)
        tight.extend(glm::vec3(loaded.instances[0].world * glm::vec4(p, 1.0f)));
    EXPECT_NEAR(tight.min.y, 3.0f - std::sqrt(0.5f), 1e-5f);
    EXPECT_EQ(loaded.bounds.min, tight.min);
    EXPECT_EQ(loaded.bounds.max, tight.max);

    // The default light, its disk and the automatic view come from those bounds (what the
    // renderer and the ray tracer are handed: Renderer's disk is makeDiskLight of these).
    Scene reference = loaded;
    reference.bounds = tight;
    const Light light = sceneLight(loaded);
    EXPECT_EQ(light.position, sceneLight(reference).position);
    EXPECT_EQ(makeDiskLight(light, loaded.bounds).center,
              makeDiskLight(sceneLight(reference), tight).center);
    const CameraSpec automatic{CameraSpec::Kind::Auto};
    EXPECT_EQ(makeCameraView(loaded, automatic, 1.0f).view,
              makeCameraView(reference, automatic, 1.0f).view);

    // The added ground lies just under the lowest vertex: 1e-4 of the scene's radius below it
    // (Ground.cpp: no depth fight with a flat underside), within float rounding.
    ASSERT_TRUE(applyGround(loaded, GroundMode::Auto));
    const Mesh& g = loaded.meshes.at(static_cast<std::size_t>(loaded.instances.back().mesh));
    const float radius = tight.radius();
    for (const glm::vec3& p : g.positions) {
        EXPECT_LT(p.y, tight.min.y);
        EXPECT_NEAR(p.y, tight.min.y - 1e-4f * radius, 1e-6f * radius);
    }
}

TEST(Ground, OnAndOffOverrideTheRule) {
    Scene floored;
    addFloor(floored, 0.0f, {0, 0}, {1, 1});
    Scene alone;
    addBox(alone, {0, 0, 0}, {1, 1, 1});
    EXPECT_FALSE(applyGround(alone, GroundMode::Off));
    EXPECT_EQ(alone.instances.size(), 1u);
    EXPECT_TRUE(applyGround(floored, GroundMode::On));
    EXPECT_EQ(floored.instances.size(), 2u);
    EXPECT_EQ(parseGroundMode("auto"), GroundMode::Auto);
    EXPECT_EQ(parseGroundMode("on"), GroundMode::On);
    EXPECT_EQ(parseGroundMode("off"), GroundMode::Off);
    EXPECT_FALSE(parseGroundMode("yes"));
}

// The box around modelAndShadowPoints; invalid when there are none.
geom::Aabb shadowFrame(const Scene& s, const Light& light) {
    geom::Aabb b;
    for (const glm::vec3& p : modelAndShadowPoints(s, light)) b.extend(p);
    return b;
}

// The first view frames the model and its shadow on the added ground (issue 30 item 6).
TEST(Ground, TheModelAndItsShadowOnTheAddedGround) {
    Scene box;
    addBox(box, {0, 0, 0}, {1, 2, 1});
    Light light;
    light.type = Light::Type::Directional;
    light.direction = {0.0f, -1.0f, 0.0f};
    // No ground added: nothing, the whole scene is framed.
    EXPECT_TRUE(modelAndShadowPoints(box, light).empty());
    ASSERT_TRUE(applyGround(box, GroundMode::Auto));
    EXPECT_EQ(box.addedGround, 1);
    const float groundY = box.bounds.min.y;
    // From straight above, the shadow is the model's own footprint, on the ground's plane.
    geom::Aabb b = shadowFrame(box, light);
    EXPECT_EQ(b.min, glm::vec3(0.0f, groundY, 0.0f));
    EXPECT_EQ(b.max, glm::vec3(1.0f, 2.0f, 1.0f));
    // 24 vertices (the box's faces have their own) and their 24 shadows.
    EXPECT_EQ(modelAndShadowPoints(box, light).size(), 48u);
    // At 45 degrees along +x the top's shadow lands 2 further on, x in [2, 3]: cut at the
    // ground's edge, x = 2.5 (the square reaches 1.5 past the footprint).
    light.direction = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f));
    b = shadowFrame(box, light);
    EXPECT_NEAR(b.max.x, 2.5f, 1e-5f);
    EXPECT_NEAR(b.min.x, 0.0f, 1e-5f);
    EXPECT_NEAR(b.max.z, 1.0f, 1e-5f);
    // A point light 2 above the model's centre: the top corners' shadows lie twice as far from
    // the light's foot as the corners (x 0 -> -0.5, z 1 -> 1.5).
    light.type = Light::Type::Point;
    light.position = {0.5f, 4.0f, 0.5f};
    b = shadowFrame(box, light);
    EXPECT_NEAR(b.min.x, -0.5f, 1e-3f);
    EXPECT_NEAR(b.max.z, 1.5f, 1e-3f);
    // A point light lower than the model's top: that shadow runs off the ground, all of it framed.
    light.position = {-3.0f, 1.5f, 0.5f};
    b = shadowFrame(box, light);
    EXPECT_EQ(b.min, box.bounds.min);
    EXPECT_EQ(b.max, box.bounds.max);
}

// Whether the segment from a to b meets box `b` (slab test).
bool segmentMeetsBox(glm::vec3 a, glm::vec3 b, const geom::Aabb& box) {
    float t0 = 0.0f, t1 = 1.0f;
    for (int k = 0; k < 3; ++k) {
        const float d = b[k] - a[k];
        if (std::abs(d) < 1e-12f) {
            if (a[k] < box.min[k] || a[k] > box.max[k]) return false;
            continue;
        }
        float u = (box.min[k] - a[k]) / d, v = (box.max[k] - a[k]) / d;
        if (u > v) std::swap(u, v);
        t0 = std::max(t0, u);
        t1 = std::min(t1, v);
        if (t0 > t1) return false;
    }
    return true;
}

// Named after what the real-model benchmark found: on a model standing on the ground Floodlight
// adds, the light's frustum was fitted to the whole square of ground, and the model got a
// third of the map's width. Fitted to what casts shadows (the model), widened by the disk's
// penumbrae, it must (1) give the model most of the map, (2) still hold every ground point the
// model can shadow from any point of the disk, and (3) hold the ground in depth.
TEST(Ground, TheLightsFrustumSpendsTheMapOnTheModel) {
    Scene s;
    addBox(s, {0, 0, 0}, {1, 2, 1});
    ASSERT_TRUE(applyGround(s, GroundMode::Auto));
    Light light = sceneLight(s);
    light.radius = 0.3f; // large, so the penumbra margin matters
    const geom::Aabb casters = shadowCasterBounds(s, light, s.bounds, s.modelBounds);
    EXPECT_EQ(casters.min, s.modelBounds.min);
    EXPECT_EQ(casters.max, s.modelBounds.max);
    const glm::mat4 fitted = lightVolume(s, light).viewProj();
    const glm::mat4 whole = lightVolume(s.bounds, light).viewProj();
    // (1) The model's width on the map: its corners' NDC extent, both fits.
    const auto extent = [&](const glm::mat4& m) {
        glm::vec2 lo(1e9f), hi(-1e9f);
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 c{(i & 1) ? casters.max.x : casters.min.x,
                              (i & 2) ? casters.max.y : casters.min.y,
                              (i & 4) ? casters.max.z : casters.min.z};
            const glm::vec4 q = m * glm::vec4(c, 1.0f);
            lo = glm::min(lo, glm::vec2(q) / q.w);
            hi = glm::max(hi, glm::vec2(q) / q.w);
        }
        return std::max(hi.x - lo.x, hi.y - lo.y) / 2.0f;
    };
    EXPECT_GT(extent(fitted), 0.6f); // 0.71: the cone holds the box at both ends and the margin
    EXPECT_GT(extent(fitted), 1.5f * extent(whole)) << "the old fit: " << extent(whole);
    // (2) and (3): every ground point that some point of the disk sees through the model's box
    // lies inside the frustum, and every ground point lies within its depth range.
    const DiskLight disk = makeDiskLight(light, s.bounds);
    const float y = s.bounds.min.y;
    const glm::vec3 u = geom::stableUp(disk.normal),
                    side = glm::normalize(glm::cross(disk.normal, u));
    const glm::vec3 up = glm::cross(side, disk.normal);
    int shadowed = 0;
    for (int i = 0; i <= 80; ++i)
        for (int j = 0; j <= 80; ++j) {
            const glm::vec3 p{glm::mix(s.bounds.min.x, s.bounds.max.x, i / 80.0f), y,
                              glm::mix(s.bounds.min.z, s.bounds.max.z, j / 80.0f)};
            const glm::vec4 q = fitted * glm::vec4(p, 1.0f);
            EXPECT_TRUE(q.w > 0.0f && std::abs(q.z) <= q.w) << "ground point out of depth range";
            bool canBeShadowed = false;
            for (int k = 0; k < 33 && !canBeShadowed; ++k) {
                const float a = 6.2831853f * k / 32.0f;
                const glm::vec3 onDisk =
                    k == 32 ? disk.center
                            : disk.center + disk.radius * (std::cos(a) * side + std::sin(a) * up);
                canBeShadowed = segmentMeetsBox(p, onDisk, casters);
            }
            if (!canBeShadowed) continue;
            ++shadowed;
            EXPECT_TRUE(std::abs(q.x) <= q.w && std::abs(q.y) <= q.w)
                << "a ground point the model shadows lies outside the map: " << p.x << ", " << p.z;
        }
    EXPECT_GT(shadowed, 100);
}

} // namespace
} // namespace fl
