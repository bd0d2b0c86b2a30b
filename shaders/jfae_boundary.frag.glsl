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
// 1: a seed's occluder is walked to the silhouette (boundaryOccluder below); 0: its own texel's
// (the thesis, centre points, and the coarse estimate of EyeFloodReach)
uniform int uSeedWalk;
uniform float uSilhouetteThreshold; // occluder_edge.glsl's threshold, as phase 2's

// The longest walk, in texels: the hard edge lies within one pixel's footprint of a boundary
// pixel, a few texels where the map is finer than the frame.
const int kMaxWalk = 16;

// The occluder point of boundary pixel t whose nearest lit neighbour is q. Phase 2 gives t the
// receiver at its own texel, which lies anywhere within a pixel's footprint of the hard edge:
// where the map is finer than the frame, several texels inside the occluder, and the flood then
// takes the edge for a few texels further in (inner penumbrae go unflooded and stay black). So
// walk the map from t's texel toward q's (lit, so across the edge), texel by texel along the
// line between them, while each next texel stays on the same surface (no silhouette between
// them, acrossSilhouette), and take the last one's edge point. Same as the CPU's
// boundaryOccluderPoint (renderer/soft/EyeSoftShadow.h).
vec3 boundaryOccluder(ivec2 t, ivec2 q) {
    ivec2 a = eyeCellTexel(texelFetch(uEyeCells, eyeFramePixel(t), 0).r);
    ivec2 b = eyeCellTexel(texelFetch(uEyeCells, eyeFramePixel(q), 0).r);
    ivec2 d = b - a;
    int n = min(max(abs(d.x), abs(d.y)), kMaxWalk);
    ivec2 k = a;
    vec4 last = mapReceiver(uEyeReceivers, a);
    for (int i = 1; i <= n; ++i) {
        // Rounded to the nearest texel in integers (no float division, whose rounding a
        // conforming driver may do its own way): |d| i / n, halves up, with d's sign.
        ivec2 c = a + sign(d) * ((2 * abs(d) * i + n) / (2 * n));
        vec4 next = mapReceiver(uEyeReceivers, c);
        if (acrossSilhouette(last, next, uSilhouetteThreshold)) break;
        k = c;
        last = next;
    }
    return occluderEdgePoint(uEyeReceivers, k, uSilhouetteThreshold);
}

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
    ivec2 nearest = t; // the nearest lit neighbour within the limit
    float nearest2 = 0.0;
    for (int j = -1; j <= 1; ++j) {
        for (int i = -1; i <= 1; ++i) {
            ivec2 q = t + ivec2(i, j);
            bool inside = all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size));
            if (!inside || eyeState(q) != kEyeLit) continue;
            vec4 n = eyePoint(q);
            precise vec3 d = n.xyz - self.xyz;
            precise float d2 = d.x * d.x + d.y * d.y + d.z * d.z;
            if (d2 < limit2 && (!boundary || d2 < nearest2)) {
                nearest = q;
                nearest2 = d2;
            }
            boundary = boundary || d2 < limit2;
        }
    }
    if (!boundary) return;
    oSeed = float(t.y * size.x + t.x + 1);
    oOccluder = eyeOccluder(t);
    // The id stays phase 2's: the walk never leaves the occluder's surface.
    if (uSeedWalk != 0) oOccluder.xyz = boundaryOccluder(t, nearest);
    if (uListSeeds != 0) jfaListSeed(t);
}
