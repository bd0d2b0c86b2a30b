// Silhouette edges of the shadow map's receiver texture, shared by JFA-L's silhouette pass and
// JFA-E's occluder lookup; fl::acrossSilhouette and fl::occluderEdgePoint on the CPU
// (renderer/soft/OccluderEdge.h), operation for operation. Needs disk_light.glsl and
// shadow_map_decode.glsl (the receiver target holds depths; positions come from mapReceiver).
//
// Why occluder points move to the edge: a texel is covered when its centre is, so the occluder's
// true edge lies anywhere between the last covered centre and the first uncovered one, on average
// half a texel beyond the covered centre. The thesis floods the centres (§5.3.1, §5.4.1); from a
// receiver in the penumbra the edge then looks half a texel further into the occluder, and every
// penumbra comes out too bright (+0.04 to +0.09 on the closed-form edges, docs/BENCHMARKS.md).

const float kSilhouetteSlope = 3.0;

float silhouetteDepth(vec3 p) {
    precise float d = (p.x - uDiskCenter.x) * uDiskNormal.x + (p.y - uDiskCenter.y) * uDiskNormal.y +
                      (p.z - uDiskCenter.z) * uDiskNormal.z;
    return d;
}

// Whether neighbour n lies across a silhouette edge from texel `self`: it sees nothing, or lies
// deeper from the light (along its normal) by more than `threshold` plus kSilhouetteSlope times
// their distance across the light's axis. The slope term keeps a continuous surface tilted up to
// atan(3) = 72 degrees away from the light from counting as a depth jump at any map resolution.
bool acrossSilhouette(vec4 self, vec4 n, float threshold) {
    precise float deeper = silhouetteDepth(n.xyz) - silhouetteDepth(self.xyz);
    precise vec3 delta = n.xyz - self.xyz;
    precise vec3 across = delta - deeper * uDiskNormal;
    precise float lateral2 = across.x * across.x + across.y * across.y + across.z * across.z;
    precise float allowed = threshold + kSilhouetteSlope * sqrt(lateral2);
    return n.w == 0.0 || deeper > allowed;
}

// Which axis neighbours of texel t lie across a silhouette edge on one side only: per axis two
// bits (x in bits 0-1, y in bits 2-3), 1 when the edge is on the high side (the point moves away
// from the low neighbour), 2 when on the low side, 0 for none, both, or the map's border. Kept
// apart from occluderEdgeApply so a packed occluder (JFA-E's eye cells, eye_decode.glsl) stores
// the four bits and decodes without the neighbourhood test.
uint occluderEdgeCode(sampler2D receivers, ivec2 t, float threshold) {
    ivec2 size = textureSize(receivers, 0);
    vec4 self = mapReceiver(receivers, t);
    uint code = 0u;
    if (self.w == 0.0) return code;
    for (int axis = 0; axis < 2; ++axis) {
        ivec2 a = axis == 0 ? ivec2(1, 0) : ivec2(0, 1);
        ivec2 lo = t - a, hi = t + a;
        bool inLo = all(greaterThanEqual(lo, ivec2(0)));
        bool inHi = all(lessThan(hi, size));
        vec4 nLo = mapReceiver(receivers, clamp(lo, ivec2(0), size - 1));
        vec4 nHi = mapReceiver(receivers, clamp(hi, ivec2(0), size - 1));
        bool edgeLo = inLo && acrossSilhouette(self, nLo, threshold);
        bool edgeHi = inHi && acrossSilhouette(self, nHi, threshold);
        if (edgeHi && !edgeLo && inLo) code |= 1u << (2 * axis);
        if (edgeLo && !edgeHi && inHi) code |= 2u << (2 * axis);
    }
    return code;
}

// The occluder point of texel t with edge code `code` (occluderEdgeCode): its receiver moved half
// a texel along the occluder's own surface toward each axis neighbour across a silhouette edge
// (the step is the texel's distance to the neighbour on the other side, which is on the same
// surface).
vec3 occluderEdgeApply(sampler2D receivers, ivec2 t, uint code) {
    vec4 self = mapReceiver(receivers, t);
    precise vec3 o = self.xyz;
    for (int axis = 0; axis < 2; ++axis) {
        uint c = (code >> uint(2 * axis)) & 3u;
        if (c == 0u) continue;
        ivec2 a = axis == 0 ? ivec2(1, 0) : ivec2(0, 1);
        vec4 n = mapReceiver(receivers, c == 1u ? t - a : t + a);
        o = o + 0.5 * (self.xyz - n.xyz);
    }
    return o;
}

// The occluder point of texel t: occluderEdgeApply of its own edge code. A texel with edges on
// both sides of an axis, or none, or at the map's border, stays put on that axis.
vec3 occluderEdgePoint(sampler2D receivers, ivec2 t, float threshold) {
    return occluderEdgeApply(receivers, t, occluderEdgeCode(receivers, t, threshold));
}
