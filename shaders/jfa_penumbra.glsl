#version 450 core
#include "bindings.glsl"
// Penumbra criterion (renderer/soft/PenumbraCriterion.h on the CPU, which this matches bit for
// bit), thesis §5.2-5.3: a texel's receiver point is its world position (mapReceiver of the
// shadow map's receiver target uPenumbraPositions, bound by MapPositions::bind); a
// cell is an occluder point (xyz, w the tag of the silhouette texel it came from, mapSeedTag;
// w = 0 empty), stored packed as the tag alone (jfaLoad, jfaStore). An occluder whose ray from the receiver
// misses the light is not taken (and so not passed on), except by the silhouette texel it came
// from (penumbraKey). Among the others the one whose ray meets
// the light's plane nearest the centre wins: that is the minimum intensity outside the hard
// shadow and the maximum inside it. Ties go to the smaller x, then y, then z.
#include "disk_light.glsl"
#include "shadow_map_decode.glsl"

layout(binding = FL_TEX_PENUMBRA_POSITIONS) uniform sampler2D uPenumbraPositions;

bool jfaEmpty(vec4 c) { return c.w == 0.0; }

// Cells are packed (JFA_CELL_FORMAT r32f): a texel stores its occluder's seed tag alone, 4 bytes
// instead of 16; the occluder's position comes back from the map (mapSeedCell).
vec4 jfaLoad(sampler2D grid, ivec2 q) {
    return mapSeedCell(uPenumbraPositions, texelFetch(grid, q, 0).r);
}
vec4 jfaStore(vec4 c) { return vec4(c.w); }

// Occluders are not tied to pixels: the half-resolution expansion copies them verbatim.
ivec2 jfaSeedPixel(vec4 c) { return ivec2(-1); }

// A silhouette texel holding its own occluder keeps it (so that later, shorter passes can still
// pass it on: JFA needs every seed to survive), ranked after every occluder its ray reaches.
// --penumbra both (uUmbraDepth > 0): where the texel's own surface takes no occluder, the
// occluders the receiver it may hide would take (umbraSideKey; the own seed too, at that key).
float penumbraKey(ivec2 p, vec3 receiver, vec4 c) {
    bool own = c.w == mapSeedTag(p, textureSize(uPenumbraPositions, 0).x);
    float k = own ? -1.0 : penumbraHit(receiver, c.xyz);
    if (k < 0.0 && uUmbraDepth > 0.0) k = umbraSideKey(receiver, c.xyz);
    return own && k < 0.0 ? uintBitsToFloat(0x7f7fffffu) : k;
}

// Band-limited flooding (jfa/Band.h): the widest penumbra the occluder can cast on the map.
ivec4 jfaSeedRect(ivec2 p, vec4 c) { return penumbraRect(c.xyz); }

bool jfaAccept(ivec2 p, vec4 c) {
    vec4 receiver = mapReceiver(uPenumbraPositions, p);
    return receiver.w != 0.0 && penumbraKey(p, receiver.xyz, c) >= 0.0;
}

// The keyed form (jfa_select.glsl): one receiver fetch per texel, one penumbraHit per candidate.
vec4 jfaContext(ivec2 p) { return mapReceiver(uPenumbraPositions, p); }
float jfaKey(ivec2 p, vec4 receiver, vec4 c) {
    return receiver.w != 0.0 ? penumbraKey(p, receiver.xyz, c) : -1.0;
}
bool jfaTieWins(vec4 a, vec4 b) {
    return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
}

bool jfaBetter(ivec2 p, vec4 a, vec4 b) {
    vec3 r = mapReceiver(uPenumbraPositions, p).xyz;
    float da = penumbraKey(p, r, a);
    float db = penumbraKey(p, r, b);
    bool tieWins = a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
    return da < db || (da == db && tieWins);
}
