#pragma once
// The in-memory scene every pass draws: flat, index-based triangle meshes in world space placement,
// materials, one camera and one disk area light. Produced by the glTF loader and the generator.

#include <geometry/Aabb.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>
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
    [[nodiscard]] std::size_t triangleCount() const { return indices.size() / 3; }
};

/// A mesh placed in the world by a node's accumulated transform.
struct Instance {
    int mesh = 0;               // index into Scene::meshes
    glm::mat4 world{1.0f};      // model -> world
    std::uint32_t objectId = 0; // one id per glTF node (JFA-E's object-ID restriction uses it)
    std::string nodeName;
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
    geom::Aabb bounds;           // world-space bounds of all instances

    /// Total triangles over all instances.
    [[nodiscard]] std::size_t triangleCount() const;
    /// Recomputes `bounds` from the instances.
    void computeBounds();
};

} // namespace fl
