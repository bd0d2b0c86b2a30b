#pragma once
// The shadow terminator of smooth-shaded low-poly objects: a triangle whose plane faces away from
// the light while the normals interpolated across it (the smooth surface the shading sees) face
// it. Rays that leave the flat triangle find such points dark (the plane blocks them, or the
// neighbouring triangles do), where shading and every shadow map light them. Production ray
// tracers start the shadow ray on the smooth surface instead: Hanika, "Hacking the Shadow
// Terminator", Ray Tracing Gems II ch. 4 (2021); Cycles' "Geometry Offset", Arnold's
// shadow_terminator_fix.
//
// Where: only where the light grazes, as Blender Cycles applies its Geometry
// Offset (offsetAmount below), so that a coarse surface that faces the light keeps its flat
// triangles' shadows; the full offset on every ray lifted a 68-triangle terrain's ray starts by
// up to 0.43 units and moved the shadows of small objects on it.

#include <glm/vec3.hpp>

#include <array>
#include <optional>

namespace fl::rt {

/// A shadow ray's start on the smooth surface: the moved point and the interpolated normal (unit,
/// on the side the point is seen from), whose tangent plane now decides which light it can see.
struct SmoothPoint {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};
};

/// Hanika's offset for the point `p` of the triangle `corner` with vertex normals `normals`
/// (unit) and Embree's barycentrics (p = (1-u-v) corner[0] + u corner[1] + v corner[2]): p is
/// projected onto each vertex's tangent plane where that moves it outward (min(dot(p - a, n_a),
/// 0)), and the three projections are blended by the barycentrics. `side` is the direction the
/// point is seen from (the receiver's plane normal); normals pointing the other way are flipped.
/// nullopt where there is no smooth surface to move to: a degenerate triangle, a normal not of
/// unit length (within 1e-3), normals that blend to zero, or every vertex
/// normal within 1e-6 (1 - cos) of the plane's normal (a flat triangle: the ray leaves the
/// triangle exactly as without the offset). A move that would go below the triangle's plane
/// (possible only where a vertex normal dips under it) is dropped: the origin never moves inward.
[[nodiscard]] std::optional<SmoothPoint> terminatorOffset(glm::vec3 p,
                                                          const std::array<glm::vec3, 3>& corner,
                                                          const std::array<glm::vec3, 3>& normals,
                                                          float u, float v, glm::vec3 side);

/// Cycles' default Geometry Offset (`shadow_terminator_geometry_offset`, per object in Blender's
/// UI): the cosine below which a ray counts as grazing.
inline constexpr float kGeometryOffset = 0.1f;

/// The share of the terminator offset one shadow ray takes, Blender Cycles' rule
/// (intern/cycles/kernel/light/sample.h, shadow_ray_offset): with c = `cutoff`, N.L = `shadingL`
/// (the smooth normal towards this ray's light point) and Ng.L = `planeL` (the triangle's),
///   amount = N.L < c ? clamp(2 - (Ng.L + N.L) / c, 0, 1) : clamp(1 - Ng.L / c, 0, 1).
/// 0 while both face the light by more than c (Cycles: 10-20% of rays are offset at c = 0.1), 1
/// once the triangle faces away (Ng.L <= 0), a ramp between. For rays the smooth surface faces
/// (N.L > 0; Cycles flips both normals for transmission, which opaque receivers have not). 0 for
/// cutoff <= 0 (Cycles' "off").
[[nodiscard]] float offsetAmount(float shadingL, float planeL, float cutoff);

} // namespace fl::rt
