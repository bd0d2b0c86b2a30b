#pragma once
// Where, on a flooded grid, an occluder point can cast a penumbra: the bound that band-limited
// flooding (jfa/Band.h) and `--jfa-passes auto` use for JFA-L and JFA-E.
//
// A receiver p takes occluder o only if the ray p -> o meets the light's disk (occluderHit), so
// p lies in the cone of rays from the disk through o, beyond o. Receivers lie no deeper (distance
// from the light's plane) than the scene's farthest point D, so the cone's part that can hold one
// is inside the pyramid with apex o and, as base, the square around the disk the cone cuts at
// depth D (centre o + t (o - c), half-side t r, t = (D - d_o) / d_o). A projective map keeps
// convex hulls while w > 0, so the texel bounds of the five projected corners hold every texel
// that can accept o; a corner behind the projection (w <= 0) bounds nothing. Margins (1% on t and
// r, 2 texels) cover float rounding in the criterion.
//
// Measured and not kept: clipping the pyramid by the scene's box and the view volume before
// projecting (11 planes, Sutherland-Hodgman per face) halves the light-space band (22% -> 11%
// of a 1024^2 map) and bounds the eye-space cones that pass behind the camera, but costs ~50x
// more per seed on llvmpipe: the seed pass went from ~5 to ~300 ms (docs/BENCHMARKS.md).

#include <renderer/soft/DiskLight.h>

#include <gpu/Program.h>
#include <jfa/Band.h>

#include <geometry/Aabb.h>

#include <glm/glm.hpp>

namespace fl {

/// The grid a penumbra is bounded on.
struct PenumbraReach {
    bool enabled = false;        // false: no bound (the plan's reach decides)
    glm::mat4 worldToClip{1.0f}; // world -> the grid's clip space (texel = (ndc / 2 + 1/2) size)
    glm::ivec2 size{0};          // grid texels
    float farDepth = 0.0f;       // deepest receiver's distance from the light's plane
};

/// The deepest point of `bounds` measured from the light's plane (either side), with a margin.
float farthestLightDepth(const DiskLight& light, const geom::Aabb& bounds);

/// The bound for a grid seen through `worldToClip` at `size`, receivers within `bounds`.
PenumbraReach penumbraReach(const DiskLight& light, const glm::mat4& worldToClip, glm::ivec2 size,
                            const geom::Aabb& bounds);

/// The texels that can take occluder `o` (see the header comment); unbounded when nothing bounds
/// it. shaders/disk_light.glsl's penumbraRect() computes the same in float; both are
/// conservative and need not agree to the texel.
jfa::ReachRect penumbraReachRect(const DiskLight& light, const PenumbraReach& reach, glm::vec3 o);

/// Sets the uReach* uniforms of shaders/disk_light.glsl.
void setPenumbraReachUniforms(const gl::Program& program, const PenumbraReach& reach);

} // namespace fl
