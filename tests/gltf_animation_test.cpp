// glTF skins, morph targets and animations: what the loader reads into Scene::nodes, skins,
// animations and the meshes' skinning and morph data, the assimp sample files, and one test per
// rejected or repaired input (file, element and problem in the message).

#include <scene/GltfLoader.h>
#include <scene/SceneGenerator.h>

#include "GltfBuilder.h"
#include "TestPaths.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>

namespace fl::test {
namespace {

namespace fs = std::filesystem;

constexpr int kTranslationSampler = 0, kRotationSampler = 1, kScaleSampler = 2;

void expectNear(const glm::vec4& a, const glm::vec4& b, float tolerance = 1e-6f) {
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(a[i], b[i], tolerance) << "component " << i;
}

// --- what loads -----------------------------------------------------------------------------

TEST(GltfAnimation, SkinnedBarNodesSkinAndAnimation) {
    const Loaded l = load(skinnedBar().write("skinned_bar.gltf"));
    EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
    const Scene& s = l.scene;
    ASSERT_EQ(s.nodes.size(), 3u);
    EXPECT_EQ(s.nodes[0].name, "bar");
    EXPECT_EQ(s.nodes[1].parent, -1);
    EXPECT_EQ(s.nodes[2].parent, 1);
    EXPECT_EQ(s.nodes[2].translation, glm::vec3(0, 1, 0));
    EXPECT_FALSE(s.nodes[2].matrix);
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.instances[0].node, 0);
    EXPECT_EQ(s.instances[0].skin, 0);
    ASSERT_EQ(s.skins.size(), 1u);
    EXPECT_EQ(s.skins[0].joints, (std::vector<int>{1, 2}));
    ASSERT_EQ(s.skins[0].inverseBind.size(), 2u);
    EXPECT_EQ(s.skins[0].inverseBind[0], glm::mat4(1.0f));
    EXPECT_EQ(s.skins[0].inverseBind[1], glm::translate(glm::mat4(1.0f), glm::vec3(0, -1, 0)));

    const Mesh& m = s.meshes[0];
    ASSERT_EQ(m.joints.size(), 6u);
    ASSERT_EQ(m.weights.size(), 6u);
    EXPECT_EQ(m.joints[2], glm::uvec4(0, 1, 0, 0));
    EXPECT_EQ(m.weights[2], glm::vec4(0.5f, 0.5f, 0, 0));
    EXPECT_EQ(m.joints[5], glm::uvec4(1, 0, 0, 0));

