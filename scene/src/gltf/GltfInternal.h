#pragma once
// Private to the glTF loader. loadGltf() (GltfLoader.cpp) parses the file with tinygltf and then
// runs the steps declared here, one source file each:
//   GltfAccessors.cpp  accessor / bufferView / buffer validation and decoding
//   GltfMeshes.cpp     triangle primitives -> fl::Mesh (modes, indices, normals, texcoords)
//   GltfNodes.cpp      node graph checks, transforms, scene traversal, cameras, the light
//   GltfMaterials.cpp  materials, textures and image decoding
//   GltfSkins.cpp      skinning attributes, morph targets, skins and the node list
//   GltfAnimation.cpp  animations (samplers and channels)
// tinygltf accepts much malformed content, so every step validates what it reads and reports
// through Context::fail (reject) or Context::warn (repair).

#include <base/Numbers.h>
#include <base/Text.h>
#include <scene/GltfLoader.h>
#include <scene/Pose.h>
#include <scene/Scene.h>

#include <tiny_gltf.h>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace fl::gltf {

/// Within the world's limit (base/Numbers.h) on every axis: a vertex, camera or light farther
/// out makes the renderer's float bounds, frusta and light transforms overflow.
inline bool inWorld(const glm::vec3& p) {
    return std::abs(p.x) <= kMaxWorldCoordinate && std::abs(p.y) <= kMaxWorldCoordinate &&
           std::abs(p.z) <= kMaxWorldCoordinate;
}

// Limits that keep a hostile file from making us allocate gigabytes or spin for minutes. They
// sit far above anything Floodlight can render interactively, so real scenes never meet them.
// An accessor without a bufferView reads as zeros, so a few bytes of JSON can ask for any count:
// the per-accessor and per-file limits bound what such a file makes us allocate.
inline constexpr std::size_t kMaxAccessorCount = std::size_t{1} << 24; // elements per accessor
inline constexpr std::size_t kMaxDecodedValues = std::size_t{1} << 28; // all accessors: 1 GiB
inline constexpr std::size_t kMaxNodes = std::size_t{1} << 20;
// Morph targets cost memory even when they name no accessor; real files have a few hundred.
// (Of those, the first fl::kMaxMorphTargets are drawn: scene/Pose.h.)
inline constexpr std::size_t kMaxFileMorphTargets = std::size_t{1} << 16;
inline constexpr int kMaxImageSide = 16384; // GL_MAX_TEXTURE_SIZE of common desktop drivers
inline constexpr long long kMaxImagePixels = 1LL << 26; // 256 MiB of RGBA8

using ::fl::cat;

/// "meshes[3]".
inline std::string elem(std::string_view array, std::size_t index) {
    return cat(array, '[', index, ']');
}

/// What every step needs: the parsed model plus where messages go.
class Context {
  public:
    Context(std::string fileName, std::filesystem::path baseDir, const tinygltf::Model& model,
            const LoadOptions& options)
        : fileName_(std::move(fileName)), baseDir_(std::move(baseDir)), model_(model),
          options_(options) {}

    /// Throws SceneError "file: element: problem".
    [[noreturn]] void fail(std::string_view element, std::string_view problem) const;
    /// Records a repair or a skipped part; flushWarnings reports it as "file: element: what".
    void warn(std::string_view element, std::string_view what) const;
    /// Reports the recorded warnings through LoadOptions::warn, one line per kind (25
    /// "degenerate triangle(s) dropped" lines came from one model): a warning alone as
    /// "file: element: what", a kind met in several elements as "file: what, summed, in N
    /// elements (the first three, ...)". Kinds are the text with its numbers blanked; counts
    /// leading the text are added up. In the order each kind first came.
    void flushWarnings() const;

    /// Counts `values` decoded components against kMaxDecodedValues; fails past it.
    void charge(std::size_t values, std::string_view element) const;

    [[nodiscard]] const tinygltf::Model& model() const { return model_; }
    [[nodiscard]] const LoadOptions& options() const { return options_; }
    [[nodiscard]] const std::string& fileName() const { return fileName_; }
    [[nodiscard]] const std::filesystem::path& baseDir() const { return baseDir_; }

