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
// On the GPU, D is the deepest receiver on the grid, and the first rect is then split along a
// pyramid of the receivers' bounds (ReceiverBoundsPyramid; shaders/disk_light.glsl,
// penumbraRect): at most 8 x 8 cells of the rect, then two finer levels under the cells kept.
// A cell is dropped when its receivers all lie above o, or when the box of their world positions
// misses the cone (a right circular cone around the axis c -> o of half-angle asin(r / |o - c|)
// holds every ray from the disk through o); a kept finest cell adds its texels that the cone's
// part between the cell's receiver depths covers. Every receiver that can take o lies in the
// cone and in the box of each cell above it, so its cell is kept. The CPU bound (the tests'
// reference) stops at the scene's D: both are conservative, so the floods agree whatever rect
// each one draws. JFA-L's 1024^2 map: band 22% (scene D) -> 9.2% (deepest receiver per rect) ->
// 6.0% of the texels (cells); JFA-E's 512^2 frame: 69% -> 55%.
//
// Measured and not kept (docs/BENCHMARKS.md): clipping the pyramid by the scene's box and the
// view volume before projecting (11 planes, Sutherland-Hodgman per face) also halved the band,
// but made the seed pass ~400 ms on llvmpipe; three rounds of the depth cut instead of one gave
// 10.7% instead of 12.5% and a slower flood; 4 x 4 first cells instead of 8 x 8 gave the same
// JFA-L band (6.1%) and a wider JFA-E one (58%).

#include <renderer/passes/ShadowMapPass.h>
#include <scene/DiskLight.h>
#include <scene/Pose.h>
#include <scene/Scene.h>

#include <gpu/BindScope.h>
#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>
#include <jfa/Band.h>

#include <base/Aabb.h>
#include <base/Framing.h>

#include <glm/glm.hpp>

#include <optional>

namespace fl {

struct EyeCells; // renderer/soft/EyeDecode.h

/// The grid a penumbra is bounded on.
struct PenumbraReach {
    bool enabled = false;        // false: no bound (the plan's reach decides)
    glm::mat4 worldToClip{1.0f}; // world -> the grid's clip space (texel = (ndc / 2 + 1/2) size)
    glm::ivec2 size{0};          // grid texels
    float farDepth = 0.0f;       // deepest receiver's distance from the light's plane
    /// GPU only: the receivers' bounds pyramid (ReceiverBoundsPyramid: its two textures and
    /// level count; 0 = none). The shaders keep only the cells whose receivers the cone can hold.
    GLuint boundsLo = 0, boundsHi = 0;
    int boundsLevels = 0;
    /// Pyramid cells per axis a rect is first split into (then two finer levels under the cells
    /// kept): more cut the rects closer and cost more per seed. 4 was the cheapest frame for
    /// JFA-L, and for JFA-E once its passes run within the flood's front, which absorbs the
    /// looser band (docs/history/soft-shadows.md, "Band-limited flooding, fourth and fifth
    /// parts").
    int firstCells = 4;
};

/// The receivers' bounds pyramid of the GPU bound (shaders/reach_bounds.comp.glsl): per 8x8
/// block of the flooded grid the box of its receivers' world positions and their range of
/// distances from the light's plane, then the bounds of 2x2 cells up to one texel. Receivers lie
/// in the grid itself (JFA-L: shadow-map texels; JFA-E: eye pixels), so a cell whose box the cone
/// of an occluder misses holds no texel that can take it.

class ReceiverBoundsPyramid {
  public:
    explicit ReceiverBoundsPyramid(const gl::ShaderLibrary& shaders);
    /// Builds it from receiver positions (texels with w >= validMin are receivers) and stores
    /// it in `reach` (boundsLo, boundsHi, boundsLevels). With `region` (one uint per tile of
    /// side `regionTile`, a multiple of 8, row-major), receivers outside its tiles do not count.
    void build(const gl::Texture& positions, float validMin, const DiskLight& light,
               PenumbraReach& reach, const gl::Buffer* region = nullptr, int regionTile = 8);
    /// The same from JFA-E's packed eye cells (eyePoint; every surface pixel is a receiver).
    void build(const EyeCells& eye, const DiskLight& light, PenumbraReach& reach);
    /// The same from the shadow map's receiver target (positions decoded in the shader).
    void build(const MapPositions& map, const DiskLight& light, PenumbraReach& reach,
               const gl::Buffer* region = nullptr, int regionTile = 8);
    /// Bytes one build() writes: both pyramids, every level (0 before the first build).
    [[nodiscard]] std::int64_t bytes() const;

  private:
    void build(gl::BindScope& scope, const gl::Program& program, int width, int height,
               float validMin, const DiskLight& light, PenumbraReach& reach,
               const gl::Buffer* region, int regionTile);
    // [source: positions, map, eye cells][seed region]: MAP_RECEIVERS decodes the shadow map's
    // receiver target, EYE_CELLS JFA-E's cells, REACH_REGION limits the receivers to a seed
    // region's tiles.
    gl::Program programs_[3][2];
    gl::Texture lo_, hi_; // min and max: xyz world position, w distance from the light's plane
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

/// The nearest the scene's surfaces come to the light in `pose`: along the disk's normal from
/// its plane (.x), and along `axis` from its centre (.y). Every vertex's, since a surface point is
/// a convex combination of its triangle's vertices and both depths are linear.
glm::vec2 nearestLightDepths(const Scene& scene, const Pose& pose, const DiskLight& light,
                             glm::vec3 axis);

/// A bound, in texels per axis, on how far from its seed's texel an occluder can cast a penumbra
/// on a size^2 map made through `lightVolume` (PenumbraReach's rects, the CPU's and the GPU's,
/// never reach farther), given the occluders' nearest depths (nearestLightDepths) and the
/// receivers' farthest (farthestLightDepth): what --flood-region view needs to know which seeds
/// can shade what the view sees without finding every seed. Only for a perspective volume whose
/// eye is the disk's centre (a point or spot light's uniform map; not TSM's warp, nor a
/// directional light's orthographic volume) with the occluders in front of the light's plane;
/// nullopt otherwise, or when the disk is too wide for the bound to mean anything.
///
/// Why it holds: the rect is the texel box of o and of the corners capCentre +- u +- v, where
/// capCentre = o + t (o - c) lies on o's ray from the eye c (o's texel) at view depth (1 + t) z_o,
/// t = 1.01 (D - d_o) / d_o + 0.001, and the corners lie within 1.01 t r along the map's axes
/// and the view axis, per vector (|u.e| + |v.e| for unit vectors u, v and axis e). Moving a
/// point at view depth z by (dx, dz) moves its projection by at most P00 (|dx| + tanHalf |dz|) /
/// (z - |dz|), since |x / z| <= tanHalf inside the map; t / (1 + t) grows as d_o shrinks, so the
/// nearest depths give the widest rect. 6 texels cover the rects' 2-texel margins, their
/// rounding and the seed's own texel.
std::optional<long long> widestPenumbraTexels(const DiskLight& light,
                                              const geom::ViewVolume& lightVolume, int size,
                                              glm::vec2 nearest, float farDepth);

/// Sets the uReach* uniforms of shaders/disk_light.glsl and binds the bounds in `scope`.
void setPenumbraReachUniforms(gl::BindScope& scope, const gl::Program& program,
                              const PenumbraReach& reach);
/// Binds the uniforms setPenumbraReachUniforms sets on `program`.
void bindPenumbraReachUniforms(gl::Program& program);

} // namespace fl
