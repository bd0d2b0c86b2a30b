#version 450 core
// Shadow-map diagnostics per visible pixel (see renderer/passes/ShadowDiagnosticsPass.h):
// texel footprint, view depth, hard visibility with this and the previous frame's map.
#include "shadow_lookup.glsl"
#include "light.glsl"

layout(binding = 3) uniform sampler2D uPosition; // SurfacesPass: world xyz, w = 0 background
layout(binding = 4) uniform sampler2D uNormal;   // SurfacesPass: shading normal facing the eye

layout(location = 0) out vec4 oDiagnostics;

layout(binding = 2) uniform sampler2DShadow uPreviousShadowMap;
uniform mat4 uPreviousLightViewProj;
uniform mat4 uPreviousShadowWarp;
uniform int uHasPrevious;
uniform float uShadowMapSize;
uniform mat4 uView;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 surface = texelFetch(uPosition, pixel, 0);
    vec3 vWorld = surface.xyz;
    // Texel coordinates up to a constant offset, computed in uniform control flow so the
    // derivatives are defined (between neighbouring pixels' surface points: within a surface the
    // same as the rasteriser's); the guard on w only keeps helper values finite.
    vec4 map = uShadowWarp * uLightViewProj * vec4(vWorld, 1.0);
    vec2 texel = map.xy / max(map.w, 1e-30) * (0.5 * uShadowMapSize);
    vec2 dx = dFdxFine(texel), dy = dFdyFine(texel);
    float det = abs(dx.x * dy.y - dx.y * dy.x); // shadow texels per screen pixel, as an area

    vec3 uvz;
    bool inMap = shadowCoord(vWorld, uvz);
    // Receivers are surfaces that face the light (as shaded: two-sided, interpolated normal):
    // on the others Lambert shading is zero, so the shadow map's texels there never show.
    vec3 n = texelFetch(uNormal, pixel, 0).xyz;
    vec3 l = toLight(vWorld);
    bool receiver = surface.w != 0.0 && inMap && dot(n, l) > 0.0;
    bool valid = receiver && !isnan(det) && !isinf(det);
    // Capped at 1e6 pixels per texel (a surface seen exactly edge-on) to stay finite.
    float footprint = valid ? min(inversesqrt(max(det, 1e-12)), 1e6) : 0.0;
    float visibility = inMap ? texture(uShadowMap, uvz) : 1.0;
    float previous = visibility;
    if (uHasPrevious != 0) {
        vec3 p;
        previous = shadowCoordWith(uPreviousLightViewProj, uPreviousShadowWarp, vWorld, p)
                       ? texture(uPreviousShadowMap, p)
                       : 1.0;
    }
    // Background keeps the old clear value: no footprint, no depth, lit.
    oDiagnostics = surface.w == 0.0
                       ? vec4(0.0, 0.0, 1.0, 1.0)
                       : vec4(footprint, -(uView * vec4(vWorld, 1.0)).z, visibility, previous);
}
