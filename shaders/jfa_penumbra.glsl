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

// Band-limited flooding (jfa/Band.h): the widest penumbra the occluder can cast on the map.
ivec4 jfaSeedRect(ivec2 p, vec4 c) { return penumbraRect(c.xyz); }

bool jfaAccept(ivec2 p, vec4 c) {
    vec4 receiver = texelFetch(uPenumbraPositions, p, 0);
    return receiver.w != 0.0 && penumbraKey(receiver.xyz, c.xyz) >= 0.0;
}

// The keyed form (jfa_select.glsl): one receiver fetch per texel, one penumbraHit per candidate.
vec4 jfaContext(ivec2 p) { return texelFetch(uPenumbraPositions, p, 0); }
float jfaKey(ivec2 p, vec4 receiver, vec4 c) {
    return receiver.w != 0.0 ? penumbraKey(receiver.xyz, c.xyz) : -1.0;
}
bool jfaTieWins(vec4 a, vec4 b) {
    return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
}

bool jfaBetter(ivec2 p, vec4 a, vec4 b) {
    vec3 r = texelFetch(uPenumbraPositions, p, 0).xyz;
    float da = penumbraKey(r, a.xyz);
    float db = penumbraKey(r, b.xyz);
    bool tieWins = a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
    return da < db || (da == db && tieWins);
}
