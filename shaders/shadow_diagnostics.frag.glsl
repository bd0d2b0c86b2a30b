#version 450 core
// Shadow-map diagnostics per visible pixel (see renderer/passes/ShadowDiagnosticsPass.h):
// texel footprint, view depth, hard visibility with this and the previous frame's map.
#include "shadow_lookup.glsl"
#include "light.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec2 vTexcoord;

layout(location = 0) out vec4 oDiagnostics;

layout(binding = 2) uniform sampler2DShadow uPreviousShadowMap;
uniform mat4 uPreviousLightViewProj;
uniform mat4 uPreviousShadowWarp;
uniform int uHasPrevious;
uniform float uShadowMapSize;
uniform mat4 uView;

void main() {
    // Texel coordinates up to a constant offset, computed in uniform control flow so the
    // derivatives are defined; the guard on w only keeps helper values finite.
    vec4 map = uShadowWarp * uLightViewProj * vec4(vWorld, 1.0);
    vec2 texel = map.xy / max(map.w, 1e-30) * (0.5 * uShadowMapSize);
    vec2 dx = dFdxFine(texel), dy = dFdyFine(texel);
    float det = abs(dx.x * dy.y - dx.y * dy.x); // shadow texels per screen pixel, as an area

    vec3 uvz;
    bool inMap = shadowCoord(vWorld, uvz);
    // Receivers are surfaces that face the light (as shaded: two-sided, interpolated normal):
    // on the others Lambert shading is zero, so the shadow map's texels there never show.
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    vec3 l = toLight(vWorld);
    bool receiver = inMap && dot(n, l) > 0.0;
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
    oDiagnostics = vec4(footprint, -(uView * vec4(vWorld, 1.0)).z, visibility, previous);
}
