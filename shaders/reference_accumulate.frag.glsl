#version 450 core
#include "bindings.glsl"
// Ground truth, one disk sample: the hard visibility of each eye pixel's surface from this
// sample's depth map (the same test as every method's hardShadow()), added to the sum by
// additive blending.
#include "shadow_lookup.glsl"
#include "surface_decode.glsl"
#include "surface_lookup.glsl"

// SurfacesPass: positions (surfacePosition)
layout(binding = FL_TEX_SURFACES_DEPTH) uniform sampler2D uDepth;

layout(location = 0) out float oLit;

void main() {
    vec4 p = surfacePosition(uDepth, ivec2(gl_FragCoord.xy));
    if (p.w == 0.0) discard;
    ivec2 t = ivec2(gl_FragCoord.xy);
    oLit = hardShadow(shadowNormalOffset(surfaceLookupPoint(p.xyz, t), surfaceLookupPlane(t)));
}
