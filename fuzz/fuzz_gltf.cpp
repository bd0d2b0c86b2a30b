// libFuzzer target: the glTF loader on any bytes, as a .glb when they start with the "glTF"
// magic and as a .gltf otherwise (the loader dispatches on the content; the extension only has
// to be one it accepts). loadGltf reads a file, so each input goes to a per-process temporary
// file; external buffers and images resolve next to it, as for any scene. A bad file must throw
// SceneError; a scene that loads must hold what the renderer relies on: finite positions,
// normals, texcoords, transforms and bounds, indices within their mesh, valid material, texture
// and mesh indices, complete images, usable cameras and a usable light.
#include "FuzzInput.h"

#include <renderer/gltf/GltfLoader.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

// tinygltf is built into the target (see fuzz/CMakeLists.txt). Its implementation includes
// nlohmann/json.hpp, and with it system headers, under hidden visibility, which would hide
// getpid() from the link: everything else is included first.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>

namespace {

bool finite(float v) {
    return std::isfinite(v);
}

template <int N>
bool finite(const glm::vec<N, float>& v) {
    for (int i = 0; i < N; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        if (!finite(m[c])) return false;
    return true;
}

/// What loadGltf promises about a scene it returns (Scene.h, GltfLoader.cpp).
void checkScene(const fl::Scene& s) {
    REQUIRE(!s.meshes.empty() && !s.instances.empty());
    for (const fl::Mesh& m : s.meshes) {
        REQUIRE(m.normals.size() == m.positions.size());
        REQUIRE(m.texcoords.empty() || m.texcoords.size() == m.positions.size());
        REQUIRE(m.indices.size() % 3 == 0);
        REQUIRE(m.material >= -1 && m.material < static_cast<int>(s.materials.size()));
        for (const glm::vec3& p : m.positions) REQUIRE(finite(p));
        for (const glm::vec3& n : m.normals) REQUIRE(finite(n));
        for (const glm::vec2& t : m.texcoords) REQUIRE(finite(t));
        REQUIRE(m.colors.empty() || m.colors.size() == m.positions.size());
        for (const glm::vec4& c : m.colors)
            REQUIRE(c.x >= 0 && c.x <= 1 && c.y >= 0 && c.y <= 1 && c.z >= 0 && c.z <= 1 &&
                    c.w >= 0 && c.w <= 1);
        for (const std::uint32_t i : m.indices) REQUIRE(i < m.positions.size());
    }
    for (const fl::Instance& i : s.instances) {
        REQUIRE(i.mesh >= 0 && i.mesh < static_cast<int>(s.meshes.size()));
        REQUIRE(finite(i.world));
    }
    REQUIRE(s.bounds.valid() && finite(s.bounds.min) && finite(s.bounds.max));
    for (const fl::Material& m : s.materials) {
        REQUIRE(finite(m.baseColorFactor));
        REQUIRE(std::isfinite(m.alphaCutoff) && m.alphaCutoff >= 0.0f);
        REQUIRE(m.baseColorTexture >= -1 && m.baseColorTexture < static_cast<int>(s.images.size()));
    }
    for (const fl::Image& im : s.images)
        REQUIRE(im.width > 0 && im.height > 0 &&
                im.rgba.size() == std::size_t(im.width) * std::size_t(im.height) * 4);
    for (const fl::Camera& c : s.cameras) {
        REQUIRE(finite(c.view) && finite(c.yfov) && c.yfov > 0.0f);
        REQUIRE(finite(c.znear) && c.znear > 0.0f && finite(c.zfar) && c.zfar > c.znear);
        REQUIRE(!c.aspectRatio || (finite(*c.aspectRatio) && *c.aspectRatio > 0.0f));
    }
    if (const auto& l = s.light) {
        REQUIRE(finite(l->position) && finite(l->direction) && finite(l->color));
        REQUIRE(finite(l->intensity) && l->intensity >= 0.0f);
        REQUIRE(finite(l->radius) && l->radius >= 0.0f);
        REQUIRE(finite(l->outerConeAngle) && l->outerConeAngle > 0.0f);
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    static const std::filesystem::path glb = fl::fuzz::tempFile("gltf", "glb"),
                                       gltf = fl::fuzz::tempFile("gltf", "gltf");
    const std::filesystem::path& file = binary ? glb : gltf;
    fl::fuzz::writeInput(file, data, size);
    fl::LoadOptions options;
    options.warn = [](const std::string&) {}; // exercises the warning paths' formatting
    try {
        checkScene(fl::loadGltf(file, options));
    } catch (const fl::SceneError&) {
    }
    return 0;
}
