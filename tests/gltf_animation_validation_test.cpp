// glTF skins, morph targets and animations with bad input: one test per rule, each names the
// case; rejections must name the file, the element and the problem, repairs must warn and leave
// usable data.

#include <scene/GltfLoader.h>

#include "GltfBuilder.h"

#include <scene/Pose.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fl::test {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

json& skin0(Gltf& g) {
    return g.doc["skins"][0];
}
json& channel(Gltf& g, int c) {
    return g.doc["animations"][0]["channels"][static_cast<std::size_t>(c)];
}
json& sampler(Gltf& g, int s) {
    return g.doc["animations"][0]["samplers"][static_cast<std::size_t>(s)];
}
json& attributes(Gltf& g) {
    return g.prim()["attributes"];
}

/// skinnedBar()'s JOINTS_0 with vertex 5's first joint set to `joint`.
int jointsWith(Gltf& g, std::uint8_t joint) {
    std::vector<std::uint8_t> j = {0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0,
                                   0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
    j[20] = joint;
    return g.ints(j, kU8, "VEC4");
}

/// skinnedBar()'s weights with vertex 0's set to `w`.
int weightsWith(Gltf& g, std::vector<float> w) {
    std::vector<float> all = {1,    0,    0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0,
                              0.5f, 0.5f, 0, 0, 1, 0, 0, 0, 1,    0,    0, 0};
    std::copy(w.begin(), w.end(), all.begin());
    return g.floats(all, "VEC4");
}

// --- skins ----------------------------------------------------------------------------------

TEST(GltfAnimationValidation, SkinJointNodeOutOfRange) {
    Gltf g = skinnedBar();
    skin0(g)["joints"] = {1, 9};
    expectRejected(g, "skin_joint_range.gltf",
                   {"skins[0].joints[1]", "node 9 does not exist (3 in nodes)"});
}

TEST(GltfAnimationValidation, SkinWithoutJoints) {
    Gltf g = skinnedBar();
    skin0(g)["joints"] = json::array();
    skin0(g).erase("inverseBindMatrices");
    expectRejected(g, "skin_no_joints.gltf", {"skins[0]: no joints"});
}

TEST(GltfAnimationValidation, NodeSkinOutOfRange) {
    Gltf g = skinnedBar();
    g.node(0)["skin"] = 5;
    expectRejected(g, "node_skin_range.gltf", {"nodes[0]", "skin 5 does not exist (1 in skins)"});
}

TEST(GltfAnimationValidation, InverseBindMatrixCountMismatch) {
    Gltf g = skinnedBar();
    skin0(g)["inverseBindMatrices"] = g.floats(std::vector<float>(16, 1.0f), "MAT4");
    expectRejected(g, "ibm_count.gltf",
                   {"skins[0]", "inverseBindMatrices has 1 matrices but the skin has 2 joints"});
}

TEST(GltfAnimationValidation, InverseBindMatrixNotFinite) {
    Gltf g = skinnedBar();
    std::vector<float> m(32, 0.0f);
    m[17] = kNaN;
    skin0(g)["inverseBindMatrices"] = g.floats(m, "MAT4");
    expectRejected(g, "ibm_nan.gltf", {"skins[0].inverseBindMatrices: matrix 1 is not finite"});
}

TEST(GltfAnimationValidation, InverseBindMatrixWrongType) {
    Gltf g = skinnedBar();
    skin0(g)["inverseBindMatrices"] = g.floats(std::vector<float>(8, 0.0f), "VEC4");
    expectRejected(g, "ibm_type.gltf",
                   {"skins[0].inverseBindMatrices needs MAT4 FLOAT, got VEC4 FLOAT"});
}

TEST(GltfAnimationValidation, AbsentInverseBindMatricesAreIdentity) {
    Gltf g = skinnedBar();
    skin0(g).erase("inverseBindMatrices");
    const Loaded l = load(g.write("ibm_absent.gltf"));
    EXPECT_TRUE(l.warnings.empty()) << l.warnings.front(); // the spec allows it
    EXPECT_EQ(l.scene.skins[0].inverseBind, std::vector<glm::mat4>(2, glm::mat4(1.0f)));
}

TEST(GltfAnimationValidation, SkinnedNodeMeshWithoutJoints) {
    Gltf g = skinnedBar();
    attributes(g).erase("JOINTS_0");
    attributes(g).erase("WEIGHTS_0");
    const Loaded l = load(g.write("skin_no_joints_attr.gltf"));
    EXPECT_TRUE(l.warned("skin_no_joints_attr.gltf: nodes[0]: skins[0] ignored: meshes[0] has no "
                         "JOINTS_0 and WEIGHTS_0; drawn unskinned"));
    EXPECT_EQ(l.scene.instances[0].skin, -1);
    EXPECT_TRUE(l.scene.skins.empty());
}

TEST(GltfAnimationValidation, JointsWithoutSkin) {
    Gltf g = skinnedBar();
    g.node(0).erase("skin");
    const Loaded l = load(g.write("joints_no_skin.gltf"));
    EXPECT_TRUE(l.warned("joints_no_skin.gltf: nodes[0]: meshes[0] has JOINTS_0 and WEIGHTS_0 but "
                         "the node has no skin; drawn unskinned"));
    EXPECT_EQ(l.scene.instances[0].skin, -1);
    EXPECT_TRUE(l.scene.meshes[0].joints.empty());
    EXPECT_TRUE(l.scene.meshes[0].weights.empty());
}

TEST(GltfAnimationValidation, JointIndexOutOfRange) {
    Gltf g = skinnedBar();
    attributes(g)["JOINTS_0"] = jointsWith(g, 2);
    expectRejected(g, "joint_index_range.gltf",
                   {"nodes[0]", "joint index 2 out of range (skins[0] has 2 joints)"});
}

TEST(GltfAnimationValidation, JointsCountMismatch) {
    Gltf g = skinnedBar();
    attributes(g)["JOINTS_0"] = g.ints(std::vector<std::uint8_t>(20, 0), kU8, "VEC4");
    expectRejected(g, "joints_count.gltf",
                   {"meshes[0].primitives[0]", "JOINTS_0 has 5 elements but POSITION has 6"});
}

TEST(GltfAnimationValidation, WeightsCountMismatch) {
    Gltf g = skinnedBar();
    attributes(g)["WEIGHTS_0"] = g.floats(std::vector<float>(28, 0.25f), "VEC4");
    expectRejected(g, "weights_count.gltf",
                   {"meshes[0].primitives[0]", "WEIGHTS_0 has 7 elements but POSITION has 6"});
}

TEST(GltfAnimationValidation, JointsWrongComponentType) {
    Gltf g = skinnedBar();
    attributes(g)["JOINTS_0"] = g.floats(std::vector<float>(24, 0.0f), "VEC4");
    expectRejected(g, "joints_float.gltf",
                   {"meshes[0].primitives[0].attributes.JOINTS_0 needs VEC4 "
                    "UNSIGNED_BYTE/UNSIGNED_SHORT, got VEC4 FLOAT"});
}

TEST(GltfAnimationValidation, WeightsUnnormalizedIntegers) {
    Gltf g = skinnedBar();
    attributes(g)["WEIGHTS_0"] = g.ints(std::vector<std::uint8_t>(24, 64), kU8, "VEC4");
    expectRejected(g, "weights_unnormalized.gltf",
                   {"attributes.WEIGHTS_0 with component type UNSIGNED_BYTE must be normalized"});
}

TEST(GltfAnimationValidation, NormalizedByteWeightsRenormalisedSilently) {
    Gltf g = skinnedBar();
    // 85 * 3 = 255: three thirds; 127 + 127 = 254: just short of 1, as quantization leaves it.
    std::vector<std::uint8_t> w(24, 0);
    for (std::size_t v = 0; v < 6; ++v) {
        w[4 * v] = 127;
        w[4 * v + 1] = 127;
    }
    attributes(g)["WEIGHTS_0"] = g.ints(w, kU8, "VEC4", /*normalized=*/true);
    const Loaded l = load(g.write("weights_u8.gltf"));
    EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
    EXPECT_FLOAT_EQ(l.scene.meshes[0].weights[0].x, 0.5f);
}

TEST(GltfAnimationValidation, WeightsNotSummingToOne) {
    Gltf g = skinnedBar();
    attributes(g)["WEIGHTS_0"] = weightsWith(g, {1, 1, 2, 0});
    const Loaded l = load(g.write("weights_sum.gltf"));
    EXPECT_TRUE(l.warned("weights_sum.gltf: meshes[0].primitives[0]: WEIGHTS_0: 1 vertex weight "
                         "sum(s) not 1; normalised"));
    EXPECT_EQ(l.scene.meshes[0].weights[0], glm::vec4(0.25f, 0.25f, 0.5f, 0.0f));
}

TEST(GltfAnimationValidation, WeightsAllZero) {
    Gltf g = skinnedBar();
    attributes(g)["WEIGHTS_0"] = weightsWith(g, {0, 0, 0, 0});
    const Loaded l = load(g.write("weights_zero.gltf"));
    EXPECT_TRUE(l.warned("weights_zero.gltf: meshes[0].primitives[0]: WEIGHTS_0: 1 vertex(es) "
                         "with no weight; weight 1 given to their first joint"));
    EXPECT_EQ(l.scene.meshes[0].weights[0], glm::vec4(1, 0, 0, 0));
}

TEST(GltfAnimationValidation, WeightsNegativeOrNaN) {
    Gltf g = skinnedBar();
    attributes(g)["WEIGHTS_0"] = weightsWith(g, {0.5f, -0.5f, kNaN, 0.5f});
    const Loaded l = load(g.write("weights_negative.gltf"));
    EXPECT_TRUE(l.warned("weights_negative.gltf: meshes[0].primitives[0]: WEIGHTS_0: 2 negative "
                         "or non-finite weight(s) set to 0"));
    EXPECT_EQ(l.scene.meshes[0].weights[0], glm::vec4(0.5f, 0, 0, 0.5f));
}

TEST(GltfAnimationValidation, JointsWithoutWeights) {
    Gltf g = skinnedBar();
    attributes(g).erase("WEIGHTS_0");
    const Loaded l = load(g.write("joints_no_weights.gltf"));
    EXPECT_TRUE(l.warned("joints_no_weights.gltf: meshes[0].primitives[0]: JOINTS_0 without "
                         "WEIGHTS_0; drawn unskinned"));
    EXPECT_EQ(l.scene.instances[0].skin, -1);
}

TEST(GltfAnimationValidation, SecondInfluenceSetIgnored) {
    Gltf g = skinnedBar();
    attributes(g)["JOINTS_1"] = attributes(g)["JOINTS_0"];
    attributes(g)["WEIGHTS_1"] = attributes(g)["WEIGHTS_0"];
    const Loaded l = load(g.write("joints_1.gltf"));
    EXPECT_TRUE(l.warned("joints_1.gltf: meshes[0].primitives[0]: JOINTS_1 ignored (at most 4 "
                         "joint influences per vertex)"));
    EXPECT_TRUE(l.warned("WEIGHTS_1 ignored"));
    EXPECT_EQ(l.scene.instances[0].skin, 0);
}

// --- morph targets --------------------------------------------------------------------------

TEST(GltfAnimationValidation, TargetPositionCountMismatch) {
    Gltf g = morphTriangle();
    g.prim()["targets"][0]["POSITION"] = g.vec3({{0, 0, 1}, {0, 0, 1}});
    expectRejected(g, "target_count.gltf",
                   {"meshes[0].primitives[0]", "targets[0].POSITION has 2 elements but POSITION "
                                               "has 3"});
}

TEST(GltfAnimationValidation, TargetsBeyondTheVertexStagesLimitAreDroppedWithAWarning) {
    Gltf g = morphTriangle();
    const json target = g.prim()["targets"][0];
    for (std::size_t i = 1; i < kMaxMorphTargets + 3; ++i) g.prim()["targets"].push_back(target);
    const Loaded l = load(g.write("too_many_targets.gltf"));
    EXPECT_EQ(l.scene.meshes[0].targets.size(), kMaxMorphTargets);
    EXPECT_EQ(l.scene.meshes[0].morphWeights.size(), kMaxMorphTargets);
    EXPECT_TRUE(l.warned("meshes[0]: 35 morph targets: the first 32 are drawn"));
}

TEST(GltfAnimationValidation, TargetNormalCountMismatch) {
    Gltf g = morphTriangle();
    g.prim()["targets"][0]["NORMAL"] = g.vec3({{0, 0, 1}});
    expectRejected(g, "target_normal_count.gltf",
                   {"meshes[0].primitives[0]", "targets[0].NORMAL has 1 elements but POSITION "
                                               "has 3"});
}

TEST(GltfAnimationValidation, TargetDeltaNotFinite) {
    Gltf g = morphTriangle();
    g.prim()["targets"][0]["POSITION"] = g.vec3({{0, 0, 1}, {0, kNaN, 1}, {0, 0, 1}});
    expectRejected(g, "target_nan.gltf",
                   {"meshes[0].primitives[0].targets[0].POSITION: delta 1 is not finite"});
}

TEST(GltfAnimationValidation, TargetCountsDifferBetweenPrimitives) {
    Gltf g = morphTriangle();
    json second = g.prim();
    second.erase("targets");
    g.doc["meshes"][0]["primitives"].push_back(second);
    expectRejected(g, "target_primitives.gltf",
                   {"meshes[0].primitives[1]", "0 morph targets but primitives[0] has 1"});
}

TEST(GltfAnimationValidation, MeshWeightsCountMismatch) {
    Gltf g = morphTriangle();
    g.doc["meshes"][0]["weights"] = {0.5, 0.5};
    const Loaded l = load(g.write("mesh_weights_count.gltf"));
    EXPECT_TRUE(l.warned("mesh_weights_count.gltf: meshes[0]: weights has 2 values but the mesh "
                         "has 1 morph targets; zeros used"));
    EXPECT_EQ(l.scene.meshes[0].morphWeights, std::vector<float>{0.0f});
}

TEST(GltfAnimationValidation, NodeWeightsCountMismatch) {
    Gltf g = morphTriangle();
    g.node(0)["weights"] = {0.1, 0.2, 0.3};
    const Loaded l = load(g.write("node_weights_count.gltf"));
    EXPECT_TRUE(l.warned("node_weights_count.gltf: nodes[0]: weights has 3 values but its mesh "
                         "has 1 morph targets; the mesh's weights used"));
    EXPECT_TRUE(l.scene.nodes[0].weights.empty());
}

TEST(GltfAnimationValidation, TargetNormalWithoutBaseNormal) {
    Gltf g = morphTriangle();
    attributes(g).erase("NORMAL");
    const Loaded l = load(g.write("target_normal_no_base.gltf"));
    EXPECT_TRUE(l.warned("target_normal_no_base.gltf: meshes[0].primitives[0]: targets[0].NORMAL "
                         "ignored: the primitive has no NORMAL"));
    EXPECT_TRUE(l.scene.meshes[0].targets[0].normals.empty());
    EXPECT_EQ(l.scene.meshes[0].targets[0].positions.size(), 3u);
}

TEST(GltfAnimationValidation, TangentDeltasIgnoredSilently) {
    Gltf g = morphTriangle();
    g.prim()["targets"][0]["TANGENT"] = g.vec3({{1, 0, 0}, {1, 0, 0}, {1, 0, 0}});
    const Loaded l = load(g.write("target_tangent.gltf"));
    EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
    EXPECT_EQ(l.scene.meshes[0].targets.size(), 1u);
}

TEST(GltfAnimationValidation, QuantizedTargetPositionsNeedTheExtension) {
    Gltf g = morphTriangle();
    g.prim()["targets"][0]["POSITION"] =
        g.ints(std::vector<std::int8_t>{0, 0, 127, 0, 0, -127, 0, 0, 0}, kI8, "VEC3", true);
    expectRejected(g, "target_i8.gltf", {"targets[0].POSITION needs VEC3 FLOAT, got VEC3 BYTE"});
    g.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
    const Loaded l = load(g.write("target_i8_quantized.gltf"));
    EXPECT_EQ(l.scene.meshes[0].targets[0].positions[1], glm::vec3(0, 0, -1));
}

TEST(GltfAnimationValidation, AbsurdMorphTargetCount) {
    Gltf g = triangle();
    // Empty targets name no accessor, so only a count limit bounds what they cost.
    g.prim()["targets"] = json::array();
    for (int i = 0; i <= 1 << 16; ++i) g.prim()["targets"].push_back(json::object());
    expectRejected(g, "absurd_targets.gltf",
                   {"meshes[0]", "absurd morph target count 65537 (limit 65536)"});
}

// --- animations -----------------------------------------------------------------------------

TEST(GltfAnimationValidation, SamplerTimesNotIncreasing) {
    Gltf g = skinnedBar();
    sampler(g, 0)["input"] = g.floats({0, 1, 1}, "SCALAR");
    expectRejected(g, "times_not_increasing.gltf",
                   {"animations[0].samplers[0]",
                    "input times are not strictly increasing: time 2 (1) after time 1 (1)"});
}

TEST(GltfAnimationValidation, SamplerTimesNegative) {
    Gltf g = skinnedBar();
    sampler(g, 1)["input"] = g.floats({-1, 1, 2}, "SCALAR");
    expectRejected(g, "times_negative.gltf",
                   {"animations[0].samplers[1]", "input time 0 is negative (-1)"});
}

TEST(GltfAnimationValidation, SamplerTimesNaN) {
    Gltf g = skinnedBar();
    sampler(g, 2)["input"] = g.floats({0, kNaN, 2}, "SCALAR");
    expectRejected(g, "times_nan.gltf",
                   {"animations[0].samplers[2]", "input time 1 is not finite"});
}

TEST(GltfAnimationValidation, SamplerTimesWrongType) {
    Gltf g = skinnedBar();
    sampler(g, 0)["input"] = g.ints(std::vector<std::uint16_t>{0, 1, 2}, kU16, "SCALAR");
    expectRejected(g, "times_u16.gltf",
                   {"animations[0].samplers[0].input needs SCALAR FLOAT, got SCALAR "
                    "UNSIGNED_SHORT"});
}

TEST(GltfAnimationValidation, SamplerOutputCountMismatch) {
    Gltf g = skinnedBar();
    sampler(g, 0)["output"] = g.floats(std::vector<float>(6, 0.0f), "VEC3");
    expectRejected(g, "output_count.gltf",
                   {"animations[0].samplers[0]", "output has 2 elements but 3 keys need 3"});
}

TEST(GltfAnimationValidation, CubicSplineOutputCountMismatch) {
    Gltf g = skinnedBar();
    sampler(g, 2)["output"] = g.floats(std::vector<float>(9, 1.0f), "VEC3");
    expectRejected(
        g, "cubic_count.gltf",
        {"animations[0].samplers[2]", "output has 3 elements but 3 keys x 3 (CUBICSPLINE) need 9"});
}

TEST(GltfAnimationValidation, WeightsOutputCountMismatch) {
    Gltf g = morphTriangle();
    animate(g, g.floats({0, 1}, "SCALAR"), g.floats({0, 1, 0}, "SCALAR"), 0, "weights");
    expectRejected(
        g, "weights_output_count.gltf",
        {"animations[0].samplers[0]", "output has 3 elements but 2 keys x 1 morph targets need 2"});
}

TEST(GltfAnimationValidation, SamplerOutputNotFinite) {
    Gltf g = skinnedBar();
    sampler(g, 0)["output"] = g.floats({0, 0, 0, 1, kNaN, 0, 2, 0, 0}, "VEC3");
    expectRejected(g, "output_nan.gltf",
                   {"animations[0].samplers[0]", "output element 1 is not finite"});
}

TEST(GltfAnimationValidation, RotationOutputWrongType) {
    Gltf g = skinnedBar();
    sampler(g, 1)["output"] = g.floats(std::vector<float>(9, 0.0f), "VEC3");
    expectRejected(g, "rotation_vec3.gltf",
                   {"animations[0].samplers[1].output needs VEC4 "
                    "FLOAT/BYTE/UNSIGNED_BYTE/SHORT/UNSIGNED_SHORT, got VEC3 FLOAT"});
}

TEST(GltfAnimationValidation, RotationOutputNormalizedShorts) {
    Gltf g = skinnedBar();
    sampler(g, 1)["output"] =
        g.ints(std::vector<std::int16_t>{0, 0, 0, 32767, 0, 0, 32767, 0, 0, 0, -32767, 0}, kI16,
               "VEC4", true);
    const Loaded l = load(g.write("rotation_i16.gltf"));
    const auto& v = l.scene.animations[0].samplers[1].values;
    ASSERT_EQ(v.size(), 12u);
    EXPECT_EQ(v[10], -1.0f);
}

TEST(GltfAnimationValidation, TranslationOutputIntegers) {
    Gltf g = skinnedBar();
    sampler(g, 0)["output"] =
        g.ints(std::vector<std::int16_t>(9, 0), kI16, "VEC3", /*normalized=*/true);
    expectRejected(g, "translation_i16.gltf",
                   {"animations[0].samplers[0].output needs VEC3 FLOAT, got VEC3 SHORT"});
}

TEST(GltfAnimationValidation, ZeroRotationKey) {
    Gltf g = skinnedBar();
    sampler(g, 1)["output"] = g.floats({0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 1}, "VEC4");
    const Loaded l = load(g.write("rotation_zero.gltf"));
    EXPECT_TRUE(l.warned("rotation_zero.gltf: animations[0].samplers[1]: 1 zero rotation key(s) "
                         "replaced by identity"));
    EXPECT_EQ(l.scene.animations[0].samplers[1].values[7], 1.0f);
}

TEST(GltfAnimationValidation, UnknownInterpolation) {
    Gltf g = skinnedBar();
    sampler(g, 0)["interpolation"] = "BEZIER";
    const Loaded l = load(g.write("interpolation.gltf"));
    EXPECT_TRUE(l.warned(
        "interpolation.gltf: animations[0].samplers[0]: unknown interpolation 'BEZIER'; LINEAR "
        "used"));
    EXPECT_EQ(l.scene.animations[0].samplers[0].interpolation, Animation::Interpolation::Linear);
}

TEST(GltfAnimationValidation, ChannelWithoutNode) {
    Gltf g = skinnedBar();
    channel(g, 0)["target"].erase("node"); // as KHR_animation_pointer writes them
    const Loaded l = load(g.write("channel_no_node.gltf"));
    // tinygltf drops the channel and says so; the loader passes that on as a warning.
    EXPECT_TRUE(l.warned("channel_no_node.gltf: `node` field is missing")) << l.warnings.size();
    EXPECT_EQ(l.scene.animations[0].channels.size(), 2u);
}

TEST(GltfAnimationValidation, ChannelNodeOutOfRange) {
    Gltf g = skinnedBar();
    channel(g, 1)["target"]["node"] = 7;
    expectRejected(g, "channel_node_range.gltf",
                   {"animations[0].channels[1].target.node", "node 7 does not exist (3 in nodes)"});
}

TEST(GltfAnimationValidation, ChannelUnknownPath) {
    Gltf g = skinnedBar();
    channel(g, 0)["target"]["path"] = "pointer";
    const Loaded l = load(g.write("channel_path.gltf"));
    EXPECT_TRUE(l.warned("channel_path.gltf: animations[0].channels[0]: target path 'pointer' is "
                         "not translation, rotation, scale or weights; channel skipped"));
    ASSERT_EQ(l.scene.animations[0].channels.size(), 2u);
    EXPECT_EQ(l.scene.animations[0].samplers.size(), 2u); // samplers[0] unused: not read
}

TEST(GltfAnimationValidation, ChannelSamplerOutOfRange) {
    Gltf g = skinnedBar();
    channel(g, 2)["sampler"] = 3;
    expectRejected(g, "channel_sampler_range.gltf",
                   {"animations[0].channels[2].sampler",
                    "sampler 3 does not exist (3 in animations[0].samplers)"});
}

TEST(GltfAnimationValidation, WeightsChannelWithoutTargets) {
    Gltf g = skinnedBar();
    channel(g, 0)["target"]["path"] = "weights";
    const Loaded l = load(g.write("weights_no_targets.gltf"));
    EXPECT_TRUE(l.warned("weights_no_targets.gltf: animations[0].channels[0]: weights of "
                         "nodes[1], which has no mesh with morph targets; channel skipped"));
    EXPECT_EQ(l.scene.animations[0].channels.size(), 2u);
}

TEST(GltfAnimationValidation, SamplerSharedByIncompatibleChannels) {
    Gltf g = skinnedBar();
    channel(g, 1)["sampler"] = 0; // translation's VEC3 sampler read as a rotation
    expectRejected(g, "sampler_shared.gltf",
                   {"animations[0].channels[1]", "samplers[0] is read as rotation here but "
                                                 "differently by animations[0].channels[0]"});
}

TEST(GltfAnimationValidation, DuplicateChannelTarget) {
    Gltf g = skinnedBar();
    g.doc["animations"][0]["channels"].push_back(channel(g, 0));
    const Loaded l = load(g.write("channel_twice.gltf"));
    EXPECT_TRUE(l.warned("channel_twice.gltf: animations[0].channels[3]: nodes[1].translation is "
                         "already animated by an earlier channel; channel skipped"));
    EXPECT_EQ(l.scene.animations[0].channels.size(), 3u);
}

TEST(GltfAnimationValidation, AnimatedShearedMatrixNode) {
    Gltf g = skinnedBar();
    g.node(1)["matrix"] = {1, 0, 0, 0, 0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    expectRejected(g, "animated_shear.gltf",
                   {"nodes[1]", "animated by animations[0].channels[0] but its matrix is not a "
                                "translation, rotation and scale"});
}

TEST(GltfAnimationValidation, AnimationInputAbsurdCount) {
    Gltf g = skinnedBar();
    // Animation data goes through the accessor limits: no bufferView, so the count is all it takes.
    sampler(g, 0)["input"] =
        g.push("accessors", {{"componentType", kFloat}, {"type", "SCALAR"}, {"count", 1 << 25}});
    expectRejected(g, "animation_absurd.gltf",
                   {"accessors[", "absurd count 33554432 (limit 16777216)"});
}

} // namespace
} // namespace fl::test
