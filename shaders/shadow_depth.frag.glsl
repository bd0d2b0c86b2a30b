#version 450 core
// Writes the light's post-perspective depth plus the depth bias (depth_bias.glsl), and the
// world position for the receiver-position target that JFA-L floods over.
#include "alpha_coverage.glsl"
#include "depth_bias.glsl"

in vec2 vLightZW;
in vec3 vWorld;
in vec2 vTexcoord;
in float vAlpha;

// Receiver positions (only when the pass binds that target; otherwise discarded).
layout(location = 0) out vec4 oReceiver;

void main() {
    discardCutOut(vTexcoord, vAlpha);
    gl_FragDepth = biasedLightDepth(vLightZW);
    oReceiver = vec4(vWorld, 1.0);
}
