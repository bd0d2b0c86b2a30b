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
// On the GPU, D is first the deepest receiver on the grid, and the cone is then cut again at the
// deepest receiver inside that first rect, read from a depth pyramid of the receivers
// (ReceiverDepthPyramid): every receiver that can take o lies in the rect, so none is deeper.
// On JFA-L's 1024^2 map this took the band from 22% to 12.5% of the texels. The CPU bound (the
// tests' reference) stops at the scene's D: both are conservative, so the floods agree whatever
// rect each one draws.
//
// Measured and not kept (docs/BENCHMARKS.md): clipping the pyramid by the scene's box and the
// view volume before projecting (11 planes, Sutherland-Hodgman per face) also halved the band,
// but made the seed pass ~400 ms on llvmpipe; three rounds of the depth cut instead of one gave
// 10.7% instead of 12.5% and a slower flood.

#include <renderer/soft/DiskLight.h>

#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>
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
    /// GPU only: the receivers' depth pyramid (ReceiverDepthPyramid) and its level count; 0 =
    /// none. The shaders cut each cone again at the deepest receiver inside its first rect.
    GLuint depthPyramid = 0;
    int depthLevels = 0;
};

/// The receivers' depth pyramid of the GPU bound (shaders/reach_depth.comp.glsl): per 8x8 block
/// of the flooded grid the deepest receiver (distance from the light's plane), then 2x2 maxima
/// up to one texel. Receivers lie in the grid itself (JFA-L: shadow-map texels; JFA-E: eye
/// pixels), so the deepest one in a rect bounds every receiver that can take an occluder there.
class ReceiverDepthPyramid {
  public:
    explicit ReceiverDepthPyramid(const gl::ShaderLibrary& shaders);
    /// Builds it from receiver positions (texels with w >= validMin are receivers) and stores
    /// it in `reach` (depthPyramid, depthLevels).
    void build(const gl::Texture& positions, float validMin, const DiskLight& light,
               PenumbraReach& reach);

  private:
    gl::Program program_;
    gl::Texture pyramid_;
    int levels_ = 0;
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
