#version 450 core
#include "bindings.glsl"
// Band-limited flooding, step A0: the seed texels in a list (packed x | y << 16), so that step A
// (jfa_band_reach.comp.glsl) bounds only seeds. On a SIMD rasteriser every 8-lane row holding
// one seed would otherwise pay for the criterion's bound in all its lanes: 21 of the 28 ms of
// the band on JFA-L's 1024^2 map went there. uMode 1 (one invocation) turns the count into
// step A's indirect dispatch.

#include "jfa_seed_list.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

bool jfaEmpty(vec4 c);
vec4 jfaLoad(sampler2D grid, ivec2 q);

layout(binding = FL_TEX_FLOOD_SEEDS) uniform sampler2D uSeeds;
uniform ivec2 uSize;
uniform int uMode;

void main() {
    if (uMode == 1) {
        dispatch[0] = (seedCount + 63u) / 64u;
        dispatch[1] = 1u;
        dispatch[2] = 1u;
        return;
    }
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uSize)) || jfaEmpty(jfaLoad(uSeeds, p))) return;
    jfaListSeed(p);
}
