#version 450 core
// JFA-E phase 2 (thesis §5.4.1, "Generating Hard Shadows"): per pixel of the frame's surfaces,
// its hard-shadow state (shadowed, lit, lit because outside the shadow map, background) and its
// occluder: the surface the light's centre sees at the pixel's shadow-map texel, with that
// surface's object id. Both are packed into one 32-bit cell (eye_decode.glsl): the state, the
// texel and its edge code; readers decode the world positions from the surfaces' depth and the
// map's receiver target, and the id from the light-space id pass. Phase 3 records the occluder
// of boundary pixels from here, so a boundary pixel's occluder is by construction the surface that puts it in hard shadow, not a guess from
// the shadow map's silhouettes (Arvo et al.'s condition (2), which the thesis drops). With
// uOccluderEdges, an occluder texel at a silhouette gives its edge point instead of its centre
// (occluder_edge.glsl says why); off, the thesis' texel centre.
#include "shadow_lookup.glsl"
#include "disk_light.glsl"
#include "shadow_map_decode.glsl"
#include "occluder_edge.glsl"
#include "surface_decode.glsl"
#include "eye_decode.glsl"
#include "surface_lookup.glsl"

uniform int uOccluderEdges;
uniform float uSilhouetteThreshold;

layout(location = 0) out uint oCell;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 surface = surfacePosition(uEyeDepth, p);
    if (surface.w == 0.0) {
        oCell = eyeCellPack(kEyeBackground, ivec2(0), 0u);
        return;
    }
    // The same test as the hard method's hardShadow(), so radius 0 reproduces it exactly.
    vec3 lookup = shadowNormalOffset(surfaceLookupPoint(surface.xyz, p), surfaceLookupPlane(p));
    float lit = hardShadow(lookup);
    vec3 uvz;
    // Lit outside the map is lit by convention, not by a depth test: it is no evidence of a
    // shadow edge, so phase 3 does not count it (a light inside an object would otherwise get a
    // false penumbra along the edge of the map's coverage).
    if (!shadowCoord(lookup, uvz)) {
        oCell = eyeCellPack(kEyeOutsideMap, ivec2(0), 0u); // hardShadow() calls it lit
        return;
    }
    // The texel a NEAREST lookup of uShadowMap reads.
    ivec2 size = textureSize(uEyeReceivers, 0);
    ivec2 t = clamp(ivec2(uvz.xy * vec2(size)), ivec2(0), size - 1);
    // Only hard-shadowed pixels' occluders are read (phase 3, the object-ID fix).
    uint code = uOccluderEdges != 0 && lit < 0.5
                    ? occluderEdgeCode(uEyeReceivers, t, uSilhouetteThreshold)
                    : 0u;
    oCell = eyeCellPack(lit < 0.5 ? kEyeShadowed : kEyeLit, t, code);
}
