#version 450 core
#include "bindings.glsl"
// JFA-E phase 5 (thesis §5.4.1, "Generating Final Image"): a pixel that holds an occluder after
// the flood is in penumbra; its intensity is recomputed at its own world position with the
// inside flag (inner penumbrae see the part of the light away from the centre). Otherwise the
// hard shadow decides: 0 inside, 1 lit (and 1 for background). Same as fl::eyeSoftVisibility.
// Points decode from phase 2's packed cells, seeds' occluders are phase 3's (eye_decode.glsl).
#include "disk_light.glsl"
#include "shadow_map_decode.glsl"
#include "occluder_edge.glsl"
#include "surface_decode.glsl"
#include "eye_decode.glsl"

// packed cells: the seed pixel's index + 1
layout(binding = FL_TEX_EYE_FLOODED) uniform sampler2D uFlooded;

layout(location = 0) out float oVisibility;

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
    vec4 r = eyePoint(t);
    float w = texelFetch(uFlooded, t, 0).r;
    vec4 c = vec4(0.0, 0.0, -1.0, w);
    if (w != 0.0) c.xyz = eyeSeedOccluder(eyeSeedPixel(w)).xyz;
    bool inside = r.w == 1.0;
    float v = inside ? 0.0 : 1.0;
    if (r.w >= 0.0 && c.w != 0.0) {
        float intensity = occluderIntensity(r.xyz, c.xyz, inside);
        v = intensity < 0.0 ? v : intensity;
    }
    oVisibility = v;
}
