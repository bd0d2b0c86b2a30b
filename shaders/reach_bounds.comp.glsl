#version 450 core
#include "bindings.glsl"
// The receivers' bounds pyramid of the penumbra bound (renderer/soft/PenumbraReach.h): level 0
// holds, per 8x8 block of the flooded grid, the box of its receivers' world positions (xyz) and
// their range of distances from the light's plane (w): the smallest in uDstLo, the largest in
// uDstHi (lo = 1e30, hi = -1e30 where there is none). Level L + 1 bounds 2x2 cells of level L
// (the last cell of an odd level: 3 cells). uMode 0 builds level 0 from the receiver positions,
// 1 one level from the one below. With MAP_RECEIVERS the source is the shadow map's receiver
// target (positions through mapReceiver), with EYE_CELLS JFA-E's packed eye cells (positions
// through eyePoint), else a texture of positions.
#include "disk_light.glsl"
#if defined(MAP_RECEIVERS) || defined(EYE_CELLS)
#include "shadow_map_decode.glsl"
#endif
#ifdef EYE_CELLS
#include "occluder_edge.glsl"
#include "surface_decode.glsl"
#include "eye_decode.glsl"
#endif

layout(local_size_x = 8, local_size_y = 8) in;

// xyz world position, w the receiver flag
layout(binding = FL_TEX_REACH_POSITIONS) uniform sampler2D uPositions;
layout(binding = FL_IMG_REACH_LO_OUT, rgba32f) uniform writeonly image2D uDstLo;
layout(binding = FL_IMG_REACH_HI_OUT, rgba32f) uniform writeonly image2D uDstHi;
layout(binding = FL_IMG_REACH_LO_IN, rgba32f) uniform readonly image2D uSrcLo;
layout(binding = FL_IMG_REACH_HI_IN, rgba32f) uniform readonly image2D uSrcHi;
uniform int uMode;
uniform float uValidMin; // a receiver has w >= uValidMin
uniform ivec2 uDstSize;
uniform ivec2 uSrcSize;
// With REACH_REGION (--flood-region view): receivers outside the seed region's tiles (one uint
// per tile of side uRegionTile, a multiple of 8, so a block lies in one tile) do not count.
#ifdef REACH_REGION
uniform int uRegionTile;
uniform int uRegionTilesX;
layout(std430, binding = FL_SSBO_SEED_REGION) readonly buffer SeedRegion { uint seedRegion[]; };
#endif

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, uDstSize))) return;
    vec4 lo = vec4(1e30), hi = vec4(-1e30);
    bool counted = true;
#ifdef REACH_REGION
    ivec2 region = t * 8 / uRegionTile;
    counted = uMode != 0 || seedRegion[region.y * uRegionTilesX + region.x] != 0u;
#endif
    if (!counted) {
        // no receiver of this block counts
    } else if (uMode == 0) {
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i) {
                ivec2 q = t * 8 + ivec2(i, j);
                if (any(greaterThanEqual(q, uSrcSize))) continue;
#if defined(MAP_RECEIVERS)
                vec4 p = mapReceiver(uPositions, q);
#elif defined(EYE_CELLS)
                vec4 p = eyePoint(q);
#else
                vec4 p = texelFetch(uPositions, q, 0);
#endif
                if (p.w >= uValidMin) {
                    vec4 v = vec4(p.xyz, abs(dot(p.xyz - uDiskCenter, uDiskNormal)));
                    lo = min(lo, v);
                    hi = max(hi, v);
                }
            }
    } else {
        // GL's mip sizes halve rounding down, so the last cell of a level also takes the odd
        // cell left over below it (a cell is never lost; the query clamps to the last cell).
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) {
                ivec2 q = t * 2 + ivec2(i, j);
                bool take = all(lessThan(q, uSrcSize)) && (i < 2 || t.x == uDstSize.x - 1) &&
                            (j < 2 || t.y == uDstSize.y - 1);
                if (take) {
                    lo = min(lo, imageLoad(uSrcLo, q));
                    hi = max(hi, imageLoad(uSrcHi, q));
                }
            }
    }
    imageStore(uDstLo, t, lo);
    imageStore(uDstHi, t, hi);
}
