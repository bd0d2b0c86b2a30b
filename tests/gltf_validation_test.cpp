// glTF loader validation: one test per rule, each writes a minimal malformed file and expects a
// SceneError naming the file, the element and the problem.

#include <scene/GltfLoader.h>

#include "GltfBuilder.h"
#include "TestPaths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

namespace fl::test {
namespace {

namespace fs = std::filesystem;

// --- validation: each rule rejects with file, element and problem ----------------------------

TEST(GltfLoaderValidation, IndexPastVertexCount) {
    Gltf g = triangle();
    g.prim()["indices"] = g.indices(std::vector<std::uint16_t>{0, 1, 812}, kU16);
    expectRejected(g, "index_past_vertex_count.gltf",
                   {"meshes[0].primitives[0]", "index 812 past vertex count 3"});
}

TEST(GltfLoaderValidation, NodeCycle) {
    Gltf g = triangle();
    // As in assimp's RecursiveNodes.gltf: a child lists its parent as its child.
    g.node(0)["children"] = {1};
    g.push("nodes", {{"children", {0}}});
    expectRejected(g, "node_cycle.gltf",
                   {"nodes[0]: node cycle: nodes[0] -> nodes[1] -> nodes[0]"});
}

TEST(GltfLoaderValidation, NodeCycleOutsideTheScene) {
    Gltf g = triangle();
    g.push("nodes", {{"children", {2}}});
    g.push("nodes", {{"children", {1}}});
    expectRejected(g, "node_cycle_unreachable.gltf", {"node cycle"});
}

TEST(GltfLoaderValidation, NodeIsItsOwnChild) {
    Gltf g = triangle();
    g.node(0)["children"] = {0};
    expectRejected(g, "node_own_child.gltf", {"nodes[0]", "node cycle"});
}

TEST(GltfLoaderValidation, NodeWithTwoParents) {
    Gltf g = triangle();
    g.push("nodes", {{"children", {3}}});
    g.push("nodes", {{"children", {3}}});
    g.push("nodes", {{"mesh", 0}});
    g.doc["scenes"][0]["nodes"] = {0, 1, 2};
    expectRejected(g, "node_two_parents.gltf", {"nodes[3]", "two parents", "nodes[1]", "nodes[2]"});
}

TEST(GltfLoaderValidation, SceneListsNonRootNode) {
    Gltf g = triangle();
    g.push("nodes", {{"children", {0}}});
    g.doc["scenes"][0]["nodes"] = {1, 0};
    expectRejected(g, "non_root_scene_node.gltf", {"scenes[0].nodes[1]", "not a root node"});
}

TEST(GltfLoaderValidation, NaNPosition) {
    Gltf g = triangle();
    g.prim()["attributes"]["POSITION"] =
        g.vec3({{0, 0, 0}, {std::numeric_limits<float>::quiet_NaN(), 0, 0}, {0, 1, 0}});
    expectRejected(g, "nan_position.gltf", {"accessors[3]", "POSITION", "vertex 1 is not finite"});
}

TEST(GltfLoaderValidation, InfinitePosition) {
    Gltf g = triangle();
    g.prim()["attributes"]["POSITION"] =
        g.vec3({{0, 0, 0}, {1, 0, 0}, {0, std::numeric_limits<float>::infinity(), 0}});
    expectRejected(g, "inf_position.gltf", {"accessors[3]", "vertex 2 is not finite"});
}

// Bounds with no size (issue 41, bad input): nothing to place a light, a camera or a ground by.
// Each is one message naming the file, never a ground at NaN.
TEST(GltfLoaderValidation, EveryTriangleOfZeroArea) {
    const std::vector<std::string> zeroArea = {"scene", "every triangle has zero area"};
    Gltf collinear = triangle();
    collinear.prim()["attributes"]["POSITION"] = collinear.vec3({{0, 0, 0}, {1, 0, 0}, {3, 0, 0}});
    expectRejected(collinear, "zero_area_collinear.gltf", zeroArea);
    Gltf equal = triangle();
    equal.prim()["attributes"]["POSITION"] = equal.vec3(std::vector<glm::vec3>(3, {1, 2, 3}));
    expectRejected(equal, "zero_area_equal.gltf", zeroArea);
    Gltf scaled = triangle();
    scaled.node(0)["scale"] = {0.0, 0.0, 0.0};
    expectRejected(scaled, "zero_area_scale0.gltf", zeroArea);
    scaled.node(0)["scale"] = {1.0, 0.0, 1.0}; // the triangle is in the xy plane: a line
    expectRejected(scaled, "zero_area_scale_y0.gltf", zeroArea);
    scaled.node(0)["scale"] = {1e-30, 1e-30, 1e-30}; // an area below float's range
    expectRejected(scaled, "zero_area_scale_tiny.gltf", zeroArea);
    // One point: its triangle is dropped, or it is a POINTS primitive; the scene has none.
    Gltf point = triangle();
    point.prim()["indices"] = point.indices(std::vector<std::uint16_t>{1, 1, 1}, kU16);
    expectRejected(point, "one_point.gltf", {"scene", "no triangle primitives"});
    point.prim().erase("indices");
    point.prim()["mode"] = 0;
    expectRejected(point, "points.gltf", {"scene", "no triangle primitives"});
    // A zero-scaled node beside a real one is only a point in the bounds: loaded, finite.
    Gltf two = triangle();
    two.node(0)["scale"] = {0.0, 0.0, 0.0};
    two.push("nodes", {{"mesh", 0}, {"translation", {0.0, -5.0, 0.0}}});
    two.doc["scenes"][0]["nodes"] = {0, 1};
    const Scene s = load(two.write("zero_scale_beside_one.gltf")).scene;
    EXPECT_EQ(s.bounds.min, glm::vec3(0, -5, 0));
    EXPECT_EQ(s.bounds.max, glm::vec3(1, 0, 0));
}

TEST(GltfLoaderValidation, AccessorPastBufferView) {
    Gltf g = triangle();
    g.accessorAt(0)["count"] = 4; // 4 * 12 bytes > the view's 36
    expectRejected(g, "accessor_past_view.gltf",
                   {"accessors[0]", "past the end of bufferViews[0]", "byteLength 36"});
}

TEST(GltfLoaderValidation, AccessorByteOffsetPastBufferView) {
    Gltf g = triangle();
    g.accessorAt(0)["byteOffset"] = 4;
    expectRejected(g, "accessor_offset_past_view.gltf", {"accessors[0]", "byteOffset 4", "past"});
}

TEST(GltfLoaderValidation, StridedAccessorPastBufferView) {
    // 3 VEC3 floats with stride 16 need 16 * 2 + 12 = 44 bytes; the view has 36.
    Gltf g = triangle();
    g.doc["bufferViews"][0]["byteStride"] = 16;
    expectRejected(g, "stride_past_view.gltf", {"accessors[0]", "stride 16", "= 44 bytes", "past"});
}

TEST(GltfLoaderValidation, StrideSmallerThanElement) {
    Gltf g = triangle();
    g.doc["bufferViews"][0]["byteStride"] = 8;
    expectRejected(g, "stride_too_small.gltf", {"bufferViews[0]", "byteStride 8"});
}

TEST(GltfLoaderValidation, BufferViewPastBuffer) {
    Gltf g = triangle();
    g.doc["bufferViews"][2]["byteLength"] = 4096;
    expectRejected(g, "view_past_buffer.gltf", {"bufferViews[2]", "past the end of buffers[0]"});
}

TEST(GltfLoaderValidation, PositionNotVec3) {
    Gltf g = triangle();
    g.accessorAt(0)["type"] = "VEC2";
    expectRejected(g, "position_vec2.gltf",
                   {"accessors[0]", "POSITION needs VEC3 FLOAT, got VEC2 FLOAT"});
}

TEST(GltfLoaderValidation, PositionNotFloat) {
    Gltf g = triangle();
    g.accessorAt(0)["componentType"] = kU16;
    expectRejected(g, "position_u16.gltf",
                   {"accessors[0]", "POSITION needs VEC3 FLOAT, got VEC3 UNSIGNED_SHORT"});
}

TEST(GltfLoaderValidation, NormalNotVec3) {
    Gltf g = triangle();
    g.accessorAt(1)["type"] = "VEC4";
    g.accessorAt(1)["count"] = 2;
    expectRejected(g, "normal_vec4.gltf", {"accessors[1]", "NORMAL needs VEC3 FLOAT"});
}

TEST(GltfLoaderValidation, FloatIndices) {
    Gltf g = triangle();
    g.prim()["indices"] = g.accessor(g.view(std::vector<float>{0, 1, 2}), kFloat, "SCALAR", 3);
    expectRejected(
        g, "float_indices.gltf",
        {"accessors[3]", "indices needs SCALAR UNSIGNED_BYTE/UNSIGNED_SHORT/UNSIGNED_INT"});
}

TEST(GltfLoaderValidation, UnnormalizedByteTexcoords) {
    Gltf g = triangle();
    g.prim()["attributes"]["TEXCOORD_0"] =
        g.accessor(g.view(std::vector<std::uint8_t>{0, 0, 255, 0, 0, 255}), kU8, "VEC2", 3);
    expectRejected(g, "texcoord_u8_unnormalized.gltf", {"accessors[3]", "must be normalized"});
}

TEST(GltfLoaderValidation, AttributeCountMismatch) {
    Gltf g = triangle();
    g.prim()["attributes"]["NORMAL"] = g.vec3({{0, 0, 1}, {0, 0, 1}});
    expectRejected(g, "normal_count_mismatch.gltf",
                   {"meshes[0].primitives[0]", "NORMAL has 2 elements but POSITION has 3"});
}

TEST(GltfLoaderValidation, SparseIndexPastCount) {
    Gltf g = triangle();
    const int idx = g.view(std::vector<std::uint8_t>{7});
    const int val = g.view(std::vector<glm::vec3>{{5, 5, 5}});
    g.accessorAt(0)["sparse"] = {{"count", 1},
                                 {"indices", {{"bufferView", idx}, {"componentType", kU8}}},
                                 {"values", {{"bufferView", val}}}};
    expectRejected(g, "sparse_index_past_count.gltf",
                   {"accessors[0].sparse.indices", "index 7 past accessor count 3"});
}

TEST(GltfLoaderValidation, SparseCountLargerThanAccessor) {
    Gltf g = triangle();
    const int idx = g.view(std::vector<std::uint8_t>{0, 1, 2, 2});
    const int val = g.view(std::vector<glm::vec3>(4));
    g.accessorAt(0)["sparse"] = {{"count", 4},
                                 {"indices", {{"bufferView", idx}, {"componentType", kU8}}},
                                 {"values", {{"bufferView", val}}}};
    expectRejected(g, "sparse_count_too_large.gltf", {"accessors[0].sparse", "count 4"});
}

TEST(GltfLoaderValidation, AbsurdAccessorCount) {
    Gltf g = triangle();
    g.accessorAt(0).erase("bufferView"); // all zeros: no byte range would catch it
    g.accessorAt(0)["count"] = 1u << 31;
    expectRejected(g, "absurd_count.gltf", {"accessors[0]", "absurd count 2147483648"});
}

TEST(GltfLoaderValidation, MissingImageFile) {
    Gltf g = triangle();
    g.texturedMaterial(g.texture({{"uri", "no_such_texture.png"}}));
    expectRejected(g, "missing_image.gltf", {"images[0]", "'no_such_texture.png': does not exist"});
}

TEST(GltfLoaderValidation, ImageBufferViewPastBuffer) {
    Gltf g = triangle();
    g.push("bufferViews", {{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 100000}});
    g.texturedMaterial(g.texture({{"bufferView", 3}, {"mimeType", "image/png"}}));
    expectRejected(g, "image_view_past_buffer.gltf",
                   {"bufferViews[3]", "past the end of buffers[0]"});
}

// Invalid indices into every array the loader follows.
TEST(GltfLoaderValidation, InvalidMeshIndex) {
    Gltf g = triangle();
    g.node(0)["mesh"] = 5;
    expectRejected(g, "bad_mesh_index.gltf", {"nodes[0]", "mesh 5 does not exist (1 in meshes)"});
}

TEST(GltfLoaderValidation, InvalidMaterialIndex) {
    Gltf g = triangle();
    g.prim()["material"] = 3;
    expectRejected(g, "bad_material_index.gltf",
                   {"meshes[0].primitives[0]", "material 3 does not exist"});
}

TEST(GltfLoaderValidation, InvalidImageIndex) {
    Gltf g = triangle();
    g.push("textures", {{"source", 2}});
    g.texturedMaterial(0);
    expectRejected(g, "bad_image_index.gltf", {"textures[0]", "image 2 does not exist"});
}

TEST(GltfLoaderValidation, InvalidAccessorIndex) {
    Gltf g = triangle();
    g.prim()["attributes"]["POSITION"] = 9;
    expectRejected(g, "bad_accessor_index.gltf",
                   {"meshes[0].primitives[0].attributes.POSITION", "accessor 9 does not exist"});
}

TEST(GltfLoaderValidation, InvalidBufferViewIndex) {
    Gltf g = triangle();
    g.accessorAt(0)["bufferView"] = 7;
    expectRejected(g, "bad_view_index.gltf", {"accessors[0]", "bufferView 7 does not exist"});
}

TEST(GltfLoaderValidation, InvalidBufferIndex) {
    Gltf g = triangle();
    g.doc["bufferViews"][0]["buffer"] = 3;
    expectRejected(g, "bad_buffer_index.gltf", {"bufferViews[0]", "buffer 3 does not exist"});
}

TEST(GltfLoaderValidation, InvalidCameraIndex) {
    Gltf g = triangle();
    g.node(0)["camera"] = 2;
    expectRejected(g, "bad_camera_index.gltf", {"nodes[0]", "camera 2 does not exist"});
}

TEST(GltfLoaderValidation, InvalidLightIndex) {
    Gltf g = triangle();
    g.node(0)["extensions"] = {{"KHR_lights_punctual", {{"light", 4}}}};
    expectRejected(g, "bad_light_index.gltf",
                   {"nodes[0].extensions.KHR_lights_punctual", "light 4 does not exist"});
}

TEST(GltfLoaderValidation, InvalidChildIndex) {
    Gltf g = triangle();
    g.node(0)["children"] = {9};
    expectRejected(g, "bad_child_index.gltf", {"nodes[0].children[0]", "node 9 does not exist"});
}

TEST(GltfLoaderValidation, InvalidSceneNodeIndex) {
    Gltf g = triangle();
    g.doc["scenes"][0]["nodes"] = {4};
    expectRejected(g, "bad_scene_node_index.gltf", {"scenes[0].nodes[0]", "node 4 does not exist"});
}

TEST(GltfLoaderValidation, InvalidDefaultScene) {
    Gltf g = triangle();
    g.doc["scene"] = 5;
    expectRejected(g, "bad_default_scene.gltf", {"scene: scene 5 does not exist"});
}

TEST(GltfLoaderValidation, MatrixOfWrongSize) {
    Gltf g = triangle();
    g.node(0)["matrix"] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    expectRejected(g, "matrix_9_values.gltf", {"nodes[0]", "matrix has 9 values (expected 16)"});
}

TEST(GltfLoaderValidation, JsonNumberOverflowPassedOn) {
    // JSON has no infinity; 1e400 is tinygltf's (nlohmann's) parse error, passed on.
    Gltf g = triangle();
    g.node(0)["translation"] = {0, 12345.5, 0};
    const fs::path path = g.write("translation_1e400.gltf");
    replaceInFile(path, "12345.5", "1e400");
    const std::string message = errorOf(path);
    EXPECT_EQ(message.rfind("translation_1e400.gltf: ", 0), 0u) << message;
    EXPECT_NE(message.find("1e400"), std::string::npos) << message;
}

TEST(GltfLoaderValidation, TransformOverflowsFloat) {
    Gltf g = triangle();
    g.node(0)["translation"] = {0, 1e300, 0}; // a finite double, infinite as float
    expectRejected(g, "translation_1e300.gltf", {"nodes[0]", "world transform is not finite"});
}

// Bug (fuzz_gltf): positions finite as floats but far beyond the world's limit (1e35) loaded,
// and the scene's radius, and with it a camera's far plane, came out infinite.
TEST(GltfLoaderValidation, PositionsBeyondTheWorldLimit) {
    Gltf g = triangle();
    g.node(0)["scale"] = {1e35, 1, 1};
    expectRejected(g, "scale_1e35.gltf",
                   {"scene: world-space bounds are not finite or reach beyond 1e+15"});
}

TEST(GltfLoaderValidation, InvalidPrimitiveMode) {
    Gltf g = triangle();
    g.prim()["mode"] = 9;
    expectRejected(g, "bad_mode.gltf", {"meshes[0].primitives[0]", "invalid mode 9"});
}

TEST(GltfLoaderValidation, DracoExtensionOverDataThatIsNotDraco) {
    // Draco is decoded (gltf_compression_test.cpp); here its bufferView holds the positions.
    Gltf g = triangle();
    g.accessorAt(0).erase("bufferView");
    g.prim()["extensions"] = {
        {"KHR_draco_mesh_compression", {{"bufferView", 0}, {"attributes", {{"POSITION", 0}}}}}};
    expectRejected(g, "draco_not_draco.gltf",
                   {"meshes[0].primitives[0].extensions.KHR_draco_mesh_compression",
                    "bufferViews[0] is not a Draco triangle mesh"});
}

// --- messages for files that are not loadable glTF 2.0 ------------------------------------
// Issue 42, item 5: what the loader says about a file that is not a loadable glTF 2.0 file, in
// a user's words: "FILE: not a glTF file (it starts like a PNG image)", "FILE: glTF 1.0 is not
// supported (asset.version 1.0); glTF 2.0 is needed", "FILE: truncated: ..." - never the JSON
// parser's or tinygltf's text, and no raw bytes. Repeated warnings come out as one line per kind
// and file. A .gltf's external buffer is read where its relative URI points, '..' included (the
// rule --scene's help states).

fs::path messageFile(const std::string& name, const std::string& bytes) {
    const fs::path p = outputDir("gltf_messages") / name;
    fs::create_directories(p.parent_path());
    writeBytes(p, bytes.data(), bytes.size());
    return p;
}

// The message names the file first, and carries neither library words nor unprintable bytes.
void expectMessage(const fs::path& path, const std::string& expected) {
    const std::string e = errorOf(path);
    EXPECT_EQ(e, path.filename().string() + ": " + expected);
    for (const char* library : {"json.exception", "parse_error", "tinygltf", "last read"})
        EXPECT_EQ(e.find(library), std::string::npos) << e;
    for (char c : e) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << e;
}

TEST(GltfMessages, OtherFormatsAreNamed) {
    expectMessage(messageFile("photo.glb", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16)),
                  "not a glTF file (it starts like a PNG image)");
    expectMessage(messageFile("photo.gltf", "\xFF\xD8\xFF\xE0 JFIF"),
                  "not a glTF file (it starts like a JPEG image)");
    expectMessage(messageFile("scene.glb", std::string("PK\x03\x04\x14\0", 6)),
                  "not a glTF file (it starts like a ZIP archive (unpack it first))");
    expectMessage(messageFile("mesh.gltf", "v 0 0 0\nv 1 0 0\nf 1 2 3\n"),
                  "not a glTF file (it is text that does not start with a JSON object '{'; an "
                  "OBJ mesh? convert it to glTF 2.0 first, e.g. assimp export IN.obj OUT.glb)");
}

TEST(GltfMessages, EmptyAndTruncatedFiles) {
    expectMessage(messageFile("zero.glb", ""),
                  "empty file (0 bytes); a glTF 2.0 file (.gltf or .glb) is needed");
    const fs::path whole = triangle().write("whole.glb", Container::Glb);
    std::ifstream in(whole, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    expectMessage(messageFile("cut.glb", bytes.substr(0, 60)), "truncated: its .glb header says " +
                                                                   std::to_string(bytes.size()) +
                                                                   " bytes, the file has 60");
    expectMessage(messageFile("cut.gltf", R"({"asset": {"version": "2.0"}, "meshes": [)"),
                  "truncated: the JSON ends (after 41 bytes) before it is complete");
    expectMessage(
        messageFile("bad.gltf", "{\"asset\": {\"version\": \"2.0\"},\n  \"meshes\": [}]}"),
        "not valid JSON at line 2, column 14 (a glTF file is JSON)");
}

TEST(GltfMessages, GltfOneIsNamed) {
    expectMessage(messageFile("v1.gltf", R"({"asset": {"version": "1.0"}, "meshes": {"m": {}}})"),
                  "glTF 1.0 is not supported (asset.version 1.0); glTF 2.0 is needed");
    // 1.0 files often have no asset at all: their objects by name tell them.
    expectMessage(messageFile("v1-no-asset.gltf", R"({"meshes": {"box": {"primitives": []}}})"),
                  "glTF 1.0 is not supported (its \"meshes\" are an object by name, as in glTF "
                  "1.0); glTF 2.0 is needed");
    Gltf g = triangle();
    g.doc["asset"]["version"] = "3.0";
    expectMessage(g.write("v3.gltf"),
                  "glTF 3.0 is not supported (asset.version 3.0); glTF 2.0 is needed");
    const std::string binary = "glTF" + std::string("\x01\0\0\0\x0c\0\0\0", 8);
    expectMessage(messageFile("v1.glb", binary),
                  "glTF binary version 1 is not supported (its header says so); glTF 2.0 is "
                  "needed");
}

// 25 lines for one model, one per primitive, on every run: now one line per kind of warning.
TEST(GltfMessages, RepeatedWarningsAreSummedPerFile) {
    Gltf g = triangle();
    // Each primitive: the triangle plus a degenerate one (a repeated index).
    const int degenerate = g.indices(std::vector<std::uint16_t>{0, 1, 2, 0, 0, 1}, kU16);
    json prim = g.prim();
    prim["indices"] = degenerate;
    for (int p = 0; p < 4; ++p) g.doc["meshes"][0]["primitives"][p] = prim;
    const Loaded l = load(g.write("degenerate.gltf"));
    ASSERT_EQ(l.warnings.size(), 1u);
    EXPECT_EQ(l.warnings[0],
              "degenerate.gltf: 4 degenerate triangle(s) dropped in 4 elements "
              "(meshes[0].primitives[0], meshes[0].primitives[1], meshes[0].primitives[2], "
              "and 1 more)");
    // A warning alone keeps its element.
    Gltf one = triangle();
    one.prim()["indices"] = one.indices(std::vector<std::uint16_t>{0, 1, 2, 0, 0, 1}, kU16);
    const Loaded single = load(one.write("one-degenerate.gltf"));
    ASSERT_EQ(single.warnings.size(), 1u);
    EXPECT_EQ(single.warnings[0],
              "one-degenerate.gltf: meshes[0].primitives[0]: 1 degenerate triangle(s) dropped");
}

// The rule for external files: a relative URI resolves from the .gltf's folder, '..' included,
// as the glTF specification resolves it (sample packs keep shared buffers beside their models).
TEST(GltfMessages, ABufferUriOutsideTheFolderIsReadWhereItPoints) {
    const fs::path out = triangle().write("shared.gltf", Container::BinFile);
    const fs::path sub = out.parent_path() / "models";
    fs::create_directories(sub);
    const fs::path inner = sub / "shared.gltf";
    fs::copy_file(out, inner, fs::copy_options::overwrite_existing);
    replaceInFile(inner, "\"shared.bin\"", "\"../shared.bin\"");
    EXPECT_EQ(load(inner).scene.triangleCount(), 1u);
    // Missing there: the message names the URI as written and the file.
    replaceInFile(inner, "\"../shared.bin\"", "\"../missing.bin\"");
    const std::string e = errorOf(inner);
    EXPECT_NE(e.find("missing.bin"), std::string::npos) << e;
    EXPECT_EQ(e.rfind("shared.gltf: ", 0), 0u) << e;
}

} // namespace
} // namespace fl::test
