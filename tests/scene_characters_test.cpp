// The generated characters' skeletons and cycles (issue 15, item 2): every character is skinned
// (weights summing to 1, joints in range), walks or waves, is at rest at time 0 (so the goldens,
// rendered at time 0, show the scene as before), moves, loops, keeps its feet out of the ground,
// and survives a GLB round trip with the same poses.

#include <scene/GltfLoader.h>
#include <scene/Pose.h>
#include <scene/SceneGenerator.h>

#include "TestPaths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

namespace fl {
namespace {

std::vector<std::size_t> characters(const Scene& s) {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < s.instances.size(); ++i)
        if (s.instances[i].nodeName.rfind("character", 0) == 0) out.push_back(i);
    return out;
}

std::vector<glm::vec3> posed(const Scene& s, std::size_t instance, double time) {
    const std::vector<int> all = chooseAnimations(s, "all");
    std::vector<glm::vec3> p;
    posedVertices(s, evaluatePose(s, all, time), instance, p);
    return p;
}

geom::Aabb boundsOf(const std::vector<glm::vec3>& points) {
    geom::Aabb box;
    for (const glm::vec3& p : points) box.extend(p);
    return box;
}

float maxDistance(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
    EXPECT_EQ(a.size(), b.size());
    float d = 0.0f;
    for (std::size_t v = 0; v < a.size() && v < b.size(); ++v)
        d = std::max(d, glm::length(a[v] - b[v]));
    return d;
}

/// The animation ("walk" or "wave") whose channels drive a joint of instance `i`'s skin.
std::set<std::string> animationsOf(const Scene& s, std::size_t i) {
    const Skin& skin = s.skins.at(static_cast<std::size_t>(s.instances[i].skin));
    const std::set<int> joints(skin.joints.begin(), skin.joints.end());
    std::set<std::string> names;
    for (const Animation& a : s.animations)
        for (const Animation::Channel& c : a.channels)
            if (joints.count(c.node)) names.insert(a.name);
    return names;
}

TEST(SceneCharacters, EveryCharacterIsSkinnedWithNormalisedWeights) {
    for (std::size_t n : {std::size_t{634}, std::size_t{6320}, std::size_t{216440}}) {
        const Scene s = generateScene({.triangles = n});
        const std::vector<std::size_t> cast = characters(s);
        ASSERT_EQ(cast.size(), n > 150'000 ? 6u : 4u) << n;
        EXPECT_EQ(s.skins.size(), cast.size());
        for (std::size_t i : cast) {
            const Instance& inst = s.instances[i];
            SCOPED_TRACE(inst.nodeName + " at " + std::to_string(n));
            ASSERT_GE(inst.skin, 0);
            const Skin& skin = s.skins[static_cast<std::size_t>(inst.skin)];
            EXPECT_EQ(skin.joints.size(), 7u); // hips, spine, head, two arms, two legs
            ASSERT_EQ(skin.inverseBind.size(), skin.joints.size());
            const Mesh& m = s.meshes[static_cast<std::size_t>(inst.mesh)];
            ASSERT_TRUE(isSkinned(inst, m));
            ASSERT_EQ(m.joints.size(), m.positions.size());
            std::set<unsigned> used;
            for (std::size_t v = 0; v < m.positions.size(); ++v) {
                const glm::vec4 w = m.weights[v];
                ASSERT_EQ(w.x + w.y + w.z + w.w, 1.0f) << v;
                for (int k = 0; k < 4; ++k) {
                    ASSERT_GE(w[k], 0.0f);
                    ASSERT_LT(m.joints[v][k], skin.joints.size());
                    if (w[k] > 0.0f) used.insert(m.joints[v][k]);
                }
            }
            EXPECT_EQ(used.size(), 7u) << "every joint carries some vertices";
            EXPECT_EQ(animationsOf(s, i).size(), 1u) << "walks or waves, not both";
        }
        // Nothing else is skinned.
        for (std::size_t i = 0; i < s.instances.size(); ++i) {
            if (s.instances[i].nodeName.rfind("character", 0) != 0) {
                EXPECT_EQ(s.instances[i].skin, -1) << s.instances[i].nodeName;
            }
        }
    }
}

TEST(SceneCharacters, SomeWalkAndSomeWave) {
    // The default scene (seed 1) has both, and so does the fantasy2 size.
    for (std::size_t n : {std::size_t{6320}, std::size_t{216440}}) {
        const Scene s = generateScene({.triangles = n});
        std::set<std::string> names;
        for (const Animation& a : s.animations) {
            names.insert(a.name);
            EXPECT_FLOAT_EQ(a.duration, 1.0f) << a.name;
            for (const Animation::Sampler& sm : a.samplers)
                EXPECT_EQ(sm.interpolation, Animation::Interpolation::Linear);
        }
        EXPECT_EQ(names, (std::set<std::string>{"walk", "wave"})) << n;
        EXPECT_EQ(chooseAnimations(s, "all").size(), 2u);
    }
}

TEST(SceneCharacters, TimeZeroIsTheRestPose) {
    const Scene s = generateScene({.triangles = 6320});
    for (std::size_t i : characters(s)) {
        const Mesh& m = s.meshes[static_cast<std::size_t>(s.instances[i].mesh)];
        std::vector<glm::vec3> rest;
        for (const glm::vec3& p : m.positions)
            rest.emplace_back(s.instances[i].world * glm::vec4(p, 1.0f));
        EXPECT_LT(maxDistance(posed(s, i, 0.0), rest), 1e-5f) << s.instances[i].nodeName;
    }
}

TEST(SceneCharacters, CharactersMoveAndLoop) {
    const Scene s = generateScene({.triangles = 6320});
    for (std::size_t i : characters(s)) {
        SCOPED_TRACE(s.instances[i].nodeName);
        const std::vector<glm::vec3> start = posed(s, i, 0.0);
        for (double t : {0.1, 0.25, 0.5, 0.77}) {
            const std::vector<glm::vec3> p = posed(s, i, t);
            for (const glm::vec3& v : p)
                ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) << t;
        }
        // A quarter period: a walker's legs are at full stride, a waver's arm fully out.
        const geom::Aabb a = boundsOf(start), b = boundsOf(posed(s, i, 0.25));
        EXPECT_GT(glm::length(a.min - b.min) + glm::length(a.max - b.max), 0.05f);
        EXPECT_GT(maxDistance(start, posed(s, i, 0.25)), 0.1f);
        // One period later the pose is the first again.
        EXPECT_LT(maxDistance(start, posed(s, i, 1.0)), 1e-6f);
        // Half a period: the mirror of the quarter pose, not the start.
        EXPECT_GT(maxDistance(posed(s, i, 0.25), posed(s, i, 0.75)), 0.1f);
    }
}

TEST(SceneCharacters, WalkersKeepTheirFeetOutOfTheGround) {
    const Scene s = generateScene({.triangles = 6320});
    int walkers = 0;
    for (std::size_t i : characters(s)) {
        if (animationsOf(s, i) != std::set<std::string>{"walk"}) continue;
        ++walkers;
        const float restLow = boundsOf(posed(s, i, 0.0)).min.y;
        for (int k = 1; k < 32; ++k)
            EXPECT_GE(boundsOf(posed(s, i, k / 32.0)).min.y, restLow - 1e-4f)
                << s.instances[i].nodeName << " at " << k / 32.0;
    }
    EXPECT_GT(walkers, 0);
}

TEST(SceneCharacters, SameSeedSameCyclesOtherSeedOthers) {
    const Scene a = generateScene({.triangles = 6320, .seed = 3});
    const Scene b = generateScene({.triangles = 6320, .seed = 3});
    ASSERT_EQ(a.animations.size(), b.animations.size());
    for (std::size_t k = 0; k < a.animations.size(); ++k) {
        ASSERT_EQ(a.animations[k].samplers.size(), b.animations[k].samplers.size());
        for (std::size_t j = 0; j < a.animations[k].samplers.size(); ++j)
            EXPECT_EQ(a.animations[k].samplers[j].values, b.animations[k].samplers[j].values);
    }
    for (std::size_t i : characters(a)) {
        const Mesh& ma = a.meshes[static_cast<std::size_t>(a.instances[i].mesh)];
        const Mesh& mb = b.meshes[static_cast<std::size_t>(b.instances[i].mesh)];
        EXPECT_EQ(ma.joints, mb.joints);
        EXPECT_EQ(ma.weights, mb.weights);
    }
    const Scene c = generateScene({.triangles = 6320, .seed = 4});
    const std::size_t ca = characters(a).front(), cc = characters(c).front();
    EXPECT_GT(maxDistance(posed(a, ca, 0.25), posed(c, cc, 0.25)), 0.1f);
}

TEST(SceneCharacters, GlbRoundTripKeepsSkinsAnimationsAndPoses) {
    const Scene s = generateScene({.triangles = 6320});
    const auto file = test::outputDir("scene_characters") / "characters.glb";
    writeGlb(s, file);
    const Scene r = loadGltf(file);
    ASSERT_EQ(r.skins.size(), s.skins.size());
    ASSERT_EQ(r.animations.size(), s.animations.size());
    for (std::size_t k = 0; k < s.animations.size(); ++k) {
        EXPECT_EQ(r.animations[k].name, s.animations[k].name);
        EXPECT_EQ(r.animations[k].channels.size(), s.animations[k].channels.size());
        EXPECT_FLOAT_EQ(r.animations[k].duration, s.animations[k].duration);
    }
    const std::vector<std::size_t> cast = characters(s);
    ASSERT_EQ(characters(r).size(), cast.size());
    for (std::size_t i : cast) {
        // The loader keeps the instance order (objectIds and draw order with it).
        ASSERT_EQ(r.instances[i].nodeName, s.instances[i].nodeName);
        ASSERT_GE(r.instances[i].skin, 0);
        for (double t : {0.0, 0.25, 0.6, 1.0})
            EXPECT_LT(maxDistance(posed(r, i, t), posed(s, i, t)), 1e-4f)
                << s.instances[i].nodeName << " at " << t;
    }
}

} // namespace
} // namespace fl
