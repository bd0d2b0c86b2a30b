// glTF alpha (issue 15, item 1): alphaMode and alphaCutoff on the material, COLOR_0 on the mesh;
// bad values repaired with a warning, inconsistent colour accessors rejected.

#include "GltfBuilder.h"

#include <gtest/gtest.h>

namespace fl::test {
namespace {

// triangle() with a material carrying `material`'s fields.
Gltf triangleWithMaterial(json material) {
    Gltf g = triangle();
    g.prim()["material"] = g.push("materials", std::move(material));
    return g;
}

TEST(GltfAlpha, ModesAndCutoffAreRead) {
    const Loaded mask = load(
        triangleWithMaterial({{"alphaMode", "MASK"}, {"alphaCutoff", 0.25}}).write("mask.gltf"));
    ASSERT_EQ(mask.scene.materials.size(), 1u);
    EXPECT_EQ(mask.scene.materials[0].alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(mask.scene.materials[0].alphaCutoff, 0.25f);
    EXPECT_EQ(shadowCutoff(mask.scene.materials[0]), 0.25f);

    const Loaded blend = load(triangleWithMaterial({{"alphaMode", "BLEND"}}).write("blend.gltf"));
    EXPECT_EQ(blend.scene.materials[0].alphaMode, AlphaMode::Blend);
    EXPECT_EQ(shadowCutoff(blend.scene.materials[0]), 0.5f) << "BLEND casts where alpha >= 0.5";

    const Loaded opaque = load(triangleWithMaterial({{"name", "plain"}}).write("opaque.gltf"));
    EXPECT_EQ(opaque.scene.materials[0].alphaMode, AlphaMode::Opaque);
    EXPECT_FLOAT_EQ(opaque.scene.materials[0].alphaCutoff, 0.5f) << "the spec's default";
    EXPECT_FALSE(shadowCutoff(opaque.scene.materials[0]).has_value());
    EXPECT_TRUE(opaque.warnings.empty());
}

TEST(GltfAlpha, UnknownModeIsDrawnOpaqueWithAWarning) {
    const Loaded l = load(triangleWithMaterial({{"alphaMode", "CUTOUT"}}).write("cutout.gltf"));
    EXPECT_EQ(l.scene.materials[0].alphaMode, AlphaMode::Opaque);
    EXPECT_TRUE(l.warned("materials[0]: alphaMode \"CUTOUT\" is not OPAQUE, MASK or BLEND"));
}

TEST(GltfAlpha, NegativeCutoffGetsTheDefaultWithAWarning) {
    const Loaded l =
        load(triangleWithMaterial({{"alphaMode", "MASK"}, {"alphaCutoff", -1}}).write("neg.gltf"));
    EXPECT_FLOAT_EQ(l.scene.materials[0].alphaCutoff, 0.5f);
    EXPECT_TRUE(l.warned("alphaCutoff is not a finite number >= 0; 0.5 used"));
}

TEST(GltfAlpha, VertexColoursVec3AndNormalizedVec4) {
    Gltf g = triangle();
    g.prim()["attributes"]["COLOR_0"] =
        g.accessor(g.view(std::vector<float>{1, 0, 0, 0, 1, 0, 0, 0, 1}), kFloat, "VEC3", 3);
    const Loaded rgb = load(g.write("color_vec3.gltf"));
    ASSERT_EQ(rgb.scene.meshes[0].colors.size(), 3u);
    EXPECT_EQ(rgb.scene.meshes[0].colors[1], glm::vec4(0, 1, 0, 1)) << "VEC3 gets alpha 1";

    Gltf h = triangle();
    const int a = h.accessor(
        h.view(std::vector<std::uint8_t>{255, 255, 255, 0, 255, 255, 255, 255, 0, 0, 0, 51}), kU8,
        "VEC4", 3);
    h.accessorAt(a)["normalized"] = true;
    h.prim()["attributes"]["COLOR_0"] = a;
    const Loaded rgba = load(h.write("color_vec4.gltf"));
    ASSERT_EQ(rgba.scene.meshes[0].colors.size(), 3u);
    EXPECT_EQ(rgba.scene.meshes[0].colors[0].a, 0.0f);
    EXPECT_EQ(rgba.scene.meshes[0].colors[1].a, 1.0f);
    EXPECT_FLOAT_EQ(rgba.scene.meshes[0].colors[2].a, 0.2f);
}

TEST(GltfAlpha, VertexColoursOutOfRangeAreClampedWithAWarning) {
    Gltf g = triangle();
    g.prim()["attributes"]["COLOR_0"] = g.accessor(
        g.view(std::vector<float>{2, 0, 0, 1, 0, -1, 0, 1, 0, 0, 1, 1}), kFloat, "VEC4", 3);
    const Loaded l = load(g.write("color_range.gltf"));
    EXPECT_EQ(l.scene.meshes[0].colors[0], glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(l.scene.meshes[0].colors[1], glm::vec4(0, 0, 0, 1));
    EXPECT_TRUE(l.warned("2 COLOR_0 value(s) outside [0, 1] or not finite repaired"));
}

TEST(GltfAlpha, VertexColourCountOrTypeThatDoesNotFitIsRejected) {
    Gltf g = triangle();
    g.prim()["attributes"]["COLOR_0"] =
        g.accessor(g.view(std::vector<float>{1, 1, 1, 1, 1, 1}), kFloat, "VEC3", 2);
    expectRejected(g, "color_count.gltf", {"COLOR_0 has 2 elements but POSITION has 3"});
    Gltf h = triangle();
    h.prim()["attributes"]["COLOR_0"] =
        h.accessor(h.view(std::vector<std::uint8_t>{255, 255, 255, 255, 255, 255, 255, 255, 255,
                                                    255, 255, 255}),
                   kU8, "VEC4", 3);
    expectRejected(h, "color_unnormalized.gltf", {"COLOR_0", "must be normalized"});
}

} // namespace
} // namespace fl::test
