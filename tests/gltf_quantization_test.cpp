// KHR_mesh_quantization (issue 15, item 3): integer positions, normals and texture coordinates,
// read as they are and scaled by the node's transform; refused without the extension, and in
// the forms the extension does not list.

#include "GltfBuilder.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace fl::test {
namespace {

constexpr int kByte = 5120, kShort = 5122;

// A triangle with SHORT positions (x100, node scale 0.01), normalized BYTE normals and
// UNSIGNED_SHORT texcoords, each element padded to 4 bytes as the extension requires.
Gltf quantizedTriangle(bool declare = true) {
    Gltf g;
    const std::vector<std::int16_t> pos = {0, 0, 0, 0, 100, 0, 0, 0, 0, 100, 0, 0};
    const std::vector<std::int8_t> nrm = {0, 0, 127, 0, 0, 0, 127, 0, 0, 0, 127, 0};
    const std::vector<std::uint16_t> uv = {0, 0, 2, 0, 0, 2};
    const int p = g.accessor(g.view(pos, 8), kShort, "VEC3", 3);
    g.accessorAt(p)["min"] = {0, 0, 0};
    g.accessorAt(p)["max"] = {100, 100, 0};
    const int n = g.accessor(g.view(nrm, 4), kByte, "VEC3", 3);
    g.accessorAt(n)["normalized"] = true;
    const int t = g.accessor(g.view(uv), kU16, "VEC2", 3);
    const int idx = g.indices(std::vector<std::uint16_t>{0, 1, 2}, kU16);
    g.push("meshes",
           {{"primitives",
             json::array({{{"attributes", {{"POSITION", p}, {"NORMAL", n}, {"TEXCOORD_0", t}}},
                           {"indices", idx}}})}});
    g.push("nodes", {{"mesh", 0}, {"name", "tri"}, {"scale", {0.01, 0.01, 0.01}}});
    g.doc["scenes"] = json::array({{{"nodes", {0}}}});
    g.doc["scene"] = 0;
    if (declare) {
        g.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
        g.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
    }
    return g;
}

TEST(GltfQuantization, IntegerAttributesAreReadAndScaledByTheNode) {
    const Loaded l = load(quantizedTriangle().write("quantized.gltf"));
    ASSERT_EQ(l.scene.meshes.size(), 1u);
    const Mesh& m = l.scene.meshes[0];
    ASSERT_EQ(m.positions.size(), 3u);
    EXPECT_EQ(m.positions[1], glm::vec3(100, 0, 0));
    EXPECT_EQ(m.positions[2], glm::vec3(0, 100, 0));
    for (const glm::vec3& nrm : m.normals)
        EXPECT_NEAR(glm::length(nrm - glm::vec3(0, 0, 1)), 0, 1e-6f);
    ASSERT_EQ(m.texcoords.size(), 3u);
    EXPECT_EQ(m.texcoords[1], glm::vec2(2, 0)); // unnormalized: as stored
    // The node's scale brings the model back to size: a unit triangle in the world.
    EXPECT_NEAR(l.scene.bounds.max.x, 1.0f, 1e-6f);
    EXPECT_NEAR(l.scene.bounds.max.y, 1.0f, 1e-6f);
    EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
}

TEST(GltfQuantization, WithoutTheExtensionIntegerPositionsAreRefused) {
    expectRejected(quantizedTriangle(false), "unquantized.gltf",
                   {"attributes.POSITION needs VEC3 FLOAT, got VEC3 SHORT"});
}

TEST(GltfQuantization, NormalsMustBeNormalized) {
    Gltf g = quantizedTriangle();
    g.accessorAt(1)["normalized"] = false;
    expectRejected(g, "raw_normals.gltf",
                   {"attributes.NORMAL with component type BYTE must be normalized"});
}

TEST(GltfQuantization, UnnormalizedTexcoordsNeedTheExtension) {
    // Float positions and normals: only the texcoords are out of the core spec.
    Gltf core = triangle();
    core.prim()["attributes"]["TEXCOORD_0"] =
        core.accessor(core.view(std::vector<std::uint16_t>{0, 0, 2, 0, 0, 2}), kU16, "VEC2", 3);
    expectRejected(core, "raw_texcoords.gltf",
                   {"attributes.TEXCOORD_0 with component type UNSIGNED_SHORT must be normalized"});
}

} // namespace
} // namespace fl::test
