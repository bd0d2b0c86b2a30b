#pragma once
// Minimal glTF files built in code for the loader tests: each test states the one defect or
// feature it is about instead of storing a fixture.

#include <scene/GltfLoader.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace fl::test {

using json = nlohmann::json;

inline constexpr int kI8 = 5120, kU8 = 5121, kI16 = 5122, kU16 = 5123, kU32 = 5125, kFloat = 5126;
inline constexpr int kLines = 1, kTriangles = 4, kStrip = 5, kFan = 6;

/// Standard base64 (with padding), for data: URIs.
std::string base64(const std::vector<std::uint8_t>& in);

enum class Container { DataUri, BinFile, Glb };

/// A glTF document under construction plus its single binary buffer.
struct Gltf {
    json doc = {{"asset", {{"version", "2.0"}}}};
    std::vector<std::uint8_t> bin;
    /// Buffers written after the one holding `bin` (indices 1, 2, ...), e.g. a meshopt fallback.
    std::vector<json> extraBuffers;

    /// Appends bytes to `bin` at the next 4-byte boundary; returns their offset.
    std::size_t append(const void* data, std::size_t size);
    /// Appends bytes (4-byte aligned) and a bufferView over them.
    int view(const void* data, std::size_t size, int stride = 0);
    template <class T>
    int view(const std::vector<T>& v, int stride = 0) {
        return view(v.data(), v.size() * sizeof(T), stride);
    }
    int accessor(int bufferView, int componentType, const std::string& type, std::size_t count) {
        return push("accessors", {{"bufferView", bufferView},
                                  {"componentType", componentType},
                                  {"type", type},
                                  {"count", count}});
    }
    int vec3(const std::vector<glm::vec3>& v) {
        return accessor(view(v), kFloat, "VEC3", v.size());
    }
    template <class T>
    int indices(const std::vector<T>& v, int componentType) {
        return accessor(view(v), componentType, "SCALAR", v.size());
    }
    /// FLOAT accessor of `type` (SCALAR, VEC3, VEC4, MAT4) over `v`, `type`'s width per element.
    int floats(const std::vector<float>& v, const std::string& type) {
        return accessor(view(v), kFloat, type, v.size() / components(type));
    }
    /// Integer accessor of `type` over `v` (element type matching `componentType`).
    template <class T>
    int ints(const std::vector<T>& v, int componentType, const std::string& type,
             bool normalized = false) {
        const int a = accessor(view(v), componentType, type, v.size() / components(type));
        if (normalized) accessorAt(a)["normalized"] = true;
        return a;
    }
    static std::size_t components(const std::string& type) {
        return type == "SCALAR" ? 1
               : type == "VEC2" ? 2
               : type == "VEC3" ? 3
               : type == "VEC4" ? 4
                                : 16;
    }
    int push(const std::string& array, json value) {
        doc[array].push_back(std::move(value));
        return static_cast<int>(doc[array].size()) - 1;
    }
    /// Adds `image` and a texture over it; returns the texture's index.
    int texture(json image) {
        const int source = push("images", std::move(image));
        return push("textures", {{"source", source}});
    }
    /// Gives primitive 0 a new material whose base colour is texture `index` (existing or not).
    void texturedMaterial(int index) {
        prim()["material"] = push(
            "materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", index}}}}}});
    }
    json& accessorAt(int i) { return doc["accessors"][static_cast<std::size_t>(i)]; }
    json& prim(int mesh = 0, int p = 0) {
        return doc["meshes"][static_cast<std::size_t>(mesh)]["primitives"]
                  [static_cast<std::size_t>(p)];
    }
    json& node(int i) { return doc["nodes"][static_cast<std::size_t>(i)]; }

    /// Writes the document to the test output folder as `name`; returns its path.
    std::filesystem::path write(const std::string& name,
                                Container container = Container::DataUri) const;
};

/// Writes `size` bytes to `path`, replacing it.
void writeBytes(const std::filesystem::path& path, const void* data, std::size_t size);

/// Replaces the first `from` in the file with `to` (failing the test if it is not there).
void replaceInFile(const std::filesystem::path& path, const std::string& from,
                   const std::string& to);

inline const std::vector<glm::vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

/// One indexed (u16) triangle with normals, placed by node 0 of scene 0.
Gltf triangle();

/// A bar of two quads along +y (rows at y = 0, 1, 2) skinned (skins[0]) to two joints: root
/// (nodes[1]) at the origin and its child tip (nodes[2]) at y = 1; the bar is nodes[0]. The
/// bottom row follows the root, the top the tip, the middle both. animations[0] ("bend") drives
/// the root's translation (samplers[0], LINEAR), the tip's rotation (samplers[1], STEP) and the
/// tip's scale (samplers[2], CUBICSPLINE), each over keys at 0, 1, 2 s.
Gltf skinnedBar(bool withNormals = true);

/// triangle() with one morph target (POSITION and NORMAL deltas), mesh weights {0.5} and node
/// weights {0.25}.
Gltf morphTriangle();

/// Adds an animation with one sampler (input, output, interpolation) and one channel.
void animate(Gltf& g, int input, int output, int node, const std::string& path,
             const std::string& interpolation = "LINEAR");

/// A loaded scene and the warnings the loader gave.
struct Loaded {
    Scene scene;
    std::vector<std::string> warnings;
    [[nodiscard]] bool warned(const std::string& what) const {
        for (const auto& w : warnings)
            if (w.find(what) != std::string::npos) return true;
        return false;
    }
};

Loaded load(const std::filesystem::path& path, LoadOptions options = {});

/// The SceneError message of loading `path` (failing the test if it loads).
std::string errorOf(const std::filesystem::path& path);

/// Expects a rejection whose message starts with the file name and contains every part.
void expectRejected(const Gltf& g, const std::string& name, std::vector<std::string> parts,
                    Container container = Container::DataUri);

} // namespace fl::test
