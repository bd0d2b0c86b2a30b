#pragma once
// The shadow terminator of smooth-shaded low-poly objects: a triangle whose plane faces away from
// the light while the normals interpolated across it (the smooth surface the shading sees) face
// it. Rays that leave the flat triangle find such points dark (the plane blocks them, or the
// neighbouring triangles do), where shading and every shadow map light them. Production ray
// tracers start the shadow ray on the smooth surface instead: Hanika, "Hacking the Shadow
// Terminator", Ray Tracing Gems II ch. 4 (2021); Cycles' "Geometry Offset", Arnold's
// shadow_terminator_fix.

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

} // namespace fl::rt