    ASSERT_EQ(s.animations.size(), 1u);
    const Animation& a = s.animations[0];
    EXPECT_EQ(a.name, "bend");
    EXPECT_FLOAT_EQ(a.duration, 2.0f);
    ASSERT_EQ(a.channels.size(), 3u);
    ASSERT_EQ(a.samplers.size(), 3u);
    EXPECT_EQ(a.channels[0].node, 1);
    EXPECT_EQ(a.channels[0].path, Animation::Path::Translation);
    EXPECT_EQ(a.channels[1].path, Animation::Path::Rotation);
    EXPECT_EQ(a.channels[2].path, Animation::Path::Scale);
    EXPECT_EQ(a.channels[2].sampler, kScaleSampler);
    const auto& t = a.samplers[kTranslationSampler];
    EXPECT_EQ(t.interpolation, Animation::Interpolation::Linear);
    EXPECT_EQ(t.times, (std::vector<float>{0, 1, 2}));
    EXPECT_EQ(t.width, 3);
    EXPECT_EQ(t.values.size(), 9u);
    const auto& r = a.samplers[kRotationSampler];
    EXPECT_EQ(r.interpolation, Animation::Interpolation::Step);
    EXPECT_EQ(r.width, 4);
    ASSERT_EQ(r.values.size(), 12u);
    expectNear({r.values[4], r.values[5], r.values[6], r.values[7]}, {0, 0, 1, 0}); // normalised
    const auto& sc = a.samplers[kScaleSampler];
    EXPECT_EQ(sc.interpolation, Animation::Interpolation::CubicSpline);
    ASSERT_EQ(sc.values.size(), 27u); // 3 keys x (in, value, out) x 3
    EXPECT_EQ(sc.values[12], 2.0f);   // key 1's value
}

TEST(GltfAnimation, MorphTriangleWithMeshAndNodeWeights) {
    const Loaded l = load(morphTriangle().write("morph_triangle.gltf"));
    EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
    const Scene& s = l.scene;
    const Mesh& m = s.meshes[0];
    ASSERT_EQ(m.targets.size(), 1u);
    EXPECT_EQ(m.targets[0].positions, (std::vector<glm::vec3>{{0, 0, 1}, {0, 0, 2}, {0, 0, 3}}));
    EXPECT_EQ(m.targets[0].normals.size(), 3u);
    EXPECT_EQ(m.morphWeights, std::vector<float>{0.5f});
    ASSERT_EQ(s.nodes.size(), 1u);
    EXPECT_EQ(s.nodes[0].weights, std::vector<float>{0.25f});
    EXPECT_EQ(s.instances[0].node, 0);
    EXPECT_EQ(s.instances[0].skin, -1);
    EXPECT_TRUE(s.animations.empty());
}

TEST(GltfAnimation, StaticSceneFillsNoNodes) {
    const Loaded l = load(triangle().write("static_no_nodes.gltf"));
    EXPECT_TRUE(l.scene.nodes.empty());
    EXPECT_EQ(l.scene.instances[0].node, -1);
    EXPECT_EQ(l.scene.instances[0].skin, -1);
}

TEST(GltfAnimation, FlatNormalsCarrySkinningAndTargets) {
    Gltf g = skinnedBar(/*withNormals=*/false);
    g.prim()["targets"] =
        json::array({{{"POSITION", g.vec3(std::vector<glm::vec3>(6, glm::vec3(0, 0, 1)))}}});
    const Loaded l = load(g.write("flat_skinned.gltf"));
    const Mesh& m = l.scene.meshes[0];
    ASSERT_EQ(m.positions.size(), 12u); // 4 triangles, unshared
    ASSERT_EQ(m.joints.size(), 12u);
    ASSERT_EQ(m.weights.size(), 12u);
    ASSERT_EQ(m.targets.size(), 1u);
    EXPECT_EQ(m.targets[0].positions.size(), 12u);
    // Triangle 2 is {2, 3, 5}: its third vertex is the top row's, on the tip alone.
    EXPECT_EQ(m.positions[8], glm::vec3(1, 2, 0));
    EXPECT_EQ(m.joints[8], glm::uvec4(1, 0, 0, 0));
    EXPECT_EQ(m.joints[6], glm::uvec4(0, 1, 0, 0));
    EXPECT_EQ(m.weights[6], glm::vec4(0.5f, 0.5f, 0, 0));
}

TEST(GltfAnimation, SparseMorphTarget) {
    Gltf g = triangle();
    const int indices = g.view(std::vector<std::uint8_t>{2, 0, 0, 0});
    const int values = g.view(std::vector<glm::vec3>{{0, 0, 5}});
    const int delta =
        g.push("accessors", {{"componentType", kFloat},
                             {"type", "VEC3"},
                             {"count", 3},
                             {"sparse",
                              {{"count", 1},
                               {"indices", {{"bufferView", indices}, {"componentType", kU8}}},
                               {"values", {{"bufferView", values}}}}}});
    g.prim()["targets"] = json::array({{{"POSITION", delta}}});
    const Loaded l = load(g.write("sparse_target.gltf"));
    ASSERT_EQ(l.scene.meshes[0].targets.size(), 1u);
    EXPECT_EQ(l.scene.meshes[0].targets[0].positions,
              (std::vector<glm::vec3>{{0, 0, 0}, {0, 0, 0}, {0, 0, 5}}));
    EXPECT_EQ(l.scene.meshes[0].morphWeights, std::vector<float>{0.0f}); // default
}

TEST(GltfAnimation, AnimatedMatrixNodeBecomesTrs) {
    Gltf g = skinnedBar();
    const glm::mat4 m = glm::scale(
        glm::rotate(glm::translate(glm::mat4(1.0f), {1, 2, 3}), 0.5f, glm::vec3(0, 0, 1)),
        {2, 3, 4});
    json matrix = json::array();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) matrix.push_back(m[c][r]);
    g.node(1).erase("children");
    g.node(1)["matrix"] = matrix;
    g.node(1)["children"] = {2};
    const Loaded l = load(g.write("animated_matrix.gltf"));
    EXPECT_TRUE(l.warned("animated_matrix.gltf: nodes[1]: matrix replaced by translation, "
                         "rotation and scale because animations[0].channels[0] animates it"));
    const Node& n = l.scene.nodes[1];
    EXPECT_FALSE(n.matrix);
    const glm::mat4 back = glm::scale(
        glm::translate(glm::mat4(1.0f), n.translation) * glm::mat4_cast(n.rotation), n.scale);
    for (int c = 0; c < 4; ++c) expectNear(back[c], m[c], 1e-5f);
}

