#include "GltfBuilder.h"
#include "TestPaths.h"

#include <fstream>
#include <iterator>

namespace fl::test {

namespace fs = std::filesystem;

std::string base64(const std::vector<std::uint8_t>& in) {
    static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < in.size(); i += 3) {
        const std::uint32_t n = (in[i] << 16) | (i + 1 < in.size() ? in[i + 1] << 8 : 0) |
                                (i + 2 < in.size() ? in[i + 2] : 0);
        out += abc[(n >> 18) & 63];
        out += abc[(n >> 12) & 63];
        out += i + 1 < in.size() ? abc[(n >> 6) & 63] : '=';
        out += i + 2 < in.size() ? abc[n & 63] : '=';
    }
    return out;
}

std::size_t Gltf::append(const void* data, std::size_t size) {
    while (bin.size() % 4 != 0) bin.push_back(0);
    const std::size_t offset = bin.size();
    const auto* p = static_cast<const std::uint8_t*>(data);
    bin.insert(bin.end(), p, p + size);
    return offset;
}

int Gltf::view(const void* data, std::size_t size, int stride) {
    json v = {{"buffer", 0}, {"byteOffset", append(data, size)}, {"byteLength", size}};
    if (stride != 0) v["byteStride"] = stride;
    return push("bufferViews", v);
}

void writeBytes(const fs::path& path, const void* data, std::size_t size) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
}

fs::path Gltf::write(const std::string& name, Container container) const {
    const fs::path path = outputDir("gltf_loader") / name;
    json d = doc;
    if (!bin.empty() && !d.contains("buffers")) {
        json buffer = {{"byteLength", bin.size()}};
        if (container == Container::DataUri)
            buffer["uri"] = "data:application/octet-stream;base64," + base64(bin);
        if (container == Container::BinFile) {
            const fs::path binPath = fs::path(path).replace_extension(".bin");
            writeBytes(binPath, bin.data(), bin.size());
            buffer["uri"] = binPath.filename().string();
        }
        d["buffers"] = json::array({buffer});
        for (const json& extra : extraBuffers) d["buffers"].push_back(extra);
    }
    std::string text = d.dump();
    if (container != Container::Glb) {
        writeBytes(path, text.data(), text.size());
        return path;
    }
    while (text.size() % 4 != 0) text += ' ';
    std::vector<std::uint8_t> chunk = bin;
    while (chunk.size() % 4 != 0) chunk.push_back(0);
    std::vector<std::uint8_t> glb;
    auto u32 = [&glb](std::uint32_t v) {
        for (int i = 0; i < 4; ++i) glb.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    };
    const std::size_t total = 12 + 8 + text.size() + (chunk.empty() ? 0 : 8 + chunk.size());
    // "glTF" as a number: GCC 12 reports a false -Wstringop-overflow on inserting the four
    // characters into the empty vector.
    u32(0x46546C67);
    u32(2);
    u32(static_cast<std::uint32_t>(total));
    u32(static_cast<std::uint32_t>(text.size()));
    u32(0x4E4F534A); // JSON
    glb.insert(glb.end(), text.begin(), text.end());
    if (!chunk.empty()) {
        u32(static_cast<std::uint32_t>(chunk.size()));
        u32(0x004E4942); // BIN
        glb.insert(glb.end(), chunk.begin(), chunk.end());
    }
    writeBytes(path, glb.data(), glb.size());
    return path;
}

void replaceInFile(const fs::path& path, const std::string& from, const std::string& to) {
    std::ifstream in(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    writeBytes(path, text.data(), text.size());
}

Gltf triangle() {
    Gltf g;
    const int pos = g.vec3(kTriangle);
    const int nrm = g.vec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    const int idx = g.indices(std::vector<std::uint16_t>{0, 1, 2}, kU16);
    g.push("meshes",
           {{"primitives", json::array({{{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}}},
                                         {"indices", idx}}})}});
    g.push("nodes", {{"mesh", 0}, {"name", "tri"}});
    g.doc["scenes"] = json::array({{{"nodes", {0}}}});
    g.doc["scene"] = 0;
    return g;
}

