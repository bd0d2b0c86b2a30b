#pragma once
// The trapezoid fit of Trapezoidal Shadow Maps (Martin & Tan, EGSR 2004): a projective map N_T
// from the light's post-perspective space onto the shadow map square that spends most texels
// near the eye. Pure math, no GL.
//
// Conventions
// - "Light NDC" is the light's post-perspective space: clip = lightViewProj * world, ndc = clip /
//   clip.w; the shadow map covers x, y in [-1, 1].
// - N_T acts on light *clip* coordinates: trapezoidClip = nt * lightViewProj * world.
// - The top line (near the eye, short edge) maps to y = +1 and the base line (far) to y = -1, as
//   in the paper, so the 80% rule reads literally: the focus point maps to y = xi (-0.6 by
//   default) and the focus region covers (1 - xi) / 2 = 80% of the map's rows.
// - The map preserves orientation (positive Jacobian determinant), so face culling in the
//   shadow pass keeps working.
// - Depth: N_T's z row is zero, so trapezoid-space z is 0 and never depth-clipped. A projective
//   map cannot both warp x, y and leave z / w unchanged (that would need z * w_T / w, which is
//   not linear), and the renderer compares depths in the light's post-perspective space anyway:
//   write z_light / w_light (from lightViewProj alone) as the stored depth and look it up the
//   same way.
//
// Degenerate cases and the blend
// The trapezoid needs a well-defined centre line and a frustum in front of the light. Two
// measures, both continuous in the configuration, weigh the trapezoid against a focused uniform
// map U (the axis-aligned bounding box of the clipped hull mapped to [-1, 1]^2):
// - r: the length of the projected centre line over the hull's larger bounding-box side. It
//   goes to 0 when the light travels (nearly) along the view direction, including a light behind
//   the camera shining forward. Weight smoothstep(rLow, rHigh, r).
// - wRel: the smallest corner w over the largest |w| (1 for orthographic lights). It goes to 0
//   as the eye frustum reaches the plane through a perspective light's centre (eye inside the
//   light's near plane, light behind part of the frustum). Weight smoothstep(0, wBand, wRel).
// An eye between a perspective light and its near plane (w > 0, z < -w) is not degenerate for
// x, y: only depth would be clipped, and depth does not go through N_T. When the light sees none
// of the frustum, nt is the identity map of the whole square (z row zero), weight 0.
// nt = (1 - t) * U + t * T with t the product of both weights. Both maps are normalised so that
// w > 0 on the hull, hence every blended image is a convex combination of two points in the
// square and stays inside it. degenerate is true whenever t < 1; the matrix is always finite.
//
// Stability
// The paper's fit is a continuous function of the camera, so its texels slide over the scene
// whenever the camera moves and shadow edges shimmer. Three optional measures, all off (0) by
// the paper's fit, make the map change in steps instead:
// - quantize: every parameter moves in steps of this size in its own unit: the centre line's
//   angle (radians), its lateral position, the top, base and focus lines (light NDC, where the
//   map spans 2), the side lines' slopes and the blend weight. Extents round outwards, so the
//   frustum's hull stays inside. Stateless: the same camera always gives the same map.
// - snapTexels: the positional parameters snap to multiples of this many texels of a mapSize
//   map (light NDC), as cascaded shadow maps snap their translation. With quantize too, the
//   positional step is quantize rounded to whole multiples of that.
// - hysteresis: given the previous frame's fit, keep it unchanged while it still holds the
//   hull, the new focus point maps within 2 * hysteresis of xi, the hull spans at least
//   1 - 2 * hysteresis of the map on each axis, the centre line turned by at most
//   hysteresis * 90 degrees and the blend weight moved by at most hysteresis. A refit is fitted
//   to the hull scaled by 1 + hysteresis about its centre so that it can be kept a while.

#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace fl::geom {

