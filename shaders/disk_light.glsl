// The disk light of the soft-shadow methods (renderer/soft/DiskLight.h, thesis §5.2): centre,
// unit normal (the direction it faces) and radius.
#include "bindings.glsl"
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

// JFA-L's umbra side (--penumbra both; 0 = outer only): the deepest a receiver can lie from the
// light's plane (fl::PenumbraReach::farDepth). Set by setCriterionUniforms; 0 for JFA-E.
uniform float uUmbraDepth;

// The key of occluder o at a map texel whose surface r lies no deeper than o, so that it may hide
// a receiver in o's umbra: penumbraHit of the stand-in receiver on the ray from the disk's centre
// through r at depth uUmbraDepth, plus radius^2 (ranked after every key of r itself), or -1.
// Operation by operation fl::umbraSideKey on the CPU.
float umbraSideKey(vec3 r, vec3 o) {
    vec3 n = uDiskNormal;
    vec3 c = uDiskCenter;
    precise float dr = abs((r.x - c.x) * n.x + (r.y - c.y) * n.y + (r.z - c.z) * n.z);
    precise float dO = abs((o.x - c.x) * n.x + (o.y - c.y) * n.y + (o.z - c.z) * n.z);
    if (!(dr <= dO * 1.001) || !(dr > 0.0) || !(uUmbraDepth > dr)) return -1.0;
    precise float k = uUmbraDepth / dr;
    precise vec3 p = vec3((r.x - c.x) * k + c.x, (r.y - c.y) * k + c.y, (r.z - c.z) * k + c.z);
    precise float d2 = penumbraHit(p, o);
    if (d2 < 0.0) return -1.0;
    return d2 + uDiskRadius * uDiskRadius;
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
// The receivers' bounds pyramid (reach_bounds.comp.glsl): per cell the min (uReachLo) and max
// (uReachHi) of its receivers' world xyz and light depth (w), 8x8-texel cells at level 0; 0
// levels = none (the scene's deepest point bounds every cone).
layout(binding = FL_TEX_REACH_LO) uniform sampler2D uReachLo;
layout(binding = FL_TEX_REACH_HI) uniform sampler2D uReachHi;
uniform int uReachLevels;
const int kJfaUnboundedReach = 0x3fffffff;
const ivec4 kJfaUnboundedRect = ivec4(-kJfaUnboundedReach, -kJfaUnboundedReach,
                                      kJfaUnboundedReach, kJfaUnboundedReach);

// The texel bounds of the cone's part between light depths d0 and d1 (d0 <= d1): the hull of
// the squares around its two cross-sections (at d0 <= depth of o, the apex itself), projected;
// .x > .z never (unbounded when a corner is behind the projection).
ivec4 penumbraSegmentRect(vec3 o, float depth, float d0, float d1) {
    vec3 n = uDiskNormal;
    // Margins (1%, 1e-3) widen the segment: covers float rounding in the criterion.
    float t0 = max(max((d0 - depth) / depth, 0.0) * 0.99 - 1e-3, 0.0);
    float t1 = max((d1 - depth) / depth, 0.0) * 1.01 + 1e-3;
    vec3 a = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    vec3 u = normalize(cross(n, a));
    vec3 w = cross(normalize(n), u);
    vec2 lo = vec2(1e30), hi = vec2(-1e30);
    bool front = true;
    for (int i = 0; i < 8; ++i) {
        float t = i < 4 ? t0 : t1;
        float radius = t * uDiskRadius * 1.01;
        vec3 q = o + t * (o - uDiskCenter) + ((i & 1) != 0 ? -u : u) * radius +
                 ((i & 2) != 0 ? -w : w) * radius;
        vec4 c = uReachMatrix * vec4(q, 1.0);
        front = front && c.w > 1e-6;
        vec2 texel = (c.xy / c.w * 0.5 + 0.5) * vec2(uReachSize);
        lo = min(lo, texel);
        hi = max(hi, texel);
    }
    if (!front || !(hi.x - lo.x < 1e9 && hi.y - lo.y < 1e9)) return kJfaUnboundedRect;
    return ivec4(ivec2(floor(lo)) - 2, ivec2(floor(hi)) + 2);
}

// Whether the box lo..hi (world) may hold a point of o's cone, the rays from the disk through o
// beyond o. The cone lies inside the right circular cone with apex o, axis a from the disk's
// centre through o, and half-angle asin(r / |o - c|): in the triangle o, c, q (q on the disk,
// |q - c| <= r < |o - c|) the angle at o faces the shorter side q - c, so it is acute and its sine
// is at most r / |o - c|. The box's bounding sphere is tested against that cone exactly (Eberly,
// "Intersection of a sphere and a cone"); margins of 1% cover float rounding.
bool coneMayHold(vec3 o, vec3 a, float sinHalf, float cosHalf, vec4 lo, vec4 hi) {
    if (!(lo.x <= hi.x)) return false; // no receiver in the cell
    vec3 centre = (lo.xyz + hi.xyz) * 0.5;
    float radius = length(hi.xyz - lo.xyz) * 0.5 * 1.01 + 1e-4;
    vec3 d = centre - (o - a * (radius / sinHalf)); // from the apex moved back by r / sin
    float e = dot(a, d);
    if (!(e > 0.0 && e * e >= dot(d, d) * cosHalf * cosHalf)) return false;
    d = centre - o;
    e = -dot(a, d);
    if (e > 0.0 && e * e >= dot(d, d) * sinHalf * sinHalf) return dot(d, d) <= radius * radius;
    return true;
}

// Pyramid cells per axis a seed's rect is first split into (at most uReachCells^2 tested, then
// two finer levels below the cells that pass): PenumbraReach::firstCells.
uniform int uReachCells;

// Whether a cell whose shallowest receiver lies at depth `lo` may hold a surface that takes o on
// the umbra side (umbraSideKey: a surface no deeper than o's depth * 1.001; the pyramid's depth
// may round otherwise than the key's, hence the wider margin).
bool umbraSideMayHold(float depth, float lo) {
    return uUmbraDepth > 0.0 && lo <= depth * 1.002;
}

// Whether cell q of `level` may hold a receiver that takes o (coneMayHold on its bounds, or the
// umbra side's test).
bool cellMayHold(vec3 o, float depth, vec3 a, float sinHalf, float cosHalf, ivec2 q, int level) {
    vec4 lo = texelFetch(uReachLo, q, level);
    return coneMayHold(o, a, sinHalf, cosHalf, lo, texelFetch(uReachHi, q, level)) ||
           (lo.x <= texelFetch(uReachHi, q, level).x && umbraSideMayHold(depth, lo.w));
}

// The cells one level below cell q (.xy first, .zw last) of a level `size` cells wide, the
// level below `childSize`; the last cell also has the odd cell left over below it. At level 0
// (no level below), q itself.
ivec4 childCells(ivec2 q, int level, ivec2 size, ivec2 childSize) {
    if (level == 0) return ivec4(q, q);
    return ivec4(q * 2, mix(q * 2 + 1, childSize - 1, equal(q, size - 1)));
}

// `u` grown by the texels of finest cell q (of a level `size` cells wide) that can take o: none
// when its receivers all lie above o or (with `test`) its box misses the cone, else those the
// cone's part between the cell's receiver depths covers. The last cell also holds the rest of
// the grid.
ivec4 keepCell(vec3 o, float depth, vec3 a, float sinHalf, float cosHalf, ivec2 q, int level,
               ivec2 size, bool test, ivec4 u) {
    vec4 cellLo = texelFetch(uReachLo, q, level);
    vec4 cellHi = texelFetch(uReachHi, q, level);
    float deepest = cellHi.w * 1.001 + 1e-4;
    // A surface on the umbra side takes o for its stand-in at uUmbraDepth: the cone down there.
    bool umbra = cellLo.x <= cellHi.x && umbraSideMayHold(depth, cellLo.w);
    if (!umbra &&
        (!(deepest > depth) || (test && !coneMayHold(o, a, sinHalf, cosHalf, cellLo, cellHi))))
        return u;
    int side = 8 << level;
    ivec4 seg = umbra ? penumbraSegmentRect(o, depth, depth, max(deepest, uUmbraDepth))
                      : penumbraSegmentRect(o, depth, cellLo.w * 0.999 - 1e-4, deepest);
    ivec2 p0 = max(q * side, seg.xy);
    ivec2 p1 = min(mix((q + 1) * side - 1, uReachSize - 1, equal(q, size - 1)), seg.zw);
    if (p0.x > p1.x || p0.y > p1.y) return u;
    return ivec4(min(u.xy, p0), max(u.zw, p1));
}

// Texels x0..x1 (.x, .z), y0..y1 (.y, .w) that can take occluder o. The cone is first cut at the
// deepest receiver of the grid (the pyramid's top), else the scene's deepest point. With the
// pyramid, the cells of that rect (at most 8 x 8 of them) whose receivers' boxes the cone misses
// are dropped, then the children of those kept, twice; the rect is the union of the cells kept
// at the finest level, within the first rect. A receiver that takes o lies in the cone and in the
// box of every cell above it, so its cell is kept at every level.
ivec4 penumbraRect(vec3 o) {
    if (uReachEnabled == 0) return kJfaUnboundedRect;
    float depth = abs(dot(o - uDiskCenter, uDiskNormal));
    if (!(depth > 1e-6)) return kJfaUnboundedRect;
    float first = uReachLevels == 0
                      ? uReachFarDepth
                      : texelFetch(uReachHi, ivec2(0), uReachLevels - 1).w * 1.001 + 1e-4;
    // The umbra side's stand-in receivers lie at uUmbraDepth (umbraSideKey).
    first = max(first, uUmbraDepth);
    ivec4 r = penumbraSegmentRect(o, depth, depth, first);
    vec3 oc = o - uDiskCenter;
    float sinHalf = uDiskRadius * 1.01 / length(oc);
    if (uReachLevels == 0 || !(sinHalf < 0.999)) return r;
    float cosHalf = sqrt(1.0 - sinHalf * sinHalf) * 0.99;
    vec3 a = normalize(oc);
    ivec2 lo = max(r.xy, ivec2(0)), hi = min(r.zw, uReachSize - 1);
    if (lo.x > hi.x || lo.y > hi.y) return ivec4(1, 1, 0, 0); // off the grid: no receiver
    // The level whose cells are wide enough that the rect spans at most uReachCells of them.
    int level = 0;
    while (level + 1 < uReachLevels &&
           any(greaterThan(hi / (8 << level) - lo / (8 << level), ivec2(uReachCells - 1))))
        ++level;
    // Level sizes from the grid, not textureSize(lod): llvmpipe (Mesa 22.3) answers that with the
    // next level's size, which clamped the query to half the cells and cut cones short (band !=
    // full on flood-E; tests/jfae_gltest.cpp).
    ivec2 grid = (uReachSize + 7) / 8;
    ivec2 size0 = max(grid >> level, ivec2(1));
    ivec2 c0 = min(lo / (8 << level), size0 - 1), c1 = min(hi / (8 << level), size0 - 1);
    int level1 = max(level - 1, 0), level2 = max(level - 2, 0);
    ivec2 size1 = max(grid >> level1, ivec2(1)), size2 = max(grid >> level2, ivec2(1));
    ivec4 u = ivec4(kJfaUnboundedReach, kJfaUnboundedReach, -kJfaUnboundedReach,
                    -kJfaUnboundedReach);
    for (int y0 = c0.y; y0 <= c1.y; ++y0) {
        for (int x0 = c0.x; x0 <= c1.x; ++x0) {
            ivec2 q0 = ivec2(x0, y0);
            if (!cellMayHold(o, depth, a, sinHalf, cosHalf, q0, level)) continue;
            ivec4 k = childCells(q0, level, size0, size1);
            for (int y1 = k.y; y1 <= k.w; ++y1) {
                for (int x1 = k.x; x1 <= k.z; ++x1) {
                    ivec2 q1 = ivec2(x1, y1);
                    if (level > 0 && !cellMayHold(o, depth, a, sinHalf, cosHalf, q1, level1)) continue;
                    ivec4 m = childCells(q1, level1, size1, size2);
                    for (int y2 = m.y; y2 <= m.w; ++y2)
                        for (int x2 = m.x; x2 <= m.z; ++x2)
                            u = keepCell(o, depth, a, sinHalf, cosHalf, ivec2(x2, y2), level2,
                                         size2, level > 1, u);
                }
            }
        }
    }
    return ivec4(max(u.xy, r.xy), min(u.zw, r.zw));
}
