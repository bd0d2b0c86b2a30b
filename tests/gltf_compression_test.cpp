// Compressed meshes (issue 15, item 3): KHR_draco_mesh_compression and EXT_meshopt_compression
// files built with the libraries' encoders load as the same mesh uncompressed (exactly for
// meshopt, within the quantisation step for Draco), as .gltf and .glb; corrupt or inconsistent
// compressed data is rejected with one message naming the file, the element and the problem.

#include "CompressedGltf.h"
#include "GltfBuilder.h"

#include <base/Text.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>

namespace fl::test {
namespace {

const Mesh& onlyMesh(const Loaded& l) {
    EXPECT_EQ(l.scene.meshes.size(), 1u);
    return l.scene.meshes.front();
}

// --- EXT_meshopt_compression ---------------------------------------------------------------

/// The triangles as vertex triples rotated to start at their smallest index (winding kept).
/// (`map` renames the vertices first; none: as they are).
std::multiset<std::array<std::uint32_t, 3>> triangles(const std::vector<std::uint32_t>& indices,
                                                      const std::vector<std::uint32_t>& map = {}) {
    std::multiset<std::array<std::uint32_t, 3>> out;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        std::array<std::uint32_t, 3> tri = {indices[t], indices[t + 1], indices[t + 2]};
        if (!map.empty())
            for (std::uint32_t& v : tri) v = map[v];
        std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
        out.insert(tri);
    }
    return out;
}

class GltfMeshoptContainers : public ::testing::TestWithParam<Container> {};

std::string suffix(Container c) {
    return c == Container::Glb ? ".glb" : c == Container::BinFile ? "_bin.gltf" : ".gltf";
}

// The fallback buffer has no uri (tinygltf 2.7 refuses that in a .gltf, and hands it a .glb's
// BIN chunk): the loader must still read the compressed views, and give exactly the mesh of the
// decoded bytes stored uncompressed.
TEST_P(GltfMeshoptContainers, LoadsAsTheDecodedBytesStoredPlainly) {
    for (const bool sequence : {false, true}) {
        const MeshoptGltf files = meshoptGltf(gridMesh(9), sequence);
        const std::string name = std::string(sequence ? "meshopt_indices" : "meshopt_triangles");
        const Loaded compressed =
            load(files.compressed.write(name + suffix(GetParam()), GetParam()));
        const Loaded plain = load(files.plain.write(name + "_plain" + suffix(GetParam())));
        const Mesh& a = onlyMesh(compressed);
        const Mesh& b = onlyMesh(plain);
        EXPECT_EQ(a.positions, b.positions);
        EXPECT_EQ(a.normals, b.normals);
        EXPECT_EQ(a.texcoords, b.texcoords);
        EXPECT_EQ(a.indices, b.indices);
        // TRIANGLES mode may rotate a triangle's corners; it keeps the triangles and winding.
        EXPECT_EQ(triangles(a.indices), triangles(gridMesh(9).indices));
        EXPECT_TRUE(compressed.warnings.empty()) << compressed.warnings.front();
    }
}

INSTANTIATE_TEST_SUITE_P(Containers, GltfMeshoptContainers,
                         ::testing::Values(Container::DataUri, Container::BinFile, Container::Glb));

json& meshoptExt(Gltf& g, int view) {
    return g.doc["bufferViews"][static_cast<std::size_t>(view)]["extensions"]
                ["EXT_meshopt_compression"];
}

constexpr const char* kPositionView = "bufferViews[0].extensions.EXT_meshopt_compression";

TEST(GltfMeshoptBadInput, CorruptVertexDataIsRejected) {
    Gltf g = meshoptGltf(gridMesh(9)).compressed;
    // The vertex codec's header byte (0xa0 | version) made invalid.
    g.bin[meshoptExt(g, 0)["byteOffset"].get<std::size_t>()] = 0x00;
    expectRejected(g, "meshopt_corrupt.gltf",
                   {kPositionView, "compressed data is corrupt (meshoptimizer error"});
}

TEST(GltfMeshoptBadInput, TruncatedIndexDataIsRejected) {
    Gltf g = meshoptGltf(gridMesh(9)).compressed;
    meshoptExt(g, 3)["byteLength"] = 8;
    expectRejected(
        g, "meshopt_truncated.glb",
        {"bufferViews[3].extensions.EXT_meshopt_compression", "compressed data is corrupt"},
        Container::Glb);
}

TEST(GltfMeshoptBadInput, CountTimesStrideDisagreeingWithByteLengthIsRejected) {
    Gltf g = meshoptGltf(gridMesh(9)).compressed;
    meshoptExt(g, 0)["count"] = 82;
    expectRejected(
        g, "meshopt_count.gltf",
        {kPositionView, "count 82 * byteStride 12 = 984 bytes", "bufferView's byteLength is 972"});
}

TEST(GltfMeshoptBadInput, AbsurdCountIsRejectedBeforeAllocating) {
    Gltf g = meshoptGltf(gridMesh(9)).compressed;
    // tinygltf keeps extension integers as int: larger counts arrive truncated, and are then
    // rejected by the byteLength check.
    meshoptExt(g, 0)["count"] = 1 << 30;
    expectRejected(g, "meshopt_huge_count.gltf", {kPositionView, "count 1073741824 outside"});
}

TEST(GltfMeshoptBadInput, UnknownModeAndFilterAreRejected) {
    Gltf g = meshoptGltf(gridMesh(9)).compressed;
    meshoptExt(g, 0)["mode"] = "VERTICES";
    expectRejected(g, "meshopt_mode.gltf",
                   {kPositionView, "mode is not one of ATTRIBUTES, TRIANGLES, INDICES"});
    g = meshoptGltf(gridMesh(9)).compressed;
    meshoptExt(g, 0)["filter"] = "ZIGZAG";
    expectRejected(g, "meshopt_filter.gltf", {kPositionView, "filter is not one of NONE"});
}

TEST(GltfMeshoptBadInput, FilterWithAStrideItCannotDecodeIsRejected) {
    Gltf g = meshoptGltf(gridMesh(9)).compressed;
    meshoptExt(g, 0)["filter"] = "OCTAHEDRAL";
    expectRejected(g, "meshopt_oct_stride.gltf",
                   {kPositionView, "OCTAHEDRAL needs byteStride 4 or 8, got 12"});
    g = meshoptGltf(gridMesh(9)).compressed;
    meshoptExt(g, 3)["filter"] = "EXPONENTIAL";
    expectRejected(g, "meshopt_index_filter.gltf",
                   {"bufferViews[3].extensions", "filters apply only to ATTRIBUTES"});
}

TEST(GltfMeshoptBadInput, AttributeStrideNotAMultipleOfFourIsRejected) {
    Gltf g = meshoptGltf(gridMesh(9)).compressed;
    meshoptExt(g, 0)["byteStride"] = 6; // the view's own must be a multiple of 4 (tinygltf)
    expectRejected(g, "meshopt_stride.gltf",
                   {kPositionView, "ATTRIBUTES needs a byteStride divisible by 4"});
}

TEST(GltfMeshoptBadInput, CompressedRangePastItsBufferIsRejected) {
    Gltf g = meshoptGltf(gridMesh(9)).compressed;
    meshoptExt(g, 0)["byteOffset"] = g.bin.size();
    expectRejected(g, "meshopt_range.gltf", {kPositionView, "past the end of buffers[0]"});
}

TEST(GltfMeshoptBadInput, UncompressedViewReadingTheFallbackBufferIsRejected) {
    Gltf g = meshoptGltf(gridMesh(9)).compressed;
    g.doc["bufferViews"][1].erase("extensions");
    expectRejected(g, "meshopt_fallback_read.gltf",
                   {"bufferViews[1]", "fallback buffer, but is not compressed itself"});
}

TEST(GltfMeshoptFallback, FallbackBufferFileIsNeverRead) {
    // Only compressed views use a fallback buffer, so its file need not be there.
    MeshoptGltf files = meshoptGltf(gridMesh(9));
    files.compressed.extraBuffers[0]["uri"] = "fallback_not_shipped.bin";
    const Loaded compressed = load(files.compressed.write("meshopt_fallback_uri.gltf"));
    const Loaded plain = load(files.plain.write("meshopt_fallback_uri_plain.gltf"));
    EXPECT_EQ(onlyMesh(compressed).positions, onlyMesh(plain).positions);
    EXPECT_EQ(onlyMesh(compressed).indices, onlyMesh(plain).indices);
}

// --- KHR_draco_mesh_compression ------------------------------------------------------------

class GltfDracoContainers : public ::testing::TestWithParam<Container> {};

/// For each vertex of `got`, the vertex of `want` nearest by position; fails past `tolerance`.
std::vector<std::uint32_t> nearestVertices(const Mesh& got, const Mesh& want, float tolerance) {
    std::vector<std::uint32_t> map(got.positions.size());
    for (std::size_t i = 0; i < got.positions.size(); ++i) {
        float best = 1e30f;
        for (std::size_t j = 0; j < want.positions.size(); ++j) {
            const glm::vec3 d = glm::abs(got.positions[i] - want.positions[j]);
            const float worst = std::max({d.x, d.y, d.z});
            if (worst < best) {
                best = worst;
                map[i] = static_cast<std::uint32_t>(j);
            }
        }
        EXPECT_LE(best, tolerance) << "vertex " << i;
    }
    return map;
}

// Draco reorders the points, so the decoded mesh is matched to the original vertex by vertex
// (the grid's spacing is far above the quantisation step) and then compared triangle by
// triangle: every attribute within its quantisation step, the same triangles, same winding.
TEST_P(GltfDracoContainers, LoadsAsTheUncompressedMeshWithinTheQuantisationStep) {
    const GridMesh grid = gridMesh(9);
    const DracoGltf draco = dracoGltf(grid);
    const std::string name = "draco" + suffix(GetParam());
    const Loaded compressed = load(draco.gltf.write(name, GetParam()));
    // One plain file per parameter: ctest runs the two instances at once, in the same folder.
    const Loaded plain = load(plainGltf(grid).write(
        "draco_plain_" + std::to_string(static_cast<int>(GetParam())) + ".gltf"));
    const Mesh& a = onlyMesh(compressed);
    const Mesh& b = onlyMesh(plain);
    EXPECT_TRUE(compressed.warnings.empty()) << compressed.warnings.front();
    ASSERT_EQ(a.positions.size(), draco.points);
    ASSERT_EQ(a.indices.size(), b.indices.size());

    const std::vector<std::uint32_t> map = nearestVertices(a, b, draco.positionStep);
    EXPECT_EQ(triangles(a.indices, map), triangles(b.indices));
    for (std::size_t i = 0; i < map.size(); ++i) {
        // Octahedral quantisation: a step in each of the two octahedral coordinates moves each
        // component of the unit vector by up to about two steps.
        const glm::vec3 dn = glm::abs(a.normals[i] - b.normals[map[i]]);
        EXPECT_LE(std::max({dn.x, dn.y, dn.z}), 2 * draco.normalStep) << "normal " << i;
        const glm::vec2 dt = glm::abs(a.texcoords[i] - b.texcoords[map[i]]);
        EXPECT_LE(std::max(dt.x, dt.y), draco.texcoordStep) << "texcoord " << i;
    }
}

INSTANTIATE_TEST_SUITE_P(Containers, GltfDracoContainers,
                         ::testing::Values(Container::DataUri, Container::Glb));

constexpr const char* kDracoExt = "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression";

json& dracoExt(Gltf& g) {
    return g.prim()["extensions"]["KHR_draco_mesh_compression"];
}

TEST(GltfDracoBadInput, TruncatedDracoDataIsRejected) {
    DracoGltf d = dracoGltf(gridMesh(9));
    const auto length = d.gltf.doc["bufferViews"][0]["byteLength"].get<std::size_t>();
    d.gltf.doc["bufferViews"][0]["byteLength"] = length / 2;
    expectRejected(d.gltf, "draco_truncated.gltf", {kDracoExt, "does not decode"});
}

TEST(GltfDracoBadInput, GarbageInsteadOfDracoDataIsRejected) {
    DracoGltf d = dracoGltf(gridMesh(9));
    std::fill(d.gltf.bin.begin(), d.gltf.bin.end(), std::uint8_t{0x5A});
    expectRejected(d.gltf, "draco_garbage.glb",
                   {kDracoExt, "bufferViews[0] is not a Draco triangle mesh"}, Container::Glb);
}

TEST(GltfDracoBadInput, CorruptedDracoPayloadIsRejectedOrLoadsFinite) {
    // Flipping bytes after the header either fails decoding (one clear message) or decodes to
    // some other mesh, which must then pass the ordinary checks; it must never crash.
    for (std::size_t at = 16; at < 200; at += 7) {
        DracoGltf d = dracoGltf(gridMesh(9));
        d.gltf.bin[at] ^= 0xFF;
        const auto path = d.gltf.write("draco_flipped.gltf");
        try {
            const Loaded l = load(path);
            for (const glm::vec3& p : onlyMesh(l).positions)
                EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
        } catch (const SceneError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("draco_flipped.gltf: ", 0), 0u) << e.what();
        }
    }
}

