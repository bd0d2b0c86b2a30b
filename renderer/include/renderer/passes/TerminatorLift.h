#pragma once
// The surfaces pass's lift (shaders/terminator.glsl, operation for operation): how far every
// shadow-map lookup moves a pixel's point along its shading normal, so that near the terminator
// of a smooth-shaded low-poly body the map is read from the smooth surface the vertex normals
// describe (Hanika's offset, by Cycles' geometry-offset amount) as the ray-traced truth's rays
// start there (raytrace/Terminator.h). The GLSL file says why.

#include <raytrace/Terminator.h>

#include <glm/glm.hpp>

#include <array>

namespace fl::surface {

/// Cycles' geometry offset (its default, the ray-traced truth's): the range of cos(angle to the
/// light) the lift fades in over.
inline constexpr float kTerminatorOffset = rt::kGeometryOffset;

/// A triangle's vertex normals as tangent planes (unit n, n . a) and its plane on their side;
/// all zero where the lift is 0 (degenerate, a zero normal, or flat within 1e-6).
struct TangentPlanes {
    std::array<glm::vec4, 3> planes{};
    glm::vec3 front{0.0f};
};
TangentPlanes terminatorPlanes(const std::array<glm::vec3, 3>& corner,
                               const std::array<glm::vec3, 3>& normals);

/// Hanika's move of p (barycentric weights w) onto the smooth surface seen from `side`.
glm::vec3 terminatorMove(glm::vec3 p, glm::vec3 w, const TangentPlanes& t, glm::vec3 side);

/// The share of the move that applies: `nl` and `ngl` the shading normal's and the plane's cos
/// to the light (the truth's rule, rt::offsetAmount).
float terminatorAmount(float nl, float ngl);

/// The lift of point p of the triangle (weights w) whose shading normal (facing the eye) is n and
/// whose plane on that side is `plane`, lit from direction l (unit, towards the light).
float terminatorLift(glm::vec3 p, glm::vec3 w, const TangentPlanes& t, glm::vec3 n, glm::vec3 plane,
                     glm::vec3 l);

/// The normal offset's share of a texel (shaders/normal_offset.glsl says why a quarter).
inline constexpr float kNormalOffsetTexels = 0.25f;

/// The world size of a texel of a `size`-texel map made with `mapViewProj` at `world`
/// (mapTexelWorld() in normal_offset.glsl).
float mapTexelWorld(glm::vec3 world, const glm::mat4& mapViewProj, float size);

/// `world` moved off its surface (normal n) by the normal offset, `toLight` unit towards the
/// light (normalOffset() in normal_offset.glsl).
glm::vec3 normalOffset(glm::vec3 world, glm::vec3 n, glm::vec3 toLight,
                       const glm::mat4& mapViewProj, float size);

} // namespace fl::surface
