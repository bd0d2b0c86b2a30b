#pragma once
// Cameras and the light's frame, as pure math on the scene (CPU): what the camera sees with, how
// a user picks it (a glTF camera, the automatic view, an eye and a target), and the light's view
// volume fitted to the scene.

#include <scene/Scene.h>

#include <base/Aabb.h>
#include <base/Framing.h>

#include <glm/glm.hpp>

#include <optional>

namespace fl {

/// What the camera sees with: matrices and eye position.
struct CameraView {
    glm::mat4 view{1.0f};
    glm::mat4 proj{1.0f};
    glm::vec3 eye{0.0f};
};

/// How to pick the camera: a glTF camera, automatic framing, or an explicit eye/target.
struct CameraSpec {
    enum class Kind { Default, Auto, Gltf, LookAt };
    Kind kind = Kind::Default; // Default: the scene's first camera if it has one, else Auto
    int gltfIndex = 0;
    glm::vec3 eye{0.0f}, target{0.0f};
    std::optional<float> yfovDegrees; // overrides the camera's field of view
    /// Auto: frame the geometry in this pose (a skinned or animated model at --time) instead of
    /// at rest; nullptr: at rest. Not owned.
    const struct Pose* pose = nullptr;
};

/// The automatic view's direction (from the target to the eye) and vertical field of view (when
/// --fov does not set it).
inline const glm::vec3 kAutoViewFrom{0.55f, 0.5f, 0.75f};
inline constexpr float kAutoViewFovDegrees = 50.0f;

/// The camera for `spec` at the given aspect ratio; throws std::invalid_argument for a glTF
/// camera index the scene does not have. The automatic view (Auto, and Default for a scene
/// without cameras) frames the scene's bounds, or, on a ground Floodlight added, the model and
/// its shadow under sceneLight (modelAndShadowPoints, Ground.h), as tightly as they allow; in
/// spec.pose when given.
CameraView makeCameraView(const Scene& scene, const CameraSpec& spec, float aspect);

/// The scene's light, or the default one (above and to the side of the bounds) if it has none.
Light sceneLight(const Scene& scene);

/// The bounds of what can cast a shadow under `light`: `model` (the bounds without the ground
/// Floodlight added, Scene::modelBounds or its animated box) where the scene has an added ground
/// and a point or spot light stands above it, else `bounds` (everything).
geom::Aabb shadowCasterBounds(const Scene& scene, const Light& light, const geom::Aabb& bounds,
                              const geom::Aabb& model);

/// The light's view volume: aimed at the scene's shadow casters (shadowCasterBounds) and widened
/// by the disk light's penumbrae, with the depth range of the whole scene.
geom::ViewVolume lightVolume(const Scene& scene, const Light& light);
/// The same where everything in `bounds` casts shadows.
geom::ViewVolume lightVolume(const geom::Aabb& bounds, const Light& light);
/// The volume aimed at `casters` (geom::fitPerspectiveLight's), holding `bounds` in depth.
geom::ViewVolume lightVolume(const geom::Aabb& casters, const geom::Aabb& bounds,
                             const Light& light);

} // namespace fl
