#pragma once
// The scene at a time: glTF animations sampled (translation, rotation, scale, morph weights;
// LINEAR with slerp for rotations, STEP, CUBICSPLINE), every node's world transform, each
// skin's joint matrices and each instance's morph weights. The GL passes pose vertices from this
// in their vertex stages (shaders/pose.glsl, uploaded by GpuScene::setPose); posedVertices() is
// the CPU twin, which the ray-traced truth, the bounds and the tests use.

#include <base/Aabb.h>
#include <scene/Scene.h>

#include <span>
#include <string>
#include <vector>

namespace fl {

/// Morph targets the vertex stage applies per mesh (shaders/pose.glsl kMaxMorphTargets); the
/// loader keeps the first ones and drops the rest with a warning.
inline constexpr std::size_t kMaxMorphTargets = 32;
/// The largest time (seconds, 11.6 days) a command accepts: far beyond any clip, and small
/// enough that float key times keep their resolution next to it.
inline constexpr double kMaxAnimationTime = 1e6;

struct Pose {
    double time = 0.0;
    std::vector<glm::mat4> nodeWorld;     // per Scene::nodes
    std::vector<glm::mat4> instanceWorld; // per instance: model -> world (identity when skinned)
    /// Per skin: world(joint) * inverseBind(joint), per joint.
    std::vector<std::vector<glm::mat4>> joints;
    /// Per instance: its morph weights (one per target of its mesh; empty without targets).
    std::vector<std::vector<float>> morphWeights;
};

/// True when `instance` (of `mesh`) is drawn by its skin's joints: it has a skin and the mesh
/// has joints and weights.
[[nodiscard]] bool isSkinned(const Instance& instance, const Mesh& mesh);

/// True when the scene has something a time changes or a pose deforms: animations, skins or
/// morph targets.
[[nodiscard]] bool isAnimated(const Scene& scene);

/// The animations `choice` names: "all", "none", an animation's name or its index. Throws
/// std::invalid_argument listing the scene's animations otherwise.
[[nodiscard]] std::vector<int> chooseAnimations(const Scene& scene, const std::string& choice);

/// The pose at `time` seconds with `animations` applied (a sampler holds its first value before
/// its first key and its last after its last: no looping here; callers wrap time if they loop).
/// Nothing animated: the rest pose (the nodes' own transforms, the meshes' default weights).
[[nodiscard]] Pose evaluatePose(const Scene& scene, std::span<const int> animations, double time);

/// The longest duration among `animations` (0 for none).
[[nodiscard]] double animationDuration(const Scene& scene, std::span<const int> animations);

/// Instance `instance`'s vertices in world space in `pose` (morphed, skinned or moved), and its
/// normals when `normals` is given (unit; skinned normals use the blended matrix's upper 3x3,
/// as the vertex stage does, exact for rigid joints).
void posedVertices(const Scene& scene, const Pose& pose, std::size_t instance,
                   std::vector<glm::vec3>& positions, std::vector<glm::vec3>* normals = nullptr);

/// The scene's bounds in `pose`: skinned and morphed instances' posed vertices, and each rigid
/// instance's mesh box moved by its transform (looser than its vertices where the transform
/// turns: the clip's margin, animatedBounds).
/// `skipInstance` (>= 0) leaves that instance out.
[[nodiscard]] geom::Aabb posedBounds(const Scene& scene, const Pose& pose, int skipInstance = -1);

/// The scene's bounds at rest (what Scene::computeBounds stores): the tight box around every
/// vertex where the vertex stage places it with no animation applied; rigid instances' vertices
/// moved by their `world`, skinned and morphed ones posed at rest (evaluatePose with none).
/// The added ground, the default light, the auto camera and the ray tracer's disk all start here.
/// `skipInstance` (>= 0) leaves that instance out (Scene::modelBounds: the added ground).
[[nodiscard]] geom::Aabb restBounds(const Scene& scene, int skipInstance = -1);

/// True when some triangle at rest (placed as restBounds places its vertices) has a nonzero,
/// finite area in float: false for a scene whose vertices all lie in one point or on one line,
/// or whose every node is scaled to 0. Stops at the first such triangle.
[[nodiscard]] bool restHasArea(const Scene& scene);

/// The bounds of every pose `animations` take over their duration: the union over every key
/// time (at most 256 of them) and `steps` even steps. The light's frustum fits these, so that the
/// shadow map does not change its texel grid (and swim) from frame to frame as the characters move.
/// `skipInstance` (>= 0) leaves that instance out (the added ground).
[[nodiscard]] geom::Aabb animatedBounds(const Scene& scene, std::span<const int> animations,
                                        int steps = 64, int skipInstance = -1);

} // namespace fl
