#version 450 core
#include "bindings.glsl"
// PCF / PCSS visibility per eye pixel (renderer/soft/FilteredShadow.h has the method; the CPU
// reference fl::filteredVisibility does the same operations). Taps are points of the light's
// unwarped NDC plane, looked up through the provider's warp, compared with the receiver-plane
// depth along the light's ray through the tap.
#include "surface_decode.glsl"
#include "surface_lookup.glsl"
#include "normal_offset.glsl"

// SurfacesPass: positions (surfacePosition)
layout(binding = FL_TEX_SURFACES_DEPTH) uniform sampler2D uSurfaceDepth;
// SurfacesPass: normals (surfacePlane)
layout(binding = FL_TEX_SURFACES_NORMALS) uniform sampler2D uNormals;

layout(location = 0) out float oVisibility;

// The depth texture through a sampler without comparison (stored depths are read).
layout(binding = FL_TEX_SHADOW_DEPTH) uniform sampler2D uDepth;
uniform mat4 uLightView;
uniform mat4 uLightProj;
uniform mat4 uInvLightProj;
uniform mat4 uShadowWarp;
uniform int uPcss; // 0 PCF, 1 PCSS
uniform vec3 uDiskCenter;
uniform float uDiskRadius;
uniform float uSearchDepth;
uniform vec3 uDiskNormalView; // the disk's normal (toward the scene) and tangents, light view
uniform vec3 uDiskTangentView;
uniform vec3 uDiskBitangentView;
uniform int uTapCount;
uniform vec2 uTaps[225];
uniform int uBlockerCount;
uniform vec2 uBlockerTaps[64];

// View-space point of NDC (x, y, z) of the light.
vec3 unproject(vec3 ndc) {
    vec4 v = uInvLightProj * vec4(ndc, 1.0);
    return v.xyz / v.w;
}

// One tap at light NDC point s for the receiver plane (pv, nv) in view space: x = 1 lit,
// 0 shadowed; y = the stored depth (1 when off the map).
vec2 tap(vec2 s, vec3 pv, vec3 nv, float receiverNdcZ) {
    vec4 m = uShadowWarp * vec4(s, receiverNdcZ, 1.0);
    if (m.w <= 0.0) return vec2(1.0, 1.0);
    vec2 uv = m.xy / m.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return vec2(1.0, 1.0);
    ivec2 size = textureSize(uDepth, 0);
    ivec2 texel = clamp(ivec2(floor(uv * vec2(size))), ivec2(0), size - 1);
    float stored = texelFetch(uDepth, texel, 0).r;
    // The light's ray through s: from its near-plane point to its far-plane point.
    vec3 a = unproject(vec3(s, -1.0));
    vec3 b = unproject(vec3(s, 1.0));
    float den = dot(nv, b - a);
    float ref = receiverNdcZ * 0.5 + 0.5;
    if (abs(den) > 1e-6 * length(b - a)) {
        float t = dot(nv, pv - a) / den;
        if (t > 0.0 && t < 1.0) {
            vec4 c = uLightProj * vec4(a + t * (b - a), 1.0);
            ref = c.z / c.w * 0.5 + 0.5;
        }
    }
    return vec2(ref <= stored ? 1.0 : 0.0, stored);
}

// Centre (NDC xy) and NDC radii of the disk light seen from pv through the plane at depth d.
vec4 diskThrough(vec3 pv, vec3 cv, float d) {
    float dR = -pv.z, dC = -cv.z;
    float k = (dR - d) / max(dR - dC, 1e-6);
    vec3 x = pv + (cv - pv) * k;
    vec4 clip = uLightProj * vec4(x, 1.0);
    float r = uDiskRadius * max(k, 0.0);
    return vec4(clip.xy / clip.w, vec2(uLightProj[0][0], uLightProj[1][1]) * r / clip.w);
}

// PCSS's filter region: the disk seen from pv through the plane parallel to the disk at
// distance `blocker` in front of it; NDC centre (xy) and the images of the disk's tangents.
// Taken across the disk, not across the map, which differ where the map is not aimed along the
// spot (fl::diskImage on the CPU, the same operations).
void diskImage(vec3 pv, vec3 cv, float blocker, out vec2 centre, out vec2 u, out vec2 v) {
    float dR = dot(pv - cv, uDiskNormalView);
    float k = (dR - blocker) / max(dR, 1e-6);
    vec3 x = pv + (cv - pv) * k;
    float r = uDiskRadius * max(k, 0.0);
    vec4 c0 = uLightProj * vec4(x, 1.0);
    vec4 cu = uLightProj * vec4(x + r * uDiskTangentView, 1.0);
    vec4 cb = uLightProj * vec4(x + r * uDiskBitangentView, 1.0);
    centre = c0.xy / c0.w;
    u = cu.xy / cu.w - centre;
    v = cb.xy / cb.w - centre;
}

float filtered(vec3 world, vec3 n) {
    vec3 pv = (uLightView * vec4(world, 1.0)).xyz;
    vec3 nv = mat3(uLightView) * n;
    vec4 clip = uLightProj * vec4(pv, 1.0);
    if (clip.w <= 0.0) return 1.0;
    vec3 ndc = clip.xyz / clip.w;
    if (uPcss == 0) {
        float lit = 0.0;
        for (int i = 0; i < uTapCount; ++i) lit += tap(ndc.xy + uTaps[i], pv, nv, ndc.z).x;
        return lit / float(uTapCount);
    }
    vec3 cv = (uLightView * vec4(uDiskCenter, 1.0)).xyz;
    // Blocker search: the disk seen through the nearest plane an occluder can lie in.
    vec4 search = diskThrough(pv, cv, uSearchDepth);
    float blockers = 0.0, depthSum = 0.0;
    for (int i = 0; i < uBlockerCount; ++i) {
        vec2 s = search.xy + search.zw * uBlockerTaps[i];
        vec2 r = tap(s, pv, nv, ndc.z);
        if (r.x == 0.0) {
            blockers += 1.0;
            // The blocker's distance in front of the disk, from its point in the map.
            vec3 bv = unproject(vec3(s, 2.0 * r.y - 1.0));
            depthSum += dot(bv - cv, uDiskNormalView);
        }
    }
    if (blockers == 0.0) return 1.0;
    // Filter: the disk seen through the mean blocker distance (penumbra by similar triangles).
    vec2 centre, u, v;
    diskImage(pv, cv, depthSum / blockers, centre, u, v);
    float lit = 0.0;
    for (int i = 0; i < uTapCount; ++i)
        lit += tap(centre + u * uTaps[i].x + v * uTaps[i].y, pv, nv, ndc.z).x;
    return lit / float(uTapCount);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 world = surfacePosition(uSurfaceDepth, p);
    // The receiver plane: the surfaces pass's geometric normal (only the plane is used).
    if (world.w == 0.0) {
        oVisibility = 1.0;
        return;
    }
    vec3 plane = surfaceLookupPlane(p);
    vec3 lookup = surfaceLookupPoint(world.xyz, p);
    lookup = normalOffset(lookup, plane, normalize(uDiskCenter - lookup),
                          uShadowWarp * uLightProj * uLightView,
                          float(textureSize(uDepth, 0).x));
    oVisibility = filtered(lookup, plane);
}