/// Tuning for fitTrapezoid; the defaults follow the paper where it gives values.
struct TrapezoidParams {
    /// Focus distance delta as a fraction of the eye frustum depth (near plane = 0, far = 1).
    /// The 80% rule is only satisfiable while the focus point lies within (1 - xi) / 2 of the
    /// trapezoid height; beyond that eta is capped and the trapezoid tends to a rectangle.
    float focusFraction = 0.5f;
    /// Where the focus point lands on the map's y axis (paper: -0.6, i.e. the 80% rule).
    float xi = -0.6f;
    /// Centre-line ratio below which the map is fully uniform and above which fully TSM.
    float rLow = 0.05f;
    float rHigh = 0.15f;
    /// wRel band over which a perspective light fades from uniform to TSM.
    float wBand = 0.05f;
    /// Stability, see the header comment; 0 turns each off (the paper's fit, every frame).
    float quantize = 0.0f;
    float snapTexels = 0.0f;
    float hysteresis = 0.0f;
    /// Texels per side of the map the fit is for (snapTexels' unit).
    int mapSize = 1024;
};

/// The result of a trapezoid fit; 2D quantities are in light NDC.
struct TrapezoidFit {
    glm::mat4 nt{1.0f};                 ///< light clip space -> trapezoid (shadow map) clip space
    bool degenerate = true;             ///< true when the uniform fallback has any weight
    float weight = 0.0f;                ///< 1 = pure trapezoid, 0 = pure uniform fallback
    std::array<glm::vec2, 4> corners{}; ///< maps to (-1,+1), (+1,+1), (+1,-1), (-1,-1)
    std::vector<glm::vec2> hull;        ///< projected frustum clipped to [-1,1]^2, CCW
    glm::vec2 nearCenter{0.0f};         ///< projected centre of the eye's near plane
    glm::vec2 farCenter{0.0f};          ///< projected centre of the eye's far plane
    glm::vec2 focusPoint{0.0f};         ///< projected focus point p_L
    glm::vec2 q{0.0f};                  ///< projection point (apex of the side lines)
    float lambda = 0.0f;                ///< distance between top and base lines
    float deltaPrime = 0.0f;            ///< distance from the top line to the focus point
    float eta = 0.0f;                   ///< distance from q to the top line
    float centerLineRatio = 0.0f;       ///< r, see the header comment
    float wRel = 0.0f;                  ///< see the header comment
    glm::vec2 axis{0.0f, 1.0f};         ///< u: the centre line's direction, near to far
    bool held = false;                  ///< hysteresis kept the previous fit's map
};

/// Convex hull of 2D points (Andrew's monotone chain), counter-clockwise, no collinear points.
std::vector<glm::dvec2> convexHull2d(std::vector<glm::dvec2> points);

/// Clips a convex CCW polygon to the square [-1,1]^2 (Sutherland-Hodgman); may return empty.
std::vector<glm::dvec2> clipToSquare(const std::vector<glm::dvec2>& polygon);

/// The 8 corners of the eye frustum (NDC cube through eyeViewProjInverse) in light clip space;
/// index bits: 1 = +x, 2 = +y, 4 = far plane.
std::array<glm::dvec4, 8> projectFrustumCorners(const glm::dmat4& lightViewProj,
                                                const glm::dmat4& eyeViewProjInverse);

/// Fits the TSM trapezoid to the eye frustum seen from the light and returns N_T; never NaN.
/// Takes double matrices: the inverse of the eye matrix loses enough precision in float to make
/// the fit jitter by a fraction of a texel between nearly identical cameras. `previous` (the
/// last frame's fit with the same light and params, or null) is read only with hysteresis.
TrapezoidFit fitTrapezoid(const glm::dmat4& lightViewProj, const glm::dmat4& eyeViewProjInverse,
                          const TrapezoidParams& params = {},
                          const TrapezoidFit* previous = nullptr);

/// The checks hysteresis keeps `previous` by (see the header comment), for the fresh fit `fresh`
/// of the current frame: true when previous's map may stay.
bool keepsPreviousFit(const TrapezoidFit& previous, const TrapezoidFit& fresh, float hysteresis);

} // namespace fl::geom
