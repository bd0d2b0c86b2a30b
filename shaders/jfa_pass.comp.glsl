#version 450 core
#include "bindings.glsl"
// Jump-flooding kernel, compute version: the same passes as jfa_pass.frag.glsl, one invocation
// per texel, written with imageStore. Built with JFA_BAND it runs over a tile list
// (jfa_band_compact.comp.glsl) by an indirect dispatch: group x = the list entry, group y = the
// 8x8 block within the tile.
#include "jfa_select.glsl"
// JFA_CELL_FORMAT: rgba32f, or r32f for packed cells (jfa::detail::cellFormatDefine).

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = FL_TEX_FLOOD_IN) uniform sampler2D uSrc;
// full-resolution seeds (for the expansion)
layout(binding = FL_TEX_FLOOD_SEEDS) uniform sampler2D uSeeds;
layout(binding = FL_IMG_FLOOD_OUT, JFA_CELL_FORMAT) uniform writeonly image2D uDst;
uniform ivec2 uSize;
uniform ivec2 uSrcSize;
uniform int uStep;
uniform int uScale;
uniform int uMode;
uniform int uCountChanges;
layout(binding = FL_ATOMIC_CHANGED, offset = 0) uniform atomic_uint uChanged;

#ifdef JFA_BAND
#include "jfa_band_tiles.glsl"
// The flood's front (jfa_band_front.comp.glsl): one flag per tile that has held a non-empty
// cell, set here for the next pass's list when uFront is 1 (one-stage plans).
layout(std430, binding = FL_SSBO_FLOOD_FRONT) buffer Front { uint front[]; };
uniform int uFront;
uniform int uTilesX;
#endif

void main() {
#ifdef JFA_BAND
    ivec2 t = jfaBandTexel();
#else
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
#endif
    if (any(greaterThanEqual(t, uSize))) return;
    vec4 before;
    vec4 result = jfaTexel(uSrc, uSeeds, t, uSize, uSrcSize, uStep, uScale, uMode, before);
    if (uCountChanges != 0 && result != before) atomicCounterIncrement(uChanged);
    imageStore(uDst, t, jfaStore(result));
#ifdef JFA_BAND
    if (uFront != 0 && !jfaEmpty(result)) {
        ivec2 tile = jfaBandTile();
        front[tile.y * uTilesX + tile.x] = 1u;
    }
#endif
}
