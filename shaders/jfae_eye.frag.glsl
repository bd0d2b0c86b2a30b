#version 450 core
// JFA-E phase 2 (thesis §5.4.1, "Generating Hard Shadows"): per pixel of the frame's surfaces,
// its world position with the hard-shadow flag in alpha (1 shadowed, 0 lit, 2 lit because
// outside the shadow map, -1 background), and its occluder: the surface the light's centre sees
// at the pixel's shadow-map texel (the receiver position decoded from the shadow pass's receiver
// target, shadow_map_decode.glsl) with that
// surface's object id. Phase 3 records the occluder of boundary pixels from here, so a boundary
// pixel's occluder is by construction the surface that puts it in hard shadow, not a guess from
// the shadow map's silhouettes (Arvo et al.'s condition (2), which the thesis drops). With
// uOccluderEdges, an occluder texel at a silhouette gives its edge point instead of its centre
// (occluder_edge.glsl says why); off, the thesis' texel centre.
#include "shadow_lookup.glsl"
#include "disk_light.glsl"
#include "shadow_map_decode.glsl"
#include "occluder_edge.glsl"
#include "surface_decode.glsl"

layout(binding = 0) uniform sampler2D uDepth; // SurfacesPass: positions (surfacePosition)
layout(binding = 2) uniform sampler2D uReceivers; // the map's receiver target (MapPositions)
layout(binding = 3) uniform sampler2D uLightObjectIds;
uniform int uHaveObjectIds;
uniform int uOccluderEdges;
uniform float uSilhouetteThreshold;

layout(location = 0) out vec4 oPoint;
layout(location = 1) out vec4 oOccluder;

void main() {
    vec4 surface = surfacePosition(uDepth, ivec2(gl_FragCoord.xy));
    oOccluder = vec4(0.0, 0.0, 0.0, -1.0);
    if (surface.w == 0.0) {
        oPoint = vec4(0.0, 0.0, 0.0, -1.0);
        return;
    }
    vec3 world = surface.xyz;
    // The same test as the hard method's hardShadow(), so radius 0 reproduces it exactly.
    float lit = hardShadow(world);
    vec3 uvz;
    bool inMap = shadowCoord(world, uvz);
    // Lit outside the map (2) is lit by convention, not by a depth test: it is no evidence of a
    // shadow edge, so phase 3 does not count it (a light inside an object would otherwise get a
    // false penumbra along the edge of the map's coverage).
    oPoint = vec4(world, lit < 0.5 ? 1.0 : (inMap ? 0.0 : 2.0));
    if (inMap) {
        // The texel a NEAREST lookup of uShadowMap reads.
        ivec2 size = textureSize(uReceivers, 0);
        ivec2 t = clamp(ivec2(uvz.xy * vec2(size)), ivec2(0), size - 1);
        float id = uHaveObjectIds != 0 ? texelFetch(uLightObjectIds, t, 0).r : -1.0;
        // Only hard-shadowed pixels' occluders are read (phase 3, the object-ID fix).
        vec3 o = uOccluderEdges != 0 && lit < 0.5
                     ? occluderEdgePoint(uReceivers, t, uSilhouetteThreshold)
                     : mapReceiver(uReceivers, t).xyz;
        oOccluder = vec4(o, id);
    }
}