TEST(GltfAnimation, FuzzSeedLoads) {
    // fuzz/corpus/gltf/animated.gltf: skinnedBar() plus a morph target driven by a weights
    // channel, so that fuzzing starts from every kind of animation data.
    const Loaded l = load(dataDir() / "../fuzz/corpus/gltf/animated.gltf");
    EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
    ASSERT_EQ(l.scene.animations.size(), 1u);
    EXPECT_EQ(l.scene.animations[0].channels.size(), 4u);
    EXPECT_EQ(l.scene.animations[0].channels[3].path, Animation::Path::Weights);
    EXPECT_EQ(l.scene.instances[0].skin, 0);
    EXPECT_EQ(l.scene.meshes[0].targets.size(), 1u);
}

TEST(GltfAnimation, GlbRoundTripKeepsAnimationData) {
    const Scene a = load(dataDir() / "../fuzz/corpus/gltf/animated.gltf").scene;
    const fs::path file = outputDir("gltf_loader") / "animated_round_trip.glb";
    writeGlb(a, file);
    const Loaded l = load(file);
    EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
    const Scene& b = l.scene;
    ASSERT_EQ(b.nodes.size(), a.nodes.size());
    for (std::size_t i = 0; i < a.nodes.size(); ++i) {
        EXPECT_EQ(b.nodes[i].name, a.nodes[i].name);
        EXPECT_EQ(b.nodes[i].parent, a.nodes[i].parent);
        EXPECT_EQ(b.nodes[i].translation, a.nodes[i].translation);
        EXPECT_EQ(b.nodes[i].rotation, a.nodes[i].rotation);
        EXPECT_EQ(b.nodes[i].scale, a.nodes[i].scale);
        EXPECT_EQ(b.nodes[i].matrix, a.nodes[i].matrix);
        EXPECT_EQ(b.nodes[i].weights, a.nodes[i].weights);
    }
    ASSERT_EQ(b.skins.size(), 1u);
    EXPECT_EQ(b.skins[0].joints, a.skins[0].joints);
    EXPECT_EQ(b.skins[0].inverseBind, a.skins[0].inverseBind);
    ASSERT_EQ(b.instances.size(), 1u);
    EXPECT_EQ(b.instances[0].node, a.instances[0].node);
    EXPECT_EQ(b.instances[0].skin, 0);
    EXPECT_EQ(b.instances[0].world, a.instances[0].world);
    const Mesh &ma = a.meshes[0], &mb = b.meshes[0];
    EXPECT_EQ(mb.joints, ma.joints);
    EXPECT_EQ(mb.weights, ma.weights);
    ASSERT_EQ(mb.targets.size(), 1u);
    EXPECT_EQ(mb.targets[0].positions, ma.targets[0].positions);
    EXPECT_EQ(mb.morphWeights, ma.morphWeights);
    ASSERT_EQ(b.animations.size(), 1u);
    const Animation &aa = a.animations[0], &ab = b.animations[0];
    EXPECT_EQ(ab.name, aa.name);
    EXPECT_EQ(ab.duration, aa.duration);
    ASSERT_EQ(ab.samplers.size(), aa.samplers.size());
    for (std::size_t i = 0; i < aa.samplers.size(); ++i) {
        EXPECT_EQ(ab.samplers[i].interpolation, aa.samplers[i].interpolation) << i;
        EXPECT_EQ(ab.samplers[i].times, aa.samplers[i].times) << i;
        EXPECT_EQ(ab.samplers[i].values, aa.samplers[i].values) << i;
        EXPECT_EQ(ab.samplers[i].width, aa.samplers[i].width) << i;
    }
    ASSERT_EQ(ab.channels.size(), aa.channels.size());
    for (std::size_t i = 0; i < aa.channels.size(); ++i) {
        EXPECT_EQ(ab.channels[i].node, aa.channels[i].node) << i;
        EXPECT_EQ(ab.channels[i].path, aa.channels[i].path) << i;
        EXPECT_EQ(ab.channels[i].sampler, aa.channels[i].sampler) << i;
    }
}

