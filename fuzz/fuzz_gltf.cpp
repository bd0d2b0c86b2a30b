// libFuzzer target: the glTF loader on any bytes, as a .glb when they start with the "glTF"
// magic and as a .gltf otherwise (the loader dispatches on the content; the extension only has
// to be one it accepts). loadGltf reads a file, so each input goes to a per-process temporary
// file; external buffers and images resolve next to it, as for any scene. A bad file must throw
// SceneError; a scene that loads must hold what the renderer relies on: finite positions,
// normals, texcoords, transforms and bounds, indices within their mesh, valid material, texture
// and mesh indices, complete images, usable cameras and a usable light, and for animation:
// joints within their skin, weights that sum to 1, morph targets one delta per vertex, nodes,
// skins and channels indexing what exists, samplers' times increasing and values matching them.
#include "FuzzInput.h"

#include <scene/GltfLoader.h>

#include <nlohmann/json.hpp>

#include <algorithm>
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

/// Joints and weights: both or neither, one per vertex; weights finite, >= 0, summing to 1.
void checkSkinning(const fl::Mesh& m) {
    REQUIRE(m.joints.empty() || m.joints.size() == m.positions.size());
    REQUIRE(m.weights.size() == m.joints.size());
    for (const glm::vec4& w : m.weights) {
        REQUIRE(finite(w) && w.x >= 0 && w.y >= 0 && w.z >= 0 && w.w >= 0);
        REQUIRE(std::abs(double(w.x) + w.y + w.z + w.w - 1.0) < 1e-5);
    }
}

/// Nodes, skins and animations index what exists, and every number in them is usable.
void checkAnimationData(const fl::Scene& s) {
    const auto nodeCount = static_cast<int>(s.nodes.size());
    for (std::size_t i = 0; i < s.nodes.size(); ++i) {
        const fl::Node& n = s.nodes[i];
        REQUIRE(n.parent >= -1 && n.parent < nodeCount && n.parent != static_cast<int>(i));
        REQUIRE(finite(n.translation) && finite(n.scale));
        const glm::vec4 q(n.rotation.x, n.rotation.y, n.rotation.z, n.rotation.w);
        REQUIRE(finite(q) && std::abs(glm::length(q) - 1.0f) < 1e-4f);
        REQUIRE(!n.matrix || finite(*n.matrix));
        for (const float w : n.weights) REQUIRE(finite(w));
    }
    for (const fl::Skin& skin : s.skins) {
        REQUIRE(!skin.joints.empty() && skin.inverseBind.size() == skin.joints.size());
        for (const int j : skin.joints) REQUIRE(j >= 0 && j < nodeCount);
        for (const glm::mat4& m : skin.inverseBind) REQUIRE(finite(m));
    }
    for (const fl::Animation& a : s.animations) {
        float last = 0.0f;
        for (const fl::Animation::Sampler& sm : a.samplers) {
            REQUIRE(!sm.times.empty() && sm.width > 0);
            for (std::size_t k = 0; k < sm.times.size(); ++k)
                REQUIRE(finite(sm.times[k]) && sm.times[k] >= 0.0f &&
                        (k == 0 || sm.times[k] > sm.times[k - 1]));
            const std::size_t perKey =
                sm.interpolation == fl::Animation::Interpolation::CubicSpline ? 3 : 1;
            REQUIRE(sm.values.size() ==
                    sm.times.size() * perKey * static_cast<std::size_t>(sm.width));
            for (const float v : sm.values) REQUIRE(finite(v));
            last = std::max(last, sm.times.back());
        }
        REQUIRE(a.duration == last);
        for (const fl::Animation::Channel& c : a.channels) {
            REQUIRE(c.node >= 0 && c.node < nodeCount);
            REQUIRE(c.sampler >= 0 && c.sampler < static_cast<int>(a.samplers.size()));
            const int width = a.samplers[static_cast<std::size_t>(c.sampler)].width;
            using Path = fl::Animation::Path;
            REQUIRE(c.path == Path::Weights || width == (c.path == Path::Rotation ? 4 : 3));
            // Driven T, R or S: the node has no matrix left to override them.
            REQUIRE(c.path == Path::Weights || !s.nodes[static_cast<std::size_t>(c.node)].matrix);
        }
    }
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
        checkSkinning(m);
        REQUIRE(m.morphWeights.size() == m.targets.size());
        for (const float w : m.morphWeights) REQUIRE(finite(w));
        for (const fl::Mesh::MorphTarget& t : m.targets) {
            REQUIRE(t.positions.empty() || t.positions.size() == m.positions.size());
            REQUIRE(t.normals.empty() || t.normals.size() == m.positions.size());
            for (const glm::vec3& d : t.positions) REQUIRE(finite(d));
            for (const glm::vec3& d : t.normals) REQUIRE(finite(d));
        }
    }
    for (const fl::Instance& i : s.instances) {
        REQUIRE(i.mesh >= 0 && i.mesh < static_cast<int>(s.meshes.size()));
        REQUIRE(finite(i.world));
        // A node index exactly when the file's nodes are kept; a skin only over skinning data.
        REQUIRE(s.nodes.empty() ? i.node == -1
                                : i.node >= 0 && i.node < static_cast<int>(s.nodes.size()));
        REQUIRE(i.skin >= -1 && i.skin < static_cast<int>(s.skins.size()));
        if (i.skin >= 0) {
            const fl::Mesh& m = s.meshes[static_cast<std::size_t>(i.mesh)];
            const std::size_t joints = s.skins[static_cast<std::size_t>(i.skin)].joints.size();
            REQUIRE(!m.joints.empty());
            for (const glm::uvec4& j : m.joints)
                REQUIRE(j.x < joints && j.y < joints && j.z < joints && j.w < joints);
        }
    }
    checkAnimationData(s);
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