    /// items[index], or fail("referrer", "<what> <index> does not exist (<n> in <array>)").
    template <class T>
    const T& lookup(const std::vector<T>& items, int index, std::string_view referrer,
                    std::string_view what, std::string_view array) const {
        if (!inRange(items, index))
            fail(referrer,
                 cat(what, ' ', index, " does not exist (", items.size(), " in ", array, ')'));
        return items[static_cast<std::size_t>(index)];
    }

    template <class T>
    static bool inRange(const std::vector<T>& items, int index) {
        return index >= 0 && static_cast<std::size_t>(index) < items.size();
    }

  private:
    std::string fileName_;
    std::filesystem::path baseDir_;
    const tinygltf::Model& model_;
    const LoadOptions& options_;
    mutable std::size_t decodedValues_ = 0; // accessor reads and warnings are the mutations
    mutable std::vector<std::pair<std::string, std::string>> warnings_; // element, what
};

// --- accessors (GltfAccessors.cpp) ---------------------------------------------------------
// `usage` names the referrer for messages, e.g. "meshes[0].primitives[1].attributes.POSITION".

/// The bytes of bufferViews[index], checked against its buffer.
struct ByteSpan {
    const std::uint8_t* data = nullptr;
    std::size_t size = 0;
};
ByteSpan bufferViewBytes(const Context& ctx, int index, std::string_view usage);

/// Whether the file lists `name` in extensionsUsed.
bool usesExtension(const Context& ctx, std::string_view name);

/// VEC3 FLOAT; with KHR_mesh_quantization also (normalized or not) BYTE, UNSIGNED_BYTE, SHORT
/// and UNSIGNED_SHORT (POSITION).
std::vector<glm::vec3> readPositionVec3(const Context& ctx, int index, std::string_view usage);
/// VEC3 FLOAT; with KHR_mesh_quantization also normalized BYTE and SHORT (NORMAL).
std::vector<glm::vec3> readNormalVec3(const Context& ctx, int index, std::string_view usage);
/// VEC2 FLOAT or normalized UNSIGNED_BYTE / UNSIGNED_SHORT (TEXCOORD_n); with
/// KHR_mesh_quantization also BYTE and SHORT, and the integer forms unnormalized.
std::vector<glm::vec2> readTexcoords(const Context& ctx, int index, std::string_view usage);
/// VEC3 or VEC4 FLOAT or normalized UNSIGNED_BYTE / UNSIGNED_SHORT (COLOR_0); VEC3 gets alpha 1.
std::vector<glm::vec4> readColors(const Context& ctx, int index, std::string_view usage);
/// SCALAR UNSIGNED_BYTE / UNSIGNED_SHORT / UNSIGNED_INT (primitive indices).
std::vector<std::uint32_t> readIndices(const Context& ctx, int index, std::string_view usage);
/// VEC3 FLOAT; with KHR_mesh_quantization also BYTE and SHORT, normalized or not (morph
/// target POSITION deltas; NORMAL deltas read as readNormalVec3).
std::vector<glm::vec3> readTargetPositionVec3(const Context& ctx, int index,
                                              std::string_view usage);
/// VEC4 UNSIGNED_BYTE / UNSIGNED_SHORT as integers (JOINTS_0).
std::vector<glm::uvec4> readJoints(const Context& ctx, int index, std::string_view usage);
/// VEC4 FLOAT or normalized UNSIGNED_BYTE / UNSIGNED_SHORT (WEIGHTS_0).
std::vector<glm::vec4> readWeights(const Context& ctx, int index, std::string_view usage);
/// MAT4 FLOAT (skin inverse bind matrices).
std::vector<glm::mat4> readMat4(const Context& ctx, int index, std::string_view usage);
/// All components of a `type` accessor as floats: FLOAT, or with `normalizedIntegers` also
/// normalized BYTE / UNSIGNED_BYTE / SHORT / UNSIGNED_SHORT (animation sampler data, 3.11).
std::vector<float> readAnimationFloats(const Context& ctx, int index, std::string_view usage,
                                       int type, bool normalizedIntegers);

// --- meshes (GltfMeshes.cpp) ----------------------------------------------------------------

/// Converts the triangle primitives of meshes[meshIndex] (one fl::Mesh each) and appends them
/// to `out`; skipped primitives (points, lines, empty) are reported through ctx.warn.
void convertMesh(const Context& ctx, int meshIndex, std::vector<Mesh>& out);

/// The number of morph targets of meshes[meshIndex] (every primitive must have the same).
std::size_t morphTargetCount(const Context& ctx, int meshIndex);

