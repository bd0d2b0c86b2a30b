#pragma once
// The in-memory scene every pass draws: flat, index-based triangle meshes in world space placement,
// materials, one camera and one disk area light. Produced by the glTF loader and the generator.

#include <base/Aabb.h>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fl {

/// RGBA8 image decoded from a glTF image (base colour textures).
struct Image {
    std::string name;
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba; // width * height * 4, row 0 at the top (as stored in files)
};

/// glTF alphaMode: what the base colour's alpha (factor x texture x vertex colour) means.
enum class AlphaMode { Opaque, Mask, Blend };

/// glTF metallic-roughness material reduced to what we shade with.
struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};
    int baseColorTexture = -1; // index into Scene::images, -1 = none
    bool doubleSided = false;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f; // MASK: a point with alpha below it is not there
};

/// Alpha at and above which a surface of `m` blocks light, in every pass that decides visibility:
/// MASK's cutoff, 0.5 for BLEND (a blended surface casts the shadow of its alpha >= 0.5 part, as
/// most engines do), nullopt for OPAQUE (alpha is ignored and every point blocks).
std::optional<float> shadowCutoff(const Material& m);

/// One triangle list (glTF primitive) in its own model space. Always triangles, indexed u32.
struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;     // same size as positions (generated if the file has none)
    std::vector<glm::vec2> texcoords;   // empty or same size as positions
    std::vector<glm::vec4> colors;      // COLOR_0, linear RGBA: empty (white) or same size
    std::vector<std::uint32_t> indices; // 3 per triangle, every index < positions.size()
    int material = -1;                  // index into Scene::materials, -1 = default material
    /// Skinning (JOINTS_0 / WEIGHTS_0): empty, or one per vertex each; a vertex's joints index
    /// its instance's Skin::joints and its weights sum to 1.
    std::vector<glm::uvec4> joints;
    std::vector<glm::vec4> weights;
    /// Morph targets: each one's POSITION and NORMAL deltas (each empty or one per vertex), and
    /// the mesh's default weights (one per target).
    struct MorphTarget {
        std::vector<glm::vec3> positions;
        std::vector<glm::vec3> normals;
    };
    std::vector<MorphTarget> targets;
    std::vector<float> morphWeights;
    [[nodiscard]] std::size_t triangleCount() const { return indices.size() / 3; }
};

/// A node of the file's hierarchy (Scene::nodes[i] is the file's nodes[i]), kept for animation:
/// its rest transform and its parent. Local transform = matrix if set, else T * R * S; an
/// animation channel drives T, R or S (the loader turns a targeted matrix node into TRS).
struct Node {
    std::string name;
    int parent = -1; // index into Scene::nodes, -1 for a root
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
    std::optional<glm::mat4> matrix; // the file's matrix (never animated)
    std::vector<float> weights;      // the node's morph weights (empty: its mesh's defaults)
};

/// A glTF skin: the joints (nodes) a skinned mesh follows and their inverse bind matrices.
struct Skin {
    std::string name;
    std::vector<int> joints;            // indices into Scene::nodes
    std::vector<glm::mat4> inverseBind; // one per joint (identity where the file has none)
};

/// A glTF animation: samplers (key times and values) driving channels (a node's property).
struct Animation {
    enum class Interpolation { Linear, Step, CubicSpline };
    enum class Path { Translation, Rotation, Scale, Weights };
    /// glTF's names of both, in enum order: the loader reads and GlbWriter writes these.
    static constexpr std::array<std::string_view, 3> kInterpolationNames = {"LINEAR", "STEP",
                                                                            "CUBICSPLINE"};
    static constexpr std::array<std::string_view, 4> kPathNames = {"translation", "rotation",
                                                                   "scale", "weights"};
    struct Sampler {
        Interpolation interpolation = Interpolation::Linear;
        std::vector<float> times;  // seconds, increasing
        std::vector<float> values; // per key `width` values (CUBICSPLINE: in-tangent, value,
                                   // out-tangent, each `width`)
        int width = 0;             // 3 (T, S), 4 (R, xyzw), or the node's morph target count
    };
    struct Channel {
        int node = -1; // index into Scene::nodes
        Path path = Path::Translation;
        int sampler = 0; // index into samplers
    };
    std::string name;
    std::vector<Sampler> samplers;
    std::vector<Channel> channels;
    float duration = 0.0f; // the last key time over every sampler
};

/// A mesh placed in the world by a node's accumulated transform.
struct Instance {
    int mesh = 0;               // index into Scene::meshes
    glm::mat4 world{1.0f};      // model -> world at rest (no animation applied)
    std::uint32_t objectId = 0; // one id per glTF node (JFA-E's object-ID restriction uses it)
    std::string nodeName;
    int node = -1; // index into Scene::nodes (-1: not animated, `world` always)
    int skin = -1; // index into Scene::skins (-1: not skinned; skinned: the joints place it,
                   // neither `world` nor its node applies, glTF 3.7.3.3)
};

/// A perspective camera: world->view transform and projection parameters.
struct Camera {
    glm::mat4 view{1.0f};
    float yfov = glm::radians(45.0f); // vertical field of view, radians
    float znear = 0.1f;
    float zfar = 100.0f;              // 0 = infinite in glTF; the loader fills a finite value
    std::optional<float> aspectRatio; // from the file; the renderer uses the viewport otherwise
    std::string name;
};

/// The disk light's radius as a fraction of the model's bounding radius (Scene::modelBounds)
/// where the scene does not give one (no light, or a light without extras.radius): what
/// --light-size means, and its default. 0.02 drew penumbrae one or two pixels wide on an
/// auto-framed model at 512^2 (hard-looking "soft" shadows); at 0.08 the default view's
/// penumbra is several pixels wide on the ground (FirstViewTest in tests/first_view_gltest.cpp
/// measures it),
/// and the real-model benchmark (bench/real_models.sh) scores every method at this size.
inline constexpr float kDefaultLightSize = 0.08f;

/// The scene light: glTF KHR_lights_punctual's first light, seen as a disk of `radius`.
struct Light {
    enum class Type { Directional, Point, Spot };
    Type type = Type::Point;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // unit, direction the light travels
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    float radius = 0.1f; // disk radius in world units (extras.radius or --light-radius)
    float outerConeAngle = glm::radians(45.0f); // spot only
    std::string name;
};

struct Scene {
    std::string source; // file it came from, or "generated"
    std::vector<Mesh> meshes;
    std::vector<Instance> instances;
    std::vector<Material> materials;
    std::vector<Image> images;
    std::vector<Camera> cameras; // with their node transforms applied (view = inverse(node world))
    std::optional<Light> light;  // absent: the renderer places a default light
    std::vector<Node> nodes;     // the file's nodes when it has skins, morph targets or
                                 // animations; empty otherwise
    std::vector<Skin> skins;
    std::vector<Animation> animations;
    /// World-space bounds of every instance's vertices at rest, tight however a node turns
    /// (restBounds in scene/Pose.h; the clip's bounds are animatedBounds).
    geom::Aabb bounds;
    /// `bounds` without the added ground (addedGround): the model's own box, which light sizes
    /// (--light-size, kDefaultLightSize) are fractions of.
    geom::Aabb modelBounds;
    /// The instance addGround (Ground.h) added under the scene, -1 for none: the first view
    /// frames the model without it (makeCameraView).
    int addedGround = -1;

    /// Total triangles over all instances.
    [[nodiscard]] std::size_t triangleCount() const;
    /// Recomputes `bounds` from the instances (restBounds).
    void computeBounds();
};

} // namespace fl