TEST(GltfDracoBadInput, AccessorCountDisagreeingWithDecodedPointsIsRejected) {
    DracoGltf d = dracoGltf(gridMesh(9));
    d.gltf.accessorAt(0)["count"] = d.points + 1;
    expectRejected(d.gltf, "draco_count.gltf",
                   {"accessors[0]", cat("POSITION: count ", d.points + 1,
                                        " but the Draco data decodes ", d.points, " points")});
}

TEST(GltfDracoBadInput, IndicesCountDisagreeingWithDecodedFacesIsRejected) {
    DracoGltf d = dracoGltf(gridMesh(9));
    d.gltf.accessorAt(3)["count"] = 3;
    expectRejected(d.gltf, "draco_index_count.gltf",
                   {"accessors[3]",
                    cat("indices: count 3 but the Draco data decodes ", d.faces, " triangles")});
}

TEST(GltfDracoBadInput, UnknownAttributeIdIsRejected) {
    DracoGltf d = dracoGltf(gridMesh(9));
    dracoExt(d.gltf)["attributes"]["NORMAL"] = 99;
    expectRejected(d.gltf, "draco_attribute_id.gltf",
                   {cat(kDracoExt, ".attributes.NORMAL"), "no attribute with id 99"});
}

TEST(GltfDracoBadInput, AttributeThePrimitiveLacksIsRejected) {
    DracoGltf d = dracoGltf(gridMesh(9));
    dracoExt(d.gltf)["attributes"]["TEXCOORD_1"] = d.texcoordId;
    expectRejected(d.gltf, "draco_missing_attribute.gltf",
                   {cat(kDracoExt, ".attributes.TEXCOORD_1"),
                    "names an attribute the primitive does not have"});
}

