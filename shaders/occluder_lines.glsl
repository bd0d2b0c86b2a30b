// An occluder's silhouette near a shadow-map texel as straight edges at sub-texel precision, and
// the share of the disk light a receiver sees past them: JFA-L's lookup and JFA-E's composite
// recompute a penumbra pixel's visibility with these, from the occluder texel the flood chose.
// Needs disk_light.glsl, shadow_map_decode.glsl and occluder_edge.glsl. CPU twin:
// renderer/soft/OccluderLines.h, operation for operation.
//
// Why lines, not the flood's occluder point: a point says how far the edge lies from the disk's
// centre but not which way it runs, so each point stands for a chord at right angles to cq, and
// the points sit on texel centres (or half a texel out). Where a penumbra is a few texels wide,
// the chord's distance then jumps from texel to texel (a comb), and which side of the edge the
// centre lies on comes from the pixel's own hard-shadow test, a staircase of map texels: the
// value flips between v and 1 - v across each step. Behind an occluder one or two texels wide
// (a leg, a wire) both sides of the texel are edges and the point stays at its centre, inside
// the occluder, so its ray reaches the disk near the centre and the umbra is lit.
//
// Here the texels of a 5 x 5 window are covered (the occluder or nearer: not across a silhouette
// edge from the centre texel) or not. Each covered / uncovered pair of axis neighbours puts an
// edge sample at its midpoint; for a straight edge sampled at texel centres these scatter evenly
// about the true edge, so their mean lies on it to a fraction of a texel. Their principal axis
// is the edge's direction. Samples whose uncovered side faces one way make one edge, the other
// way a second edge (a strip one to four texels wide, or a slit). Each edge is a line at the
// centre texel's light depth, and a receiver sees the part of the disk beyond it: the plane
// through the receiver and the line meets the light's plane in a chord, whose signed distance
// from the centre gives the share (segmentFraction), continuous across the hard edge.

const int kLineWindow = 2; // the window's radius in texels

// Up to two straight edges of the occluder at a texel, in world space.
struct OccluderLines {
    int count;     // 0: none found (no covered / uncovered neighbours), else 1 or 2
    bool slit;     // two edges whose uncovered sides face each other (else a strip between them)
    vec3 point[2]; // a point of each edge
    vec3 tangent;  // the edges' direction (both run the same way)
    vec3 open[2];  // from each edge towards its uncovered side
};

// The receiver's plane in the light's clip space: dot(result, clip) = 0 for the clip-space
// point of every world point of the plane through `p` with normal `n`.
vec4 lightClipPlane(vec3 p, vec3 n) {
    return transpose(uMapInverseLightViewProj) * vec4(n, -dot(n, p));
}

// The light's NDC depth at which the ray of map coordinate `tc` meets the clip-space plane,
// or 2 (beyond the far plane) where it runs parallel to it.
float planeDepthAt(vec4 plane, vec2 tc, vec2 size) {
    vec3 l = mapClipRay(tc, size);
    float den = plane.z * l.z;
    if (!(abs(den) > 1e-30)) return 2.0;
    return -(plane.x * l.x + plane.y * l.y + plane.w * l.z) / den;
}

// The window around texel t, for the receiver whose plane is `plane` (lightClipPlane): each
// texel 0 outside the map, 1 uncovered, 2 covered, and its depth. Covered means the light's
// centre sees something nearer than that plane there, by more than two texels' change of the
// plane's depth (so that the plane itself never counts).
struct LineWindow {
    int cover[(2 * kLineWindow + 1) * (2 * kLineWindow + 1)];
    float depth[(2 * kLineWindow + 1) * (2 * kLineWindow + 1)];
};

