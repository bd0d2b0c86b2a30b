#pragma once
// Small hand-built scenes with known answers, and a CPU ray caster as the reference for shadows.

#include <scene/Camera.h>
#include <scene/Scene.h>

namespace fl::test {

/// An axis-aligned box [lo, hi], its faces wound outward with flat normals (default material).
Mesh box(glm::vec3 lo, glm::vec3 hi);

/// A ground quad (y = 0, [-half, half]²) and an axis-aligned box [lo, hi], each its own object,
/// lit by a directional light travelling along `lightDir`.
Scene groundAndBox(float half, glm::vec3 lo, glm::vec3 hi, glm::vec3 lightDir);

/// groundAndBox's ground under a horizontal double-sided 2 x 2 card at height 1 whose base-colour
/// texture is a cells x cells checker of alpha 1 and 0 (material `mode`, cutoff 0.5), each cell
/// texelsPerCell texels wide, under a point light at (-3.6, 4, -0.9): the card's shadow, a
/// checker, falls mostly beside it (over x in [-0.13, 2.53], z in [-1.03, 1.63]), magnified 4/3.
Scene checkerCardOverGround(AlphaMode mode, int cells, int texelsPerCell = 1);

/// A scene and the camera that views it.
struct SceneView {
    Scene scene;
    CameraView camera;
};

/// A square camera at `eye` looking at `target` with a vertical field of view of `fovDegrees`.
CameraView lookAtCamera(const Scene& scene, glm::vec3 eye, glm::vec3 target, float fovDegrees);

/// groundAndBox's unit box under a spot light of radius 2 above and to the side of it, seen from
/// above the other side: inner and outer penumbrae on the ground, self-shadowing on the box.
SceneView spotLitBox();

/// CPU reference for a hard shadow: 1 if the segment from `p` towards the light (direction
/// -light.direction for directional lights, else to light.position) hits no triangle, 0 if it
/// does. `epsilon` skips hits right at p (the receiver itself). Alpha cut-outs let the ray through
/// (scene/AlphaCoverage.h).
float rayCastVisibility(const Scene& scene, const Light& light, glm::vec3 p, float epsilon = 1e-3f);

} // namespace fl::test
