#version 450 core
// JFA-E phase 3 (thesis §5.4.1, "Locating Occluders"): a pixel in hard shadow is a boundary
// pixel if one of its 8 neighbours is lit by the depth test (w = 0, not "outside the map") and nearer in 3D than the threshold (a lit pixel
// across a depth jump is another surface, not the other side of a shadow edge). A boundary
// pixel becomes a seed: its occluder's position, and w = its pixel index + 1 (the midpoint
// check needs to know where an occluder entered the flood; its object id is read there too).
// Same as fl::eyeBoundarySeeds on the CPU. The grid is the frame, or the coarse estimate's
// (uEyeFactor, eye_decode.glsl); its pixels' points decode from phase 2's packed cells.
#include "jfa_seed_list.glsl"
#include "disk_light.glsl"
#include "shadow_map_decode.glsl"
#include "occluder_edge.glsl"
#include "surface_decode.glsl"
#include "eye_decode.glsl"

uniform vec3 uEye;
// A neighbour at squared distance d2 counts when d2 < uAbsolute2 + uRelative2 * |p - eye|^2.
uniform float uAbsolute2;
uniform float uRelative2;

uniform int uListSeeds; // append each seed to the band's seed list (jfa_seed_list.glsl)

layout(location = 0) out float oSeed; // packed: the seed's index + 1, 0 none (jfae_criterion)
layout(location = 1) out vec4 oOccluder; // the seed's eyeOccluder, decoded once (eyeSeedOccluder)

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
    ivec2 size = uEyeGrid;
    oSeed = 0.0;
    oOccluder = vec4(0.0);
    // Only a hard-shadowed pixel can be a seed and only its lit neighbours count, so no other
    // point is decoded (each is an unprojection of the surfaces' depth, eyePoint).
    if (eyeState(t) != kEyeShadowed) return;
    vec4 self = eyePoint(t);
    precise vec3 toEye = self.xyz - uEye;
    precise float e2 = toEye.x * toEye.x + toEye.y * toEye.y + toEye.z * toEye.z;
    precise float limit2 = uAbsolute2 + uRelative2 * e2;
    bool boundary = false;
    for (int j = -1; j <= 1; ++j) {
        for (int i = -1; i <= 1; ++i) {
            ivec2 q = t + ivec2(i, j);
            bool inside = all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size));
            if (!inside || eyeState(q) != kEyeLit) continue;
            vec4 n = eyePoint(q);
            precise vec3 d = n.xyz - self.xyz;
            precise float d2 = d.x * d.x + d.y * d.y + d.z * d.z;
            boundary = boundary || d2 < limit2;
        }
    }
    if (!boundary) return;
    oSeed = float(t.y * size.x + t.x + 1);
    oOccluder = eyeOccluder(t);
    if (uListSeeds != 0) jfaListSeed(t);
}