LineWindow lineWindow(sampler2D receivers, ivec2 t, vec4 plane) {
    LineWindow win;
    ivec2 size = textureSize(receivers, 0);
    vec2 fsize = vec2(size);
    const int n = 2 * kLineWindow + 1;
    vec2 c = vec2(t) + 0.5;
    float d0 = planeDepthAt(plane, c, fsize);
    float margin = 2.0 * max(abs(planeDepthAt(plane, c + vec2(1.0, 0.0), fsize) - d0),
                             abs(planeDepthAt(plane, c + vec2(0.0, 1.0), fsize) - d0)) +
                   1e-6;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            ivec2 q = t + ivec2(i - kLineWindow, j - kLineWindow);
            int k = j * n + i;
            win.cover[k] = 0; // outside the map: neither
            win.depth[k] = 0.0;
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            float d = texelFetch(receivers, q, 0).r;
            win.depth[k] = d;
            bool covered = d != kMapNoReceiver &&
                           d < planeDepthAt(plane, vec2(q) + 0.5, fsize) - margin;
            win.cover[k] = covered ? 2 : 1;
        }
    }
    return win;
}

// An edge sample: axis neighbours k and k1 of the window of which one is covered and the other
// not. Its midpoint (relative to t's centre), the direction from the covered one to the other,
// the covered one's depth, and its weight (less towards the window's border, so that the fit
// moves smoothly as the window moves along an edge); false for no sample.
bool lineSample(LineWindow win, int i, int j, int axis, out vec2 mid, out vec2 open,
                out float depth, out float weight) {
    const int n = 2 * kLineWindow + 1;
    int i1 = i + (axis == 0 ? 1 : 0), j1 = j + (axis == 1 ? 1 : 0);
    mid = vec2(0.0);
    open = vec2(0.0);
    depth = 0.0;
    weight = 0.0;
    if (i1 >= n || j1 >= n) return false;
    int a = win.cover[j * n + i], b = win.cover[j1 * n + i1];
    if (a == 0 || b == 0 || a == b) return false;
    vec2 step = axis == 0 ? vec2(1.0, 0.0) : vec2(0.0, 1.0);
    mid = vec2(i - kLineWindow, j - kLineWindow) + 0.5 * step;
    open = a == 2 ? step : -step;
    depth = a == 2 ? win.depth[j * n + i] : win.depth[j1 * n + i1];
    float r2 = dot(mid, mid) / float((kLineWindow + 1) * (kLineWindow + 1));
    weight = max(1.0 - r2, 0.0) * max(1.0 - r2, 0.0);
    return true;
}

// The occluder's edges near texel t as the receiver at p with normal `n` sees them. The samples
// are visited twice in the same order, first for their principal axis, then for the edges, so
// that none is stored (an array indexed at run time costs a software rasteriser a gather per
// access).
OccluderLines occluderLines(sampler2D receivers, ivec2 t, vec3 p, vec3 n) {
    OccluderLines L;
    L.count = 0;
    L.slit = false;
    LineWindow win = lineWindow(receivers, t, lightClipPlane(p, n));
    const int side = 2 * kLineWindow + 1;
    int samples = 0;
    float total = 0.0;
    vec2 sum1 = vec2(0.0);
    vec3 sum2 = vec3(0.0); // xx, yy, xy
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i)
            for (int axis = 0; axis < 2; ++axis) {
                vec2 mid, open;
                float depth, w;
                if (!lineSample(win, i, j, axis, mid, open, depth, w)) continue;
                ++samples;
                total += w;
                sum1 += w * mid;
                sum2 += w * vec3(mid.x * mid.x, mid.y * mid.y, mid.x * mid.y);
            }
    if (samples < 2 || !(total > 0.0)) return L;
    vec2 mean = sum1 / total;
    vec3 m2 = sum2 / total - vec3(mean.x * mean.x, mean.y * mean.y, mean.x * mean.y);
    float angle = 0.5 * atan(2.0 * m2.z, m2.x - m2.y);
    vec2 dir = vec2(cos(angle), sin(angle));
    vec2 nrm = vec2(-dir.y, dir.x);
    // Edge 0 opens towards +nrm, edge 1 towards -nrm; samples across the axis (a corner's other
    // leg) belong to neither.
    vec2 sum[2] = vec2[2](vec2(0.0), vec2(0.0));
    float depthSum[2] = float[2](0.0, 0.0);
    float count[2] = float[2](0.0, 0.0);
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i)
            for (int axis = 0; axis < 2; ++axis) {
                vec2 mid, open;
                float depth, w;
                if (!lineSample(win, i, j, axis, mid, open, depth, w)) continue;
                float along = dot(open, nrm);
                if (abs(along) < 0.3 || !(w > 0.0)) continue;
                if (along > 0.0) {
                    sum[0] += w * mid;
                    depthSum[0] += w * depth;
                    count[0] += w;
                } else {
                    sum[1] += w * mid;
                    depthSum[1] += w * depth;
                    count[1] += w;
                }
            }
    vec2 size = vec2(textureSize(receivers, 0));
    vec2 centre = vec2(t) + 0.5;
    vec2 at[2] = vec2[2](vec2(0.0), vec2(0.0));
    float atDepth[2] = float[2](0.0, 0.0);
    vec2 opens[2] = vec2[2](nrm, -nrm);
    for (int e = 0; e < 2; ++e) {
        if (!(count[e] > 0.0)) continue;
        vec2 c = sum[e] / count[e];
        vec2 a = c - dir * dot(c, dir); // the edge's point nearest t's centre
        float d = depthSum[e] / count[e];
        vec3 point = mapUnproject(centre + a, size, d);
        vec3 open = mapUnproject(centre + a + opens[e], size, d) - point;
        if (L.count == 0) {
            at[0] = a;
            atDepth[0] = d;
            L.point[0] = point;
            L.open[0] = open;
        } else {
            at[1] = a;
            atDepth[1] = d;
            L.point[1] = point;
            L.open[1] = open;
        }
        ++L.count;
    }
    if (L.count == 0) return L;
    L.tangent = mapUnproject(centre + at[0] + dir, size, atDepth[0]) - L.point[0];
    // A strip has its covered texels between the edges: edge 0 (opening to +nrm) lies on the
    // +nrm side of edge 1.
    if (L.count == 2) L.slit = dot(at[0] - at[1], nrm) < 0.0;
    return L;
}

