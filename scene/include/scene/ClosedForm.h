#pragma once
// Scenes whose soft shadow is known in closed form: a disk light straight above a ground plane,
// with an occluder whose shadow on the ground has an exact visible fraction per point. What every
// shadow method (and both ground truths) can be measured against without any estimate in
// between: `bench/closed_form_bench.cpp` records every method's error on them, the tests check
// the ray tracer through them.

#include <scene/Camera.h>
#include <scene/Scene.h>

#include <io/ImageIO.h>

#include <functional>
#include <string>
#include <vector>

namespace fl {

/// The visible share of a disk light (radius r, at height H, facing down) from a ground point
/// (y = 0) at signed distance x from the line under the straight edge of a half-plane occluder
/// at height h (x < 0: the occluded side). The ray to a disk point at signed distance s crosses
/// the occluder's plane at x + (s - x) h / H, so it is blocked for s < -x (H - h) / h; the
/// visible part of the disk is the segment beyond that chord (segmentFraction, as JFA-L and
/// JFA-E use it).
double straightEdgeVisibility(double x, double h, double H, double r);

/// The visible share of the same disk light from a ground point at distance rho from the axis
/// under a disk occluder of radius a at height h centred on the light's axis: from the point the
/// occluder covers the disk of radius aH/h centred rho (H - h)/h from the light's centre; visible
/// is 1 - (the lens of the two disks) / (pi r^2).
double diskOccluderVisibility(double rho, double a, double h, double H, double r);

/// One case: the scene (ground quad, occluder, a spot light of the case's radius straight above
/// the origin), the camera that sees the penumbra (from low on the lit side, below the
/// occluder), and the exact visibility of ground points within `extent` of the origin (on both
/// axes; beyond it the occluder's finite size matters).
struct ClosedFormCase {
    std::string name;
    Scene scene;
    CameraSpec camera;
    std::function<double(glm::vec3 groundPoint)> exact;
    float extent = 1.0f;
};

/// A half-plane occluder at height h whose edge runs through the axis, its outward normal at
/// `angleDegrees` about the vertical, under a disk light of radius r at height H.
ClosedFormCase straightEdgeCase(float h, float H, float r, float angleDegrees);
/// A disk occluder of radius a (128-gon) at height h on the axis of a disk light of radius r at
/// height H.
ClosedFormCase diskOccluderCase(float a, float h, float H, float r);
/// A frame's visibility against a case's closed form, over the ground pixels (y = 0) within the
/// case's extent.
struct ClosedFormError {
    std::size_t ground = 0;   // pixels compared
    std::size_t penumbra = 0; // of which the exact visibility is in (0.02, 0.98)
    double rmse = 0.0;        // over the ground pixels
    double rmsePenumbra = 0.0;
    double biasPenumbra = 0.0; // mean signed (frame - exact) over the penumbra pixels
    double maxAbs = 0.0;
    FloatImage exact; // the frame's visibility with the closed form where it applies
};
/// `position`: the frame's surfaces (RGBA, world xyz, w = 0 background), `visibility` its R
/// channel, both as readTexture returns them.
ClosedFormError closedFormError(const ClosedFormCase& c, const FloatImage& position,
                                const FloatImage& visibility);

/// The cases bench/closed_form_bench.cpp measures: straight edges at several angles and heights,
/// and a disk occluder.
std::vector<ClosedFormCase> closedFormCases();

} // namespace fl
