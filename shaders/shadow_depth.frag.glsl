#version 450 core
// Writes the light's post-perspective depth plus the depth bias (depth_bias.glsl), and the
// unbiased NDC depth for the receiver target that JFA-L and JFA-E read positions from
// (shadow_map_decode.glsl).
#include "alpha_coverage.glsl"
#include "depth_bias.glsl"

in vec2 vLightZW;
in vec2 vTexcoord;
in float vAlpha;

// The receiver target (only when the pass binds it; otherwise discarded).
layout(location = 0) out float oReceiverDepth;

void main() {
    discardCutOut(vTexcoord, vAlpha);
    gl_FragDepth = biasedLightDepth(vLightZW);
    oReceiverDepth = vLightZW.x / vLightZW.y;
}
