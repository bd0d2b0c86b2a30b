#pragma once
// Small hand-built scenes with known answers, and a CPU ray caster as the reference for shadows.

#include <renderer/Renderer.h>
#include <renderer/scene/Scene.h>

namespace fl::test {

/// A ground quad (y = 0, [-half, half]²) and an axis-aligned box [lo, hi], each its own object,
/// lit by a directional light travelling along `lightDir`.
Scene groundAndBox(float half, glm::vec3 lo, glm::vec3 hi, glm::vec3 lightDir);

/// A scene and the camera that views it.
struct SceneView {
    Scene scene;
    CameraView camera;
};

/// groundAndBox's unit box under a spot light of radius 2 above and to the side of it, seen from
/// above the other side: inner and outer penumbrae on the ground, self-shadowing on the box.
SceneView spotLitBox();

/// CPU reference for a hard shadow: 1 if the segment from `p` towards the light (direction
/// -light.direction for directional lights, else to light.position) hits no triangle, 0 if it
/// does. `epsilon` skips hits right at p (the receiver itself).
float rayCastVisibility(const Scene& scene, const Light& light, glm::vec3 p, float epsilon = 1e-3f);

/// The exact visible share of a disk light of radius r at height H (facing down) from a ground
/// point (y = 0) at signed distance x from the line under the straight edge of a half-plane
/// occluder at height h (x < 0: the occluded side). The ray to a disk point at signed distance s
/// crosses the occluder's plane at x + (s - x) h / H, so it is blocked for s < -x (H - h) / h;
/// the visible part of the disk is the segment beyond that chord (fl::segmentFraction, as JFA-L
/// and JFA-E use it).
double straightEdgeVisibility(double x, double h, double H, double r);

} // namespace fl::test