// The chord that the edge through `e` along `tangent`, uncovered towards `open`, cuts from the
// light's plane as receiver p sees it: the plane through p and the edge meets the light's plane
// in a line; u (unit, in the light's plane, at right angles to the line, pointing to the
// uncovered side) and s, the centre's signed distance from the line (positive on the uncovered
// side). False when the edge is not between p and the light.
bool lineChord(vec3 p, vec3 e, vec3 tangent, vec3 open, out vec3 u, out float s) {
    u = vec3(0.0);
    s = 0.0;
    float dp = dot(p - uDiskCenter, uDiskNormal);
    float de = dot(e - uDiskCenter, uDiskNormal);
    if (!(de > 0.0 && de < dp)) return false;
    vec3 m = cross(tangent, e - p);
    float len = length(m);
    if (!(len > 0.0)) return false;
    m /= len;
    if (dot(m, open) < 0.0) m = -m;
    vec3 inPlane = m - dot(m, uDiskNormal) * uDiskNormal;
    float sinA = length(inPlane);
    if (!(sinA > 1e-6)) return false;
    u = inPlane / sinA;
    s = dot(uDiskCenter - p, m) / sinA;
    return true;
}

// The share of the disk on the uncovered side of a chord at signed distance s from the centre.
float chordOpenShare(float s) {
    if (!(uDiskRadius > 0.0)) return s >= 0.0 ? 1.0 : 0.0;
    float seg = segmentFraction(abs(s) / uDiskRadius);
    return s >= 0.0 ? 1.0 - seg : seg;
}

// The share of the disk receiver p sees past one edge, or -1 when it is not between p and the
// light.
float lineOpenShare(vec3 p, vec3 e, vec3 tangent, vec3 open) {
    vec3 u;
    float s;
    if (!lineChord(p, e, tangent, open, u, s)) return -1.0;
    return chordOpenShare(s);
}

// The visible share of the disk at p past the occluder's edges L (count > 0), or -1 when no edge
// lies between p and the light: one edge, or a strip (what passes either edge), or a slit (what
// passes both).
float occluderLinesVisibility(vec3 p, OccluderLines L) {
    float a = lineOpenShare(p, L.point[0], L.tangent, L.open[0]);
    if (L.count == 1) return a;
    float b = lineOpenShare(p, L.point[1], L.tangent, L.open[1]);
    if (a < 0.0 || b < 0.0) return max(a, b);
    return L.slit ? max(a + b - 1.0, 0.0) : min(a + b, 1.0);
}

