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
    glb.insert(glb.end(), {'g', 'l', 'T', 'F'});
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
