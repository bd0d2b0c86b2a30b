// JFA-L phase 4 (thesis §5.3.1, "Generating Final Image"): hard-shadowed points get 0; a point
// whose penumbra-map texel holds an occluder gets the intensity recomputed here, at the point
// itself (not the value at the texel, which would make the penumbra blocky where the shadow map
// is coarse); everything else is lit. Needs shadow_lookup.glsl. The map's cells are packed
// (jfa_penumbra.glsl): the occluder comes back from the shadow map's receiver target.
#include "disk_light.glsl"
#include "shadow_map_decode.glsl"

layout(binding = 3) uniform sampler2D uPenumbraMap;
layout(binding = 4) uniform sampler2D uPenumbraReceivers; // MapPositions::bind

float penumbraMapVisibility(vec3 world) {
    vec3 uvz;
    if (!shadowCoord(world, uvz)) return 1.0;
    if (texture(uShadowMap, uvz) < 0.5) return 0.0;
    ivec2 size = textureSize(uPenumbraMap, 0);
    ivec2 t = clamp(ivec2(uvz.xy * vec2(size)), ivec2(0), size - 1);
    vec4 o = mapSeedCell(uPenumbraReceivers, texelFetch(uPenumbraMap, t, 0).r);
    if (o.w == 0.0) return 1.0;
    float intensity = occluderIntensity(world, o.xyz, false);
    return intensity < 0.0 ? 1.0 : intensity;
}