TEST(GltfDracoBadInput, ComponentCountDisagreeingWithTheAccessorIsRejected) {
    DracoGltf d = dracoGltf(gridMesh(9));
    d.gltf.accessorAt(2)["type"] = "VEC3"; // TEXCOORD_0 decodes 2 components
    expectRejected(d.gltf, "draco_components.gltf",
                   {"accessors[2]", "TEXCOORD_0: 3 components, but Draco attribute"});
}

TEST(GltfDracoBadInput, IndexTypeTooSmallForThePointsIsRejected) {
    DracoGltf d = dracoGltf(gridMesh(17)); // 289 points: more than UNSIGNED_BYTE can name
    d.gltf.accessorAt(3)["componentType"] = kU8;
    expectRejected(d.gltf, "draco_index_type.gltf",
                   {"accessors[3]", "componentType 5121 cannot hold the Draco point id"});
}

TEST(GltfDracoBadInput, InvalidDracoBufferViewIsRejected) {
    DracoGltf d = dracoGltf(gridMesh(9));
    dracoExt(d.gltf)["bufferView"] = 7;
    expectRejected(d.gltf, "draco_view.gltf", {kDracoExt, "bufferView 7 does not exist"});
}

TEST(GltfDracoBadInput, NonFinitePositionIsRejectedAsInAnyMesh) {
    GridMesh grid = gridMesh(9);
    grid.positions[40].z = std::numeric_limits<float>::infinity();
    const DracoGltf d = dracoGltf(grid, /*positionBits=*/0); // unquantised: inf survives
    expectRejected(d.gltf, "draco_inf_position.gltf",
                   {"accessors[0]", "attributes.POSITION: vertex", "is not finite"});
}