#ifdef OCCLUDER_LINES_FUSE
// Occluders fused: the edges give the exact share of the disk an occluder leaves open, but
// another occluder may cover part of that share (a second fin under the first, the head behind
// an ear, the next finger). Sixteen points spread evenly over the disk (Vogel's spiral, in the
// frame of the first chord) are tested where they lie in the open part: the ray from p to each
// crosses the edge's depth at x, and the light's centre sees, at the point of p's own plane on
// its ray through x, something nearer (the map's depth test fails) or not. Like PCSS's filter
// against the receiver's plane with the edge's depth as the blocker's, an occluder is taken as
// reaching down to p's plane. The share is the exact open share times the open points' part of
// those tested; with no point in the open part, the exact share. Needs shadow_lookup.glsl.
// `plane`: p's surface normal.

// A chord of the disk: the point c + x of the light's plane (x in it) lies on its open side
// when dot(x, u) > -s (u unit, s the centre's signed distance from the chord).
struct DiskChord {
    vec3 u;
    float s;
};

const int kFuseSamples = 16;

// Whether x (from the disk's centre, in its plane) passes chords a (and b, with `two`): one
// chord; a strip (either chord open); a slit (both open).
bool chordsOpen(vec3 x, DiskChord a, DiskChord b, bool two, bool slit) {
    bool oa = dot(x, a.u) > -a.s;
    if (!two) return oa;
    bool ob = dot(x, b.u) > -b.s;
    return slit ? oa && ob : oa || ob;
}

// Whether the light's centre sees, at the point of p's plane on its ray through `crossing`,
// nothing nearer (the map's depth test passes). `planeAtCentre`: dot(p - centre, plane).
bool fusedRayOpen(vec3 crossing, vec3 plane, float planeAtCentre) {
    float den = dot(crossing - uDiskCenter, plane);
    if (!(abs(den) > 0.0)) return true;
    vec3 y = uDiskCenter + (crossing - uDiskCenter) * (planeAtCentre / den);
    vec3 uvz;
    return !shadowCoord(y, uvz) || texture(uShadowMap, uvz) > 0.5;
}

// `share` (the exact open share of the chords) times the part of the open sample points that
// the map finds open at p's plane, their rays crossing the occluder's light depth `de`.
// Points whose ray crosses within a texel and a half of the edge (of a chord they pass; `texel`
// the world size of the map's texel at the edge's depth) are not tested: the map cannot tell
// that side of a texel from the other, and the chord has them exactly.
// `own`: the light depth of the occluder the light's centre sees over p (its own texel's, for a
// point in the hard shadow; 0 for none): where it lies at another depth than the edge, a ray is
// also tested where it crosses that depth, so the occluder right over p blocks what passes
// beyond a farther edge.
float fusedShare(vec3 p, vec3 plane, float de, float share, DiskChord a, DiskChord b, bool two,
                 bool slit, float texel, float own) {
    if (!(share > 0.0) || !(uDiskRadius > 0.0)) return share;
    float dp = dot(p - uDiskCenter, uDiskNormal);
    if (!(de < dp)) return share;
    float planeAtCentre = dot(p - uDiskCenter, plane);
    bool ownLayer = own > 0.0 && own < dp && abs(own - de) > 0.02 * dp;
    // A point's distance beyond a chord, scaled to the edge's depth, in texels there.
    float toTexels = (dp - de) / dp / max(texel, 1e-30);
    vec3 v = cross(uDiskNormal, a.u);
    int tested = 0;
    int open = 0;
    for (int k = 0; k < kFuseSamples; ++k) {
        float radius = uDiskRadius * sqrt((float(k) + 0.5) / float(kFuseSamples));
        float angle = 2.39996323 * float(k);
        vec3 x = radius * (cos(angle) * a.u + sin(angle) * v);
        if (!chordsOpen(x, a, b, two, slit)) continue;
        ++tested;
        vec3 q = uDiskCenter + x;
        vec3 crossing = p + (q - p) * ((dp - de) / dp);
        float beyondA = (dot(x, a.u) + a.s) * toTexels;
        float beyondB = two ? (dot(x, b.u) + b.s) * toTexels : -1.0;
        bool near = (beyondA >= 0.0 && beyondA < 1.5) || (beyondB >= 0.0 && beyondB < 1.5);
        if (near) {
            ++open;
            continue;
        }
        bool lit = fusedRayOpen(crossing, plane, planeAtCentre);
        if (lit && ownLayer) lit = fusedRayOpen(p + (q - p) * ((dp - own) / dp), plane, planeAtCentre);
        open += lit ? 1 : 0;
    }
    return tested == 0 ? share : share * float(open) / float(tested);
}