TEST(GltfAnimation, GlbRoundTripKeepsMultiPrimitiveNodes) {
    // One node placing two primitives: the writer gives the node one mesh with both, so that
    // node weights and weights channels still reach them.
    Gltf g = morphTriangle();
    g.doc["meshes"][0]["primitives"].push_back(g.prim());
    animate(g, g.floats({0, 1}, "SCALAR"), g.floats({0, 1}, "SCALAR"), 0, "weights");
    const Scene a = load(g.write("morph_two_primitives.gltf")).scene;
    ASSERT_EQ(a.instances.size(), 2u);
    const fs::path file = outputDir("gltf_loader") / "morph_two_primitives.glb";
    writeGlb(a, file);
    const Loaded l = load(file);
    EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
    ASSERT_EQ(l.scene.instances.size(), 2u);
    EXPECT_EQ(l.scene.instances[0].node, 0);
    EXPECT_EQ(l.scene.instances[1].node, 0);
    EXPECT_EQ(l.scene.nodes[0].weights, std::vector<float>{0.25f});
    ASSERT_EQ(l.scene.animations.size(), 1u);
    EXPECT_EQ(l.scene.animations[0].channels.size(), 1u);
    EXPECT_EQ(l.scene.meshes[1].morphWeights, std::vector<float>{0.5f});
}

// --- the assimp sample files (scripts/setup.sh installs assimp-testmodels) -------------------

const fs::path kSamples = "/usr/share/assimp/models/glTF2";

TEST(GltfAnimationSamples, SimpleSkin) {
    const fs::path file = kSamples / "simple_skin/simple_skin.gltf";
    if (!fs::exists(file)) GTEST_SKIP() << file << " missing (scripts/setup.sh installs it)";
    const Loaded l = load(file);
    EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
    const Scene& s = l.scene;
    ASSERT_EQ(s.nodes.size(), 3u);
    EXPECT_EQ(s.nodes[1].parent, 0);
    EXPECT_EQ(s.nodes[2].parent, 1);
    ASSERT_EQ(s.skins.size(), 1u);
    EXPECT_EQ(s.skins[0].joints, (std::vector<int>{1, 2}));
    EXPECT_EQ(s.skins[0].inverseBind[1][3], glm::vec4(-0.5f, -1.0f, 0.0f, 1.0f));
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.instances[0].skin, 0);
    // No NORMAL: flat normals unshare the 8 triangles' vertices, joints and weights with them.
    EXPECT_EQ(s.meshes[0].joints.size(), 24u);
    EXPECT_EQ(s.meshes[0].weights.size(), 24u);
    ASSERT_EQ(s.animations.size(), 1u);
    ASSERT_EQ(s.animations[0].channels.size(), 1u);
    EXPECT_EQ(s.animations[0].channels[0].node, 2);
    EXPECT_EQ(s.animations[0].channels[0].path, Animation::Path::Rotation);
    EXPECT_EQ(s.animations[0].samplers[0].times.size(), 12u);
    EXPECT_FLOAT_EQ(s.animations[0].duration, 5.5f);
}

TEST(GltfAnimationSamples, AnimatedMorphCube) {
    const fs::path file =
        kSamples / "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf";
    if (!fs::exists(file)) GTEST_SKIP() << file << " missing (scripts/setup.sh installs it)";
    const Loaded l = load(file);
    EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
    const Scene& s = l.scene;
    ASSERT_EQ(s.nodes.size(), 1u);
    ASSERT_EQ(s.meshes.size(), 1u);
    ASSERT_EQ(s.meshes[0].targets.size(), 2u); // "thin" and "angle"
    EXPECT_EQ(s.meshes[0].targets[0].positions.size(), 24u);
    EXPECT_EQ(s.meshes[0].targets[1].normals.size(), 24u);
    EXPECT_EQ(s.meshes[0].morphWeights, (std::vector<float>{0, 0}));
    EXPECT_EQ(s.instances[0].node, 0);
    ASSERT_EQ(s.animations.size(), 1u);
    const Animation& a = s.animations[0];
    EXPECT_EQ(a.name, "Square");
    ASSERT_EQ(a.channels.size(), 1u);
    EXPECT_EQ(a.channels[0].path, Animation::Path::Weights);
    EXPECT_EQ(a.samplers[0].width, 2);
    EXPECT_EQ(a.samplers[0].times.size(), 127u);
    EXPECT_EQ(a.samplers[0].values.size(), 254u);
    EXPECT_NEAR(a.duration, 4.19999743f, 1e-6f);
}

} // namespace
} // namespace fl::test