TEST(GltfDracoBadInput, StripModeIsRejected) {
    DracoGltf d = dracoGltf(gridMesh(9));
    d.gltf.prim()["mode"] = kStrip;
    expectRejected(d.gltf, "draco_strip.gltf",
                   {"meshes[0].primitives[0]", "mode 5 with KHR_draco_mesh_compression"});
}

// A real file: assimp-testmodels' Draco version of 2CylinderEngine against its uncompressed GLB.
// Draco's encoder drops faces that quantisation makes degenerate (the loader drops the rest), so
// the triangle counts may differ by a few; the bounds agree within the quantisation.
TEST(GltfDracoRealWorld, AssimpCylinderEngineLoadsLikeItsUncompressedGlb) {
    const std::filesystem::path models = "/usr/share/assimp/models/glTF2";
    if (!std::filesystem::is_directory(models / "draco"))
        GTEST_SKIP() << models << " absent (install assimp-testmodels)";
    const Loaded draco = load(models / "draco/2CylinderEngine.gltf");
    const Loaded plain = load(models / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    ASSERT_EQ(draco.scene.meshes.size(), plain.scene.meshes.size());
    EXPECT_EQ(draco.scene.instances.size(), plain.scene.instances.size());
    const double a = static_cast<double>(draco.scene.triangleCount());
    const double b = static_cast<double>(plain.scene.triangleCount());
    EXPECT_LE(std::abs(a - b), 1e-3 * b) << a << " vs " << b;
    const glm::vec3 extent = plain.scene.bounds.max - plain.scene.bounds.min;
    const float tolerance = 1e-3f * std::max({extent.x, extent.y, extent.z});
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(draco.scene.bounds.min[c], plain.scene.bounds.min[c], tolerance);
        EXPECT_NEAR(draco.scene.bounds.max[c], plain.scene.bounds.max[c], tolerance);
    }
}

} // namespace
} // namespace fl::test
