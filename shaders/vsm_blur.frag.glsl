#version 450 core
#include "bindings.glsl"
// VSM step 2: one direction of the separable box blur of the moments (2r + 1 taps; edge texels
// repeat). Averaging moments is what makes VSM's shadows soft: a blurred map holds the mean and
// variance of the occluder depths around each texel.
layout(binding = FL_TEX_VSM_BLUR_IN) uniform sampler2D uMoments;
uniform ivec2 uDirection; // (1, 0) or (0, 1)
uniform int uRadius;

layout(location = 0) out vec2 oMoments;

void main() {
    ivec2 size = textureSize(uMoments, 0);
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 sum = vec2(0.0);
    for (int i = -uRadius; i <= uRadius; ++i)
        sum += texelFetch(uMoments, clamp(p + i * uDirection, ivec2(0), size - 1), 0).rg;
    oMoments = sum / float(2 * uRadius + 1);
}
