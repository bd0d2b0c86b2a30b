#version 450 core
#include "bindings.glsl"
// VSM step 3 (Donnelly & Lauritzen 2006): per pixel of the frame's surfaces, Chebyshev's upper
// bound on the lit fraction from the blurred moments at its texel, with light-bleeding reduction
// (Lauritzen 2007: the bound's tail below uBleed is cut and the rest rescaled).
#include "shadow_lookup.glsl"
#include "surface_decode.glsl"
#include "surface_lookup.glsl"

// SurfacesPass: positions (surfacePosition)
layout(binding = FL_TEX_SURFACES_DEPTH) uniform sampler2D uDepth;
layout(binding = FL_TEX_VSM_MOMENTS) uniform sampler2D uMoments;  // blurred (d, d^2), bilinear
uniform mat4 uLightView;
uniform float uBleed;
uniform float uMinVariance; // relative: variance floor (uMinVariance * d)^2

layout(location = 0) out float oVisibility;

float chebyshev(vec2 m, float t) {
    if (t <= m.x) return 1.0;
    float variance = max(m.y - m.x * m.x, (uMinVariance * t) * (uMinVariance * t));
    float d = t - m.x;
    float p = variance / (variance + d * d);
    return clamp((p - uBleed) / (1.0 - uBleed), 0.0, 1.0);
}

void main() {
    vec4 world = surfacePosition(uDepth, ivec2(gl_FragCoord.xy));
    world.xyz = shadowNormalOffset(surfaceLookupPoint(world.xyz, ivec2(gl_FragCoord.xy)),
                                   surfaceLookupPlane(ivec2(gl_FragCoord.xy)));
    vec3 uvz;
    if (world.w == 0.0 || !shadowCoord(world.xyz, uvz)) {
        oVisibility = 1.0;
        return;
    }
    float t = -(uLightView * vec4(world.xyz, 1.0)).z;
    oVisibility = chebyshev(texture(uMoments, uvz.xy).rg, t);
}
