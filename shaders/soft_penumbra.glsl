// JFA-L phase 4 (thesis §5.3.1, "Generating Final Image"): hard-shadowed points get 0 (with
// --penumbra both, the inner half: the part of the disk their texel's occluder leaves); a point
// whose penumbra-map texel holds an occluder gets the intensity recomputed here, at the point
// itself (not the value at the texel, which would make the penumbra blocky where the shadow map
// is coarse); everything else is lit. Needs shadow_lookup.glsl. The map's cells are packed
// (jfa_penumbra.glsl): the occluder comes back from the shadow map's receiver target.
#include "disk_light.glsl"
#include "shadow_map_decode.glsl"
#include "occluder_edge.glsl"

layout(binding = 3) uniform sampler2D uPenumbraMap;
layout(binding = 4) uniform sampler2D uPenumbraReceivers; // MapPositions::bind
// --penumbra both: a hard-shadowed point sees the part of the disk past its texel's occluder
// (the inner half, from 0 deep in the umbra to 0.5 at the hard edge); 0: outer only (0 there).
uniform int uPenumbraBoth;
uniform float uSilhouetteThreshold; // the silhouette pass's (occluderEdgePoint)

float penumbraMapVisibility(vec3 world) {
    vec3 uvz;
    if (!shadowCoord(world, uvz)) return 1.0;
    bool inside = texture(uShadowMap, uvz) < 0.5;
    if (inside && uPenumbraBoth == 0) return 0.0;
    ivec2 size = textureSize(uPenumbraMap, 0);
    ivec2 t = clamp(ivec2(uvz.xy * vec2(size)), ivec2(0), size - 1);
    vec4 o = mapSeedCell(uPenumbraReceivers, texelFetch(uPenumbraMap, t, 0).r);
    float lit = inside ? 0.0 : 1.0; // no occluder, or its ray misses the disk
    if (o.w == 0.0) return lit;
    // Both: the occluder's point at the silhouette's edge, not its texel's centre half a texel
    // inside (occluder_edge.glsl says why; the flood ranks the centres).
    if (uPenumbraBoth != 0)
        o.xyz = occluderEdgePoint(uPenumbraReceivers,
                                  mapSeedTexel(o.w, textureSize(uPenumbraReceivers, 0).x),
                                  uSilhouetteThreshold);
    float intensity = occluderIntensity(world, o.xyz, inside);
    return intensity < 0.0 ? lit : intensity;
}
