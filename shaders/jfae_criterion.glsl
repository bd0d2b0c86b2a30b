#version 450 core
// JFA-E flooding criterion (thesis §5.2, §5.4), bit for bit fl::EyeSoftCriterion on the CPU.
// A cell is an occluder point (xyz) and w = the index + 1 of the boundary pixel it was seeded
// at (w = 0 empty). Grid point p is the eye pixel whose world position (eyePoint) receives.
// Ranking: inside the hard shadow the thesis keeps the highest intensity, outside the lowest;
// both are the occluder whose ray from p meets the light's plane nearest the centre (intensity
// inside = segmentFraction(|cq| / r), falling in |cq|; outside = 1 - that, rising), so one key,
// |cq|^2, smaller is better, serves both. Ties go to the smaller x, y, z, then w.
// Accepted only if the ray from p through the occluder reaches the light (else p is umbra or
// lit, and must not pass the occluder on), and with the thesis' two jump-too-far fixes (§5.4.2):
//  - object ID: a hard-shadowed p takes only occluders of the object that occludes p itself
//    (its own occluder's id, eyeOccluderId); lit pixels are not restricted, since they have
//    no occluder and the wrong penumbrae the fix is for are inner ones;
//  - midpoint: the pixel midway between the occluder's boundary pixel and p must be a surface
//    whose ray through the occluder reaches the light too (it would have a penumbra intensity).
// Points decode from phase 2's packed cells, seeds' occluders are phase 3's (eye_decode.glsl).
#include "disk_light.glsl"
#include "shadow_map_decode.glsl"
#include "occluder_edge.glsl"
#include "surface_decode.glsl"
#include "eye_decode.glsl"

uniform int uObjectIdFix;
uniform int uMidpointFix;

ivec2 seedPixelOf(vec4 c) { return eyeSeedPixel(c.w); }

bool jfaEmpty(vec4 c) { return c.w == 0.0; }

// Occluders are not sites at pixels: the half-resolution expansion copies them verbatim.
ivec2 jfaSeedPixel(vec4 c) { return ivec2(-1); }

// Band-limited flooding (jfa/Band.h): the widest penumbra the occluder can cast in the image
// (it was seeded at its boundary pixel p).
ivec4 jfaSeedRect(ivec2 p, vec4 c) { return penumbraRect(c.xyz); }

bool jfaAccept(ivec2 p, vec4 c) {
    vec4 r = eyePoint(p);
    ivec2 s = seedPixelOf(c);
    bool ok = r.w >= 0.0 && penumbraHit(r.xyz, c.xyz) >= 0.0;
    if (ok && uObjectIdFix != 0 && r.w == 1.0)
        ok = eyeOccluderId(p) == eyeSeedOccluder(s).w;
    if (ok && uMidpointFix != 0) {
        vec4 m = eyePoint((p + s) / 2);
        ok = m.w >= 0.0 && penumbraHit(m.xyz, c.xyz) >= 0.0;
    }
    return ok;
}

// The keyed form (jfa_select.glsl): jfaAccept's tests, then penumbraHit once as the key.
// jfaContext runs once per texel before its candidates, so p's own occluder id is fetched there
// too, into a shader-private global, instead of once per candidate.
float gOwnOccluderId;
vec4 jfaContext(ivec2 p) {
    gOwnOccluderId = eyeOccluderId(p);
    return eyePoint(p);
}
float jfaKey(ivec2 p, vec4 r, vec4 c) {
    float k = r.w >= 0.0 ? penumbraHit(r.xyz, c.xyz) : -1.0;
    bool ok = k >= 0.0;
    if (ok && (uObjectIdFix != 0 || uMidpointFix != 0)) {
        ivec2 s = seedPixelOf(c);
        if (uObjectIdFix != 0 && r.w == 1.0)
            ok = gOwnOccluderId == eyeSeedOccluder(s).w;
        if (ok && uMidpointFix != 0) {
            vec4 m = eyeSurface((p + s) / 2);
            ok = m.w != 0.0 && penumbraHit(m.xyz, c.xyz) >= 0.0;
        }
    }
    return ok ? k : -1.0;
}
bool jfaTieWins(vec4 a, vec4 b) {
    return a.x < b.x ||
           (a.x == b.x && (a.y < b.y || (a.y == b.y && (a.z < b.z || (a.z == b.z && a.w < b.w)))));
}

bool jfaBetter(ivec2 p, vec4 a, vec4 b) {
    vec3 r = eyePoint(p).xyz;
    float da = penumbraHit(r, a.xyz);
    float db = penumbraHit(r, b.xyz);
    bool tieWins = a.x < b.x ||
                   (a.x == b.x && (a.y < b.y || (a.y == b.y && (a.z < b.z ||
                                                                (a.z == b.z && a.w < b.w)))));
    return da < db || (da == db && tieWins);
}

// Cells are packed (JFA_CELL_FORMAT r32f): a texel stores w alone, the seed pixel's index + 1,
// 4 bytes instead of 16; the occluder is the one phase 2 found at the seed pixel, as phase 3
// decoded it once (eyeSeedOccluder).
vec4 jfaLoad(sampler2D grid, ivec2 q) {
    float w = texelFetch(grid, q, 0).r;
    if (w == 0.0) return vec4(0.0, 0.0, -1.0, 0.0);
    return vec4(eyeSeedOccluder(eyeSeedPixel(w)).xyz, w);
}
vec4 jfaStore(vec4 c) { return vec4(c.w); }
