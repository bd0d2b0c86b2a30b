#version 450 core
// JFA-E, for the object-ID fix (thesis §5.4.2): the object id of the surface the light's centre
// sees at each shadow-map texel. Drawn over the finished shadow map with depth test LEQUAL and
// no depth writes, so only the fragment that won the shadow pass (or an exact tie) writes. For
// that the depth must be bit-identical to the shadow pass's: the same vertex stage
// (shadow_depth.vert.glsl) and the same function (depth_bias.glsl).
#include "alpha_coverage.glsl"
#include "depth_bias.glsl"

in vec2 vLightZW;
in vec3 vWorld;
in vec2 vTexcoord;
in float vAlpha;

layout(location = 0) out float oObjectId;

uniform int uObjectId;

void main() {
    discardCutOut(vTexcoord, vAlpha);
    gl_FragDepth = biasedLightDepth(vLightZW);
    oObjectId = float(uObjectId);
}
