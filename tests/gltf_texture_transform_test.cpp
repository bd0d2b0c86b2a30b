// The base colour texture's coordinate set and KHR_texture_transform (issue 15, item 1, part):
// applied to the mesh's texture coordinates at load, as the extension's README defines the
// matrix (translation * rotation * scale, counter-clockwise); bad values are ignored with a
// warning.

#include "GltfBuilder.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fl::test {
namespace {

// The unit triangle with TEXCOORD_0 (0,0) (1,0) (0,1) and TEXCOORD_1 (0.5,0.5) x3, and a
// material whose base colour texture carries `info` (its image does not exist: the texture is
// dropped with a warning, the coordinates are still what it would read).
Gltf texturedTriangle(json info) {
    Gltf g = triangle();
    g.prim()["attributes"]["TEXCOORD_0"] =
        g.accessor(g.view(std::vector<float>{0, 0, 1, 0, 0, 1}), kFloat, "VEC2", 3);
    g.prim()["attributes"]["TEXCOORD_1"] = g.accessor(
        g.view(std::vector<float>{0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f}), kFloat, "VEC2", 3);
    info["index"] = 4;
    g.push("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", info}}}});
    g.prim()["material"] = 0;
    g.doc["extensionsUsed"] = {"KHR_texture_transform"};
    return g;
}

void expectNear(glm::vec2 a, glm::vec2 b) {
    EXPECT_NEAR(a.x, b.x, 1e-6f) << a.x << "," << a.y;
    EXPECT_NEAR(a.y, b.y, 1e-6f) << a.x << "," << a.y;
}

TEST(GltfTextureTransform, OffsetRotationAndScaleInTheSpecsOrder) {
    const float quarter = std::acos(0.0f); // 90 degrees
    const Loaded l =
        load(texturedTriangle(
                 {{"extensions",
                   {{"KHR_texture_transform",
                     {{"offset", {0.25, 0.5}}, {"rotation", quarter}, {"scale", {2, 3}}}}}}})
                 .write("texture_transform.gltf"));
    const auto& uv = l.scene.meshes[0].texcoords;
    ASSERT_EQ(uv.size(), 3u);
    // (u, v) -> scale (2u, 3v) -> rotate 90 degrees counter-clockwise (-3v, 2u) -> offset.
    expectNear(uv[0], {0.25f, 0.5f});
    expectNear(uv[1], {0.25f, 2.5f});
    expectNear(uv[2], {-2.75f, 0.5f});
}

TEST(GltfTextureTransform, TheTextureCoordinateSetIsTheOneTheTextureNames) {
    const Loaded set1 = load(texturedTriangle({{"texCoord", 1}}).write("texcoord1.gltf"));
    for (const glm::vec2& uv : set1.scene.meshes[0].texcoords) expectNear(uv, {0.5f, 0.5f});
    // The extension's texCoord overrides the textureInfo's.
    const Loaded back =
        load(texturedTriangle(
                 {{"texCoord", 1}, {"extensions", {{"KHR_texture_transform", {{"texCoord", 0}}}}}})
                 .write("texcoord_override.gltf"));
    expectNear(back.scene.meshes[0].texcoords[1], {1.0f, 0.0f});
    // A set the primitive does not have: drawn untextured, and said so.
    const Loaded missing = load(texturedTriangle({{"texCoord", 3}}).write("texcoord3.gltf"));
    EXPECT_TRUE(missing.scene.meshes[0].texcoords.empty());
    EXPECT_TRUE(missing.warned("reads TEXCOORD_3, which it does not have"));
}

TEST(GltfTextureTransform, BadValuesAreIgnoredWithAWarning) {
    const Loaded l = load(
        texturedTriangle({{"extensions",
                           {{"KHR_texture_transform",
                             {{"offset", {1, "x"}}, {"rotation", 1e300}, {"scale", {2, 2}}}}}}})
            .write("bad_transform.gltf"));
    expectNear(l.scene.meshes[0].texcoords[1], {2.0f, 0.0f}); // the scale alone
    EXPECT_TRUE(l.warned("offset is not 2 finite numbers"));
    EXPECT_TRUE(l.warned("rotation is not a finite number"));
}

} // namespace
} // namespace fl::test
