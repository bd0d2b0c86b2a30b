// The disk light of the soft-shadow methods (renderer/soft/DiskLight.h, thesis §5.2): centre,
// unit normal (the direction it faces) and radius.
uniform vec3 uDiskCenter;
uniform vec3 uDiskNormal;
uniform float uDiskRadius;

// |cq|^2 for the ray from receiver p through occluder o meeting the light's plane at q, or -1
// when o is not between p and the plane or q is off the disk. Operation by operation the same
// as fl::occluderHitDistance2 on the CPU (`precise`: no fused multiply-add there either), so
// CPU and GL floods choose the same occluders.
float penumbraHit(vec3 p, vec3 o) {
    precise float dx = o.x - p.x;
    precise float dy = o.y - p.y;
    precise float dz = o.z - p.z;
    precise float den = dx * uDiskNormal.x + dy * uDiskNormal.y + dz * uDiskNormal.z;
    precise float num = (uDiskCenter.x - p.x) * uDiskNormal.x +
                        (uDiskCenter.y - p.y) * uDiskNormal.y +
                        (uDiskCenter.z - p.z) * uDiskNormal.z;
    if (!(den != 0.0)) return -1.0;
    precise float s = num / den;
    if (!(s > 1.0)) return -1.0;
    precise float qx = (p.x + dx * s) - uDiskCenter.x;
    precise float qy = (p.y + dy * s) - uDiskCenter.y;
    precise float qz = (p.z + dz * s) - uDiskCenter.z;
    precise float d2 = qx * qx + qy * qy + qz * qz;
    if (!(d2 < uDiskRadius * uDiskRadius)) return -1.0;
    return d2;
}

// Area fraction of the disk beyond a chord at distance t * radius from its centre.
float segmentFraction(float t) {
    t = clamp(t, 0.0, 1.0);
    return (acos(t) - t * sqrt(1.0 - t * t)) / 3.14159265358979;
}

// Visible fraction of the light at p with occluder o, or -1 for a miss: the part holding the
// centre outside the hard shadow, the other part inside it.
float occluderIntensity(vec3 p, vec3 o, bool insideHardShadow) {
    float d2 = penumbraHit(p, o);
    if (d2 < 0.0) return -1.0;
    float seg = segmentFraction(sqrt(d2) / uDiskRadius);
    return insideHardShadow ? seg : 1.0 - seg;
}

// The penumbra bound of band-limited flooding: fl::penumbraReachRect on the CPU
// (renderer/soft/PenumbraReach.h explains the geometry), in float. Both are conservative.
uniform int uReachEnabled;
uniform mat4 uReachMatrix; // world -> the flooded grid's clip space
uniform ivec2 uReachSize;
uniform float uReachFarDepth;
// The receivers' depth pyramid (reach_depth.comp.glsl): 8x8-texel blocks at level 0; 0 levels =
// none (the scene's deepest point bounds every cone).
layout(binding = 4) uniform sampler2D uReachDepth;
uniform int uReachDepthLevels;
const int kReachRounds = 1; // 3 rounds: band 12.5% -> 10.7% of the map, flood slower (BENCHMARKS)
const int kJfaUnboundedReach = 0x3fffffff;
const ivec4 kJfaUnboundedRect = ivec4(-kJfaUnboundedReach, -kJfaUnboundedReach,
                                      kJfaUnboundedReach, kJfaUnboundedReach);

// The pyramid's texel bounds for a cone cut at depth `far`; .x > .z when unbounded.
ivec4 penumbraRectAt(vec3 o, float depth, float far) {
    vec3 n = uDiskNormal;
    float t = max((far - depth) / depth, 0.0) * 1.01 + 1e-3;
    vec3 capCenter = o + t * (o - uDiskCenter);
    float capRadius = t * uDiskRadius * 1.01;
    vec3 a = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    vec3 u = normalize(cross(n, a)) * capRadius;
    vec3 w = cross(normalize(n), normalize(u)) * capRadius;
    vec2 lo = vec2(1e30), hi = vec2(-1e30);
    bool front = true;
    for (int i = 0; i < 5; ++i) {
        vec3 q = i == 4 ? o : capCenter + ((i & 1) != 0 ? -u : u) + ((i & 2) != 0 ? -w : w);
        vec4 c = uReachMatrix * vec4(q, 1.0);
        front = front && c.w > 1e-6;
        vec2 texel = (c.xy / c.w * 0.5 + 0.5) * vec2(uReachSize);
        lo = min(lo, texel);
        hi = max(hi, texel);
    }
    if (!front || !(hi.x - lo.x < 1e9 && hi.y - lo.y < 1e9)) return kJfaUnboundedRect;
    return ivec4(ivec2(floor(lo)) - 2, ivec2(floor(hi)) + 2);
}

// Texels x0..x1 (.x, .z), y0..y1 (.y, .w) that can take occluder o. With the depth pyramid the
// cone is cut a second time at the deepest receiver inside the first rect: every receiver that
// can take o lies in that rect, so none is deeper (fl::penumbraReachRect).
ivec4 penumbraRect(vec3 o) {
    if (uReachEnabled == 0) return kJfaUnboundedRect;
    float depth = abs(dot(o - uDiskCenter, uDiskNormal));
    if (!(depth > 1e-6)) return kJfaUnboundedRect;
    // The first cut: the deepest receiver on the whole grid (the pyramid's top), else the scene's.
    float first = uReachDepthLevels == 0
                      ? uReachFarDepth
                      : texelFetch(uReachDepth, ivec2(0), uReachDepthLevels - 1).r * 1.001 + 1e-4;
    ivec4 r = penumbraRectAt(o, depth, first);
    if (uReachDepthLevels == 0 || r.x > r.z) return r;
    // Each cut holds every receiver that can take o, so the deepest receiver inside it bounds
    // the next: a few rounds shrink the rect towards the receivers actually below o.
    for (int round = 0; round < kReachRounds; ++round) {
        ivec2 lo = max(r.xy, ivec2(0)), hi = min(r.zw, uReachSize - 1);
        if (lo.x > hi.x || lo.y > hi.y) return ivec4(1, 1, 0, 0); // off the grid: no receiver
        // The level whose cells are wide enough that the rect spans at most 2 x 2 of them.
        int level = 0;
        while (level + 1 < uReachDepthLevels &&
               any(greaterThan(hi / (8 << level) - lo / (8 << level), ivec2(1))))
            ++level;
        // Level sizes from the grid, not textureSize(uReachDepth, level): llvmpipe (Mesa 22.3)
        // answers that with the next level's size, which clamped the query to half the cells
        // and cut cones short (band != full on flood-E; tests/penumbra_gltest.cpp).
        ivec2 size = max(((uReachSize + 7) / 8) >> level, ivec2(1));
        ivec2 c0 = min(lo / (8 << level), size - 1), c1 = min(hi / (8 << level), size - 1);
        float far = max(max(texelFetch(uReachDepth, c0, level).r,
                            texelFetch(uReachDepth, ivec2(c1.x, c0.y), level).r),
                        max(texelFetch(uReachDepth, ivec2(c0.x, c1.y), level).r,
                            texelFetch(uReachDepth, c1, level).r));
        ivec4 next = penumbraRectAt(o, depth, far * 1.001 + 1e-4);
        // Intersect: both hold every receiver that can take o.
        r = ivec4(max(r.xy, next.xy), min(r.zw, next.zw));
    }
    return r;
}
