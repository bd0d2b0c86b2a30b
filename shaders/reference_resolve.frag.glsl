#version 450 core
// Ground truth, resolve: lit samples / N (1 for background). Sums of 0 and 1 are exact in
// float, so a pixel lit from every sample gets exactly 1.
#include "surface_decode.glsl"

layout(binding = 0) uniform sampler2D uSum;
layout(binding = 1) uniform sampler2D uDepth; // SurfacesPass: positions (surfacePosition)
uniform float uSamples;

layout(location = 0) out float oVisibility;

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
    bool surface = surfacePosition(uDepth, t).w != 0.0;
    oVisibility = surface ? texelFetch(uSum, t, 0).r / uSamples : 1.0;
}