Gltf skinnedBar(bool withNormals) {
    Gltf g;
    const int pos = g.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 2, 0}, {1, 2, 0}});
    const int joints = g.ints(std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0,
                                                        0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0},
                              kU8, "VEC4");
    const int weights = g.floats(
        {1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 0.5f, 0.5f, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0},
        "VEC4");
    const int idx = g.indices(std::vector<std::uint16_t>{0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4}, kU16);
    json attributes = {{"POSITION", pos}, {"JOINTS_0", joints}, {"WEIGHTS_0", weights}};
    if (withNormals) attributes["NORMAL"] = g.vec3(std::vector<glm::vec3>(6, glm::vec3(0, 0, 1)));
    g.push("meshes",
           {{"primitives", json::array({{{"attributes", attributes}, {"indices", idx}}})}});
    g.push("nodes", {{"mesh", 0}, {"skin", 0}, {"name", "bar"}});
    g.push("nodes", {{"name", "root"}, {"children", {2}}});
    g.push("nodes", {{"name", "tip"}, {"translation", {0, 1, 0}}});
    // Root: identity; tip: translate(0, -1, 0) (column-major, translation in the last column).
    const std::vector<float> ibm = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0,  0, 1,
                                    1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1};
    g.push("skins", {{"joints", {1, 2}}, {"inverseBindMatrices", g.floats(ibm, "MAT4")}});

    const int times = g.floats({0, 1, 2}, "SCALAR");
    const int translations = g.floats({0, 0, 0, 1, 0, 0, 2, 0, 0}, "VEC3");
    // The second key is not unit length: the loader normalises it.
    const int rotations = g.floats({0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 0, 1}, "VEC4");
    std::vector<float> cubic; // per key: in-tangent, value, out-tangent
    for (float s : {1.0f, 2.0f, 1.0f})
        for (float v : {0.0f, s, 0.0f}) cubic.insert(cubic.end(), {v, v, v});
    const int scales = g.floats(cubic, "VEC3");
    g.push(
        "animations",
        {{"name", "bend"},
         {"samplers",
          json::array({{{"input", times}, {"output", translations}},
                       {{"input", times}, {"output", rotations}, {"interpolation", "STEP"}},
                       {{"input", times}, {"output", scales}, {"interpolation", "CUBICSPLINE"}}})},
         {"channels",
          json::array({{{"sampler", 0}, {"target", {{"node", 1}, {"path", "translation"}}}},
                       {{"sampler", 1}, {"target", {{"node", 2}, {"path", "rotation"}}}},
                       {{"sampler", 2}, {"target", {{"node", 2}, {"path", "scale"}}}}})}});
    g.doc["scenes"] = json::array({{{"nodes", {0, 1}}}});
    g.doc["scene"] = 0;
    return g;
}

Gltf morphTriangle() {
    Gltf g = triangle();
    const int dp = g.vec3({{0, 0, 1}, {0, 0, 2}, {0, 0, 3}});
    const int dn = g.vec3({{0, 0.5f, 0}, {0, 0.5f, 0}, {0, 0.5f, 0}});
    g.prim()["targets"] = json::array({{{"POSITION", dp}, {"NORMAL", dn}}});
    g.doc["meshes"][0]["weights"] = {0.5};
    g.node(0)["weights"] = {0.25};
    return g;
}

void animate(Gltf& g, int input, int output, int node, const std::string& path,
             const std::string& interpolation) {
    g.push(
        "animations",
        {{"samplers",
          json::array({{{"input", input}, {"output", output}, {"interpolation", interpolation}}})},
         {"channels",
          json::array({{{"sampler", 0}, {"target", {{"node", node}, {"path", path}}}}})}});
}

Loaded load(const fs::path& path, LoadOptions options) {
    Loaded out;
    options.warn = [&out](const std::string& w) { out.warnings.push_back(w); };
    out.scene = loadGltf(path, options);
    return out;
}

std::string errorOf(const fs::path& path) {
    try {
        loadGltf(path);
    } catch (const SceneError& e) {
        return e.what();
    }
    ADD_FAILURE() << path << " loaded but should have been rejected";
    return {};
}

void expectRejected(const Gltf& g, const std::string& name, std::vector<std::string> parts,
                    Container container) {
    const std::string message = errorOf(g.write(name, container));
    EXPECT_EQ(message.rfind(name + ": ", 0), 0u) << message;
    for (const std::string& part : parts)
        EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

} // namespace fl::test
