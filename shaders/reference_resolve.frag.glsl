#version 450 core
#include "bindings.glsl"
// Ground truth, resolve: lit samples / N (1 for background). Sums of 0 and 1 are exact in
// float, so a pixel lit from every sample gets exactly 1.
#include "surface_decode.glsl"

layout(binding = FL_TEX_REFERENCE_SUM) uniform sampler2D uSum;
// SurfacesPass: positions (surfacePosition)
layout(binding = FL_TEX_REFERENCE_SURFACES_DEPTH) uniform sampler2D uDepth;
uniform float uSamples;

layout(location = 0) out float oVisibility;

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
    bool surface = surfacePosition(uDepth, t).w != 0.0;
    oVisibility = surface ? texelFetch(uSum, t, 0).r / uSamples : 1.0;
}