/// morphTargetCount of each mesh, computed once: nodes and channels ask per node, and a file can
/// have a million nodes over one mesh of many primitives.
class MorphTargetCounts {
  public:
    explicit MorphTargetCounts(const Context& ctx)
        : ctx_(ctx), counts_(ctx.model().meshes.size(), kUnknown) {}
    /// Target count of meshes[mesh]; 0 for an index that is not a mesh.
    std::size_t operator()(int mesh) {
        if (!Context::inRange(counts_, mesh)) return 0;
        std::size_t& count = counts_[static_cast<std::size_t>(mesh)];
        if (count == kUnknown) count = morphTargetCount(ctx_, mesh);
        return count;
    }

  private:
    static constexpr std::size_t kUnknown = ~std::size_t{0};
    const Context& ctx_;
    std::vector<std::size_t> counts_;
};

/// glTF primitive modes TRIANGLES / TRIANGLE_STRIP / TRIANGLE_FAN as a triangle list (spec
/// 3.7.2.1 vertex order); a list's trailing partial triangle is dropped.
std::vector<std::uint32_t> triangleList(int mode, const std::vector<std::uint32_t>& indices);

// --- nodes (GltfNodes.cpp) ------------------------------------------------------------------

/// A node of the chosen scene with its accumulated model->world transform.
struct PlacedNode {
    int node = -1;
    glm::mat4 world{1.0f};
};

/// Validates the node graph (indices, single parent, no cycles), picks the scene (default
/// scene, else scene 0, else every root node) and lists its nodes depth first.
std::vector<PlacedNode> placeSceneNodes(const Context& ctx);

/// Perspective cameras of the placed nodes; infinite zfar is made finite from `bounds`.
std::vector<Camera> convertCameras(const Context& ctx, const std::vector<PlacedNode>& placed,
                                   const geom::Aabb& bounds);

/// The first KHR_lights_punctual light placed by a node, if any.
std::optional<Light> convertLight(const Context& ctx, const std::vector<PlacedNode>& placed,
                                  const geom::Aabb& bounds);

// --- skins and morph targets (GltfSkins.cpp) ------------------------------------------------
// `element` names the primitive, e.g. "meshes[0].primitives[1]".

/// JOINTS_0 / WEIGHTS_0 of a primitive into mesh.joints / mesh.weights (weights repaired to sum
/// to 1); joint indices are checked per instance, against its skin (linkSkins).
void attachSkinning(const Context& ctx, const tinygltf::Primitive& prim, const std::string& element,
                    Mesh& mesh);
/// The primitive's morph targets' POSITION and NORMAL deltas into mesh.targets.
void attachMorphTargets(const Context& ctx, const tinygltf::Primitive& prim,
                        const std::string& element, Mesh& mesh);
/// meshes[meshIndex].weights checked against `targets` (zeros with a warning when unusable).
std::vector<float> defaultMorphWeights(const Context& ctx, int meshIndex, std::size_t targets);

/// Fills scene.skins, each instance's skin and, when the file has skins, morph targets or
/// animations, scene.nodes and scene.animations (else every Instance::node becomes -1).
/// Instance::node must hold the placing node; `placed` are the nodes the scene places.
void convertRigging(const Context& ctx, const std::vector<PlacedNode>& placed, Scene& scene);

// --- animations (GltfAnimation.cpp) ---------------------------------------------------------

/// Every animation's channels that drive T, R, S or morph weights of `nodes`, with the samplers
/// they use; a matrix node a channel drives is turned into TRS.
std::vector<Animation> convertAnimations(const Context& ctx, std::vector<Node>& nodes);

// --- materials (GltfMaterials.cpp) ----------------------------------------------------------

/// All materials, in file order (so primitive material indices carry over); the base colour
/// textures of the `used` ones are decoded into `images`.
std::vector<Material> convertMaterials(const Context& ctx, const std::vector<bool>& used,
                                       std::vector<Image>& images);

/// tinygltf image callback: keeps the encoded bytes so that decoding happens only for images
/// a material uses (see GltfMaterials.cpp).
bool keepEncodedImage(tinygltf::Image* image, int imageIndex, std::string* err, std::string* warn,
                      int reqWidth, int reqHeight, const unsigned char* bytes, int size,
                      void* user);

} // namespace fl::gltf
