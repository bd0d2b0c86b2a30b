#version 450 core
// Penumbra criterion (renderer/soft/PenumbraCriterion.h on the CPU, which this matches bit for
// bit), thesis §5.2-5.3: a texel's receiver point is its world position (uPenumbraPositions); a
// cell is an occluder point (xyz, w = 1; w = 0 empty). An occluder whose ray from the receiver
// misses the light is not taken (and so not passed on), except by the silhouette texel it came
// from (penumbraKey). Among the others the one whose ray meets
// the light's plane nearest the centre wins: that is the minimum intensity outside the hard
// shadow and the maximum inside it. Ties go to the smaller x, then y, then z.
#include "disk_light.glsl"

layout(binding = 2) uniform sampler2D uPenumbraPositions;

bool jfaEmpty(vec4 c) { return c.w == 0.0; }

// Occluders are not tied to pixels: the half-resolution expansion copies them verbatim.
ivec2 jfaSeedPixel(vec4 c) { return ivec2(-1); }

// A silhouette texel holding its own occluder keeps it (so that later, shorter passes can still
// pass it on: JFA needs every seed to survive), ranked after every occluder its ray reaches.
float penumbraKey(vec3 receiver, vec3 o) {
    return o == receiver ? uintBitsToFloat(0x7f7fffffu) : penumbraHit(receiver, o);
}

// Memo. The kernel (jfa_select.glsl) calls jfaAccept(p, c) right before jfaBetter(p, c, best),
// and `best` is the winner of an earlier call at the same p: keeping p's receiver, the key of the
// last candidate and the key of the last winner spares two of every three texel fetches and
// penumbraKey evaluations (the criterion, not the kernel, dominated the pass). Keys are looked up
// by the cell's value, so they are the same numbers recomputing would give: CPU and GL agree bit
// for bit as before.
ivec2 gMemoP = ivec2(-1);
vec4 gMemoReceiver;
const vec4 kNoCell = vec4(0.0, 0.0, 0.0, -7.0); // equals no cell (w is 0 or 1)
vec4 gLastCell = kNoCell;
float gLastKey;
vec4 gBestCell = kNoCell;
float gBestKey;

vec4 memoReceiver(ivec2 p) {
    if (p != gMemoP) {
        gMemoP = p;
        gMemoReceiver = texelFetch(uPenumbraPositions, p, 0);
        gLastCell = kNoCell;
        gBestCell = kNoCell;
    }
    return gMemoReceiver;
}

float memoKey(ivec2 p, vec4 c) {
    vec3 r = memoReceiver(p).xyz;
    if (c == gLastCell) return gLastKey;
    if (c == gBestCell) return gBestKey;
    gLastCell = c;
    gLastKey = penumbraKey(r, c.xyz);
    return gLastKey;
}

bool jfaAccept(ivec2 p, vec4 c) {
    return memoReceiver(p).w != 0.0 && memoKey(p, c) >= 0.0;
}

bool jfaBetter(ivec2 p, vec4 a, vec4 b) {
    float da = memoKey(p, a);
    float db = memoKey(p, b);
    bool tieWins = a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
    bool aWins = da < db || (da == db && tieWins);
    gBestCell = aWins ? a : b; // the kernel keeps the winner as its best
    gBestKey = aWins ? da : db;
    return aWins;
}
