#version 450 core
#include "bindings.glsl"
// Jump-flooding kernel, fragment version: one full-screen triangle per pass into the
// write texture of the ping-pong pair. uMode: 0 = pass (expand then pass in the JFA_EXPAND
// build; uSrc is then the half-resolution grid), 2 = downsample full-resolution seeds.
#include "jfa_select.glsl"

layout(binding = FL_TEX_FLOOD_IN) uniform sampler2D uSrc;
// full-resolution seeds (for the expansion)
layout(binding = FL_TEX_FLOOD_SEEDS) uniform sampler2D uSeeds;
uniform ivec2 uSize;    // grid size of the stage written
uniform ivec2 uSrcSize; // grid size of uSrc
uniform int uStep;
uniform int uScale;
uniform int uMode;
uniform int uCountChanges;
layout(binding = FL_ATOMIC_CHANGED, offset = 0) uniform atomic_uint uChanged;

layout(location = 0) out vec4 oCell;

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
    vec4 before;
    vec4 result = jfaTexel(uSrc, uSeeds, t, uSize, uSrcSize, uStep, uScale, uMode, before);
    if (uCountChanges != 0 && result != before) atomicCounterIncrement(uChanged);
    oCell = jfaStore(result);
}
