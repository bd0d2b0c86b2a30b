#version 450 core
#include "bindings.glsl"
// Shadow-map diagnostics per visible pixel (see renderer/passes/ShadowDiagnosticsPass.h):
// texel footprint, view depth, hard visibility with this and the previous frame's map.
#include "shadow_lookup.glsl"
#include "light.glsl"
#include "surface_decode.glsl"

// SurfacesPass: positions (surfacePosition)
layout(binding = FL_TEX_DIAGNOSTICS_SURFACES_DEPTH) uniform sampler2D uSurfaceDepth;
// SurfacesPass: normals (surfaceNormal, surfacePlane)
layout(binding = FL_TEX_DIAGNOSTICS_SURFACES_NORMALS) uniform sampler2D uNormals;
uniform mat4 uInvViewProj;
uniform vec2 uViewportSize;

layout(location = 0) out vec4 oDiagnostics;

layout(binding = FL_TEX_PREVIOUS_SHADOW_MAP) uniform sampler2DShadow uPreviousShadowMap;
uniform mat4 uPreviousLightViewProj;
uniform mat4 uPreviousShadowWarp;
uniform int uHasPrevious;
uniform float uShadowMapSize;
uniform mat4 uView;

// Where the camera ray through window point `xy` meets the plane through p0 with normal n.
vec3 onPlane(vec2 xy, vec3 p0, vec3 n) {
    vec2 ndc = xy / uViewportSize * 2.0 - 1.0;
    vec4 a = uInvViewProj * vec4(ndc, -1.0, 1.0);
    vec4 b = uInvViewProj * vec4(ndc, 1.0, 1.0);
    vec3 from = a.xyz / a.w, dir = b.xyz / b.w - from;
    return from + dir * (dot(n, p0 - from) / dot(n, dir));
}

vec2 texelOf(vec3 world) {
    vec4 map = uShadowWarp * uLightViewProj * vec4(world, 1.0);
    return map.xy / map.w * (0.5 * uShadowMapSize);
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 surface = surfacePosition(uSurfaceDepth, pixel);
    vec3 vWorld = surface.xyz;
    // The Jacobian screen pixel -> shadow texel by central differences of half a pixel on the
    // pixel's own surface plane (not between neighbouring pixels, which at a silhouette belong
    // to different surfaces). Edge-on planes give inf/NaN, caught below.
    vec3 n0 = surfacePlane(uNormals, pixel);
    vec2 c = gl_FragCoord.xy;
    vec2 dx = texelOf(onPlane(c + vec2(0.5, 0.0), vWorld, n0)) -
              texelOf(onPlane(c - vec2(0.5, 0.0), vWorld, n0));
    vec2 dy = texelOf(onPlane(c + vec2(0.0, 0.5), vWorld, n0)) -
              texelOf(onPlane(c - vec2(0.0, 0.5), vWorld, n0));
    float det = abs(dx.x * dy.y - dx.y * dy.x); // shadow texels per screen pixel, as an area

    vec3 uvz;
    bool inMap = shadowCoord(vWorld, uvz);
    // Receivers are surfaces that face the light (as shaded: two-sided, interpolated normal):
    // on the others Lambert shading is zero, so the shadow map's texels there never show.
    vec3 n = surfaceNormal(uNormals, pixel);
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