// occluderLinesVisibility with other occluders fused in (fusedShare).
float occluderLinesVisibilityFused(vec3 p, vec3 plane, OccluderLines L, float own) {
    DiskChord c[2];
    bool ok[2] = bool[2](false, false);
    float share[2] = float[2](-1.0, -1.0);
    for (int k = 0; k < L.count; ++k) {
        ok[k] = lineChord(p, L.point[k], L.tangent, L.open[k], c[k].u, c[k].s);
        if (ok[k]) share[k] = chordOpenShare(c[k].s);
    }
    float de = dot(L.point[0] - uDiskCenter, uDiskNormal);
    if (L.count == 1 || !ok[0] || !ok[1]) {
        int k = ok[0] ? 0 : 1;
        if (!ok[k]) return -1.0;
        return fusedShare(p, plane, dot(L.point[k] - uDiskCenter, uDiskNormal), share[k], c[k],
                          c[k], false, false, length(L.open[k]), own);
    }
    float both = L.slit ? max(share[0] + share[1] - 1.0, 0.0) : min(share[0] + share[1], 1.0);
    return fusedShare(p, plane, de, both, c[0], c[1], true, L.slit, length(L.open[0]), own);
}

// The thesis' occluder point o (the flood's, where no edge was found) fused the same way: its
// chord passes through q (where the ray from p through o meets the light's plane) at right
// angles to cq, covering the centre inside the hard shadow and not outside. -1 for a miss.
float occluderPointVisibilityFused(vec3 p, vec3 plane, vec3 o, bool inside, float own) {
    float share = occluderIntensity(p, o, inside);
    if (!(share > 0.0)) return share;
    float dp = dot(p - uDiskCenter, uDiskNormal);
    float dO = dot(o - uDiskCenter, uDiskNormal);
    vec3 q = p + (o - p) * (dp / (dp - dO));
    vec3 cq = q - uDiskCenter;
    cq -= dot(cq, uDiskNormal) * uDiskNormal;
    float d = length(cq);
    if (!(d > 0.0)) return share;
    DiskChord c;
    c.u = inside ? cq / d : -cq / d;
    c.s = inside ? -d : d;
    // Its chord is only as good as the point: inside the hard shadow every point of the small
    // part past it is tested (no texel is trusted: another occluder there is what lit umbrae);
    // outside, the ones within a texel and a half of it are not (the map there would darken
    // the lit side of a single straight edge).
    return fusedShare(p, plane, dO, share, c, c, false, false, inside ? 0.0 : shadowTexelWorld(o),
                      own);
}

// A penumbra point's share (JFA-L's lookup, JFA-E's composite): from its occluder's edges
// `lines`, or where none were found from the occluder point o, fused; -1 where neither shades p.
// `own`: p's texel of the receiver target, whose occluder the fused test also crosses inside the
// hard shadow. A borrowed occluder (a neighbour's, for a penumbra's outermost ring that the flood
// missed) counts only through its edges, and only where they leave p on its own side of the hard
// edge: it softens that ring and nothing else.
float occluderShareFused(sampler2D receivers, ivec2 own, vec3 p, vec3 plane, OccluderLines lines,
                         vec3 o, bool inside, bool borrowed) {
    vec4 over = mapReceiver(receivers, own);
    float ownDepth = inside && over.w != 0.0 ? dot(over.xyz - uDiskCenter, uDiskNormal) : 0.0;
    float l = lines.count > 0 ? occluderLinesVisibilityFused(p, plane, lines, ownDepth)
              : borrowed      ? -1.0
                              : occluderPointVisibilityFused(p, plane, o, inside, ownDepth);
    if (borrowed && (inside ? l > 0.5 : l < 0.5)) l = -1.0;
    return l;
}
#endif
