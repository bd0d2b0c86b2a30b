#include <renderer/soft/OccluderLines.h>

#include <renderer/passes/ShadowMapDecode.h>
#include <renderer/passes/TerminatorLift.h>
#include <renderer/soft/FilteredShadow.h>

#include <gpu/ReadBack.h>

#include <algorithm>
#include <cmath>

namespace fl {

namespace {

constexpr int kLineWindow = 2; // the window's radius in texels
constexpr int kLineSide = 2 * kLineWindow + 1;
constexpr int kFuseSamples = 16;

glm::vec3 mapUnproject(const LineMap& m, glm::vec2 tc, float d) {
    return shadowmap::unproject(tc, d, m.size, m.unwarp, m.inverseLightViewProj);
}

glm::vec4 lightClipPlane(const LineMap& m, glm::vec3 p, glm::vec3 n) {
    return glm::transpose(m.inverseLightViewProj) * glm::vec4(n, -glm::dot(n, p));
}

float planeDepthAt(const LineMap& m, glm::vec4 plane, glm::vec2 tc) {
    const glm::vec3 l = shadowmap::clipRay(tc, m.size, m.unwarp);
    const float den = plane.z * l.z;
    if (!(std::abs(den) > 1e-30f)) return 2.0f;
    return -(plane.x * l.x + plane.y * l.y + plane.w * l.z) / den;
}

struct LineWindow {
    int cover[kLineSide * kLineSide];
    float depth[kLineSide * kLineSide];
};

LineWindow lineWindow(const LineMap& m, glm::ivec2 t, glm::vec4 plane) {
    LineWindow win{};
    const glm::vec2 c = glm::vec2(t) + 0.5f;
    const float d0 = planeDepthAt(m, plane, c);
    const float margin =
        2.0f * std::max(std::abs(planeDepthAt(m, plane, c + glm::vec2(1.0f, 0.0f)) - d0),
                        std::abs(planeDepthAt(m, plane, c + glm::vec2(0.0f, 1.0f)) - d0)) +
        1e-6f;
    for (int j = 0; j < kLineSide; ++j)
        for (int i = 0; i < kLineSide; ++i) {
            const glm::ivec2 q = t + glm::ivec2(i - kLineWindow, j - kLineWindow);
            const int k = j * kLineSide + i;
            win.cover[k] = 0;
            win.depth[k] = 0.0f;
            if (q.x < 0 || q.y < 0 || q.x >= m.size || q.y >= m.size) continue;
            const float d = m.receiverDepth[std::size_t(q.y) * std::size_t(m.size) + q.x];
            win.depth[k] = d;
            const bool covered = d != shadowmap::kNoReceiver &&
                                 d < planeDepthAt(m, plane, glm::vec2(q) + 0.5f) - margin;
            win.cover[k] = covered ? 2 : 1;
        }
    return win;
}

struct LineSample {
    glm::vec2 mid{0.0f}, open{0.0f};
    float depth = 0.0f, weight = 0.0f;
};

// lineSample() in GLSL: axis neighbours (i, j) and the next along `axis`.
bool lineSample(const LineWindow& win, int i, int j, int axis, LineSample& s) {
    const int i1 = i + (axis == 0 ? 1 : 0), j1 = j + (axis == 1 ? 1 : 0);
    s = {};
    if (i1 >= kLineSide || j1 >= kLineSide) return false;
    const int a = win.cover[j * kLineSide + i], b = win.cover[j1 * kLineSide + i1];
    if (a == 0 || b == 0 || a == b) return false;
    const glm::vec2 step = axis == 0 ? glm::vec2(1.0f, 0.0f) : glm::vec2(0.0f, 1.0f);
    s.mid = glm::vec2(i - kLineWindow, j - kLineWindow) + 0.5f * step;
    s.open = a == 2 ? step : -step;
    s.depth = a == 2 ? win.depth[j * kLineSide + i] : win.depth[j1 * kLineSide + i1];
    const float r2 = glm::dot(s.mid, s.mid) / float((kLineWindow + 1) * (kLineWindow + 1));
    s.weight = std::max(1.0f - r2, 0.0f) * std::max(1.0f - r2, 0.0f);
    return true;
}

struct DiskChord {
    glm::vec3 u{0.0f};
    float s = 0.0f;
};

bool lineChord(const DiskLight& l, glm::vec3 p, glm::vec3 e, glm::vec3 tangent, glm::vec3 open,
               DiskChord& c) {
    c = {};
    const float dp = glm::dot(p - l.center, l.normal);
    const float de = glm::dot(e - l.center, l.normal);
    if (!(de > 0.0f && de < dp)) return false;
    glm::vec3 m = glm::cross(tangent, e - p);
    const float len = glm::length(m);
    if (!(len > 0.0f)) return false;
    m /= len;
    if (glm::dot(m, open) < 0.0f) m = -m;
    const glm::vec3 inPlane = m - glm::dot(m, l.normal) * l.normal;
    const float sinA = glm::length(inPlane);
    if (!(sinA > 1e-6f)) return false;
    c.u = inPlane / sinA;
    c.s = glm::dot(l.center - p, m) / sinA;
    return true;
}

float chordOpenShare(const DiskLight& l, float s) {
    if (!(l.radius > 0.0f)) return s >= 0.0f ? 1.0f : 0.0f;
    const float seg = segmentFraction(std::abs(s) / l.radius);
    return s >= 0.0f ? 1.0f - seg : seg;
}

bool chordsOpen(glm::vec3 x, const DiskChord& a, const DiskChord& b, bool two, bool slit) {
    const bool oa = glm::dot(x, a.u) > -a.s;
    if (!two) return oa;
    const bool ob = glm::dot(x, b.u) > -b.s;
    return slit ? oa && ob : oa || ob;
}

bool fusedRayOpen(const LineMap& m, glm::vec3 crossing, glm::vec3 plane, float planeAtCentre) {
    const DiskLight& l = m.light;
    const float den = glm::dot(crossing - l.center, plane);
    if (!(std::abs(den) > 0.0f)) return true;
    const glm::vec3 y = l.center + (crossing - l.center) * (planeAtCentre / den);
    return lineMapHardShadow(m, y) > 0.5f;
}

float fusedShare(const LineMap& m, glm::vec3 p, glm::vec3 plane, float de, float share,
                 const DiskChord& a, const DiskChord& b, bool two, bool slit, float texel,
                 float own) {
    const DiskLight& l = m.light;
    if (!(share > 0.0f) || !(l.radius > 0.0f)) return share;
    const float dp = glm::dot(p - l.center, l.normal);
    if (!(de < dp)) return share;
    const float planeAtCentre = glm::dot(p - l.center, plane);
    const bool ownLayer = own > 0.0f && own < dp && std::abs(own - de) > 0.02f * dp;
    const float toTexels = (dp - de) / dp / std::max(texel, 1e-30f);
    const glm::vec3 v = glm::cross(l.normal, a.u);
    int tested = 0, open = 0;
    for (int k = 0; k < kFuseSamples; ++k) {
        const float radius = l.radius * std::sqrt((float(k) + 0.5f) / float(kFuseSamples));
        const float angle = 2.39996323f * float(k);
        const glm::vec3 x = radius * (std::cos(angle) * a.u + std::sin(angle) * v);
        if (!chordsOpen(x, a, b, two, slit)) continue;
        ++tested;
        const glm::vec3 q = l.center + x;
        const glm::vec3 crossing = p + (q - p) * ((dp - de) / dp);
        const float beyondA = (glm::dot(x, a.u) + a.s) * toTexels;
        const float beyondB = two ? (glm::dot(x, b.u) + b.s) * toTexels : -1.0f;
        const bool near =
            (beyondA >= 0.0f && beyondA < 1.5f) || (beyondB >= 0.0f && beyondB < 1.5f);
        if (near) {
            ++open;
            continue;
        }
        bool lit = fusedRayOpen(m, crossing, plane, planeAtCentre);
        if (lit && ownLayer)
            lit = fusedRayOpen(m, p + (q - p) * ((dp - own) / dp), plane, planeAtCentre);
        open += lit ? 1 : 0;
    }
    return tested == 0 ? share : share * float(open) / float(tested);
}

} // namespace

LineMap readLineMap(const ShadowMapPass::Outputs& shadow, const DiskLight& light) {
    LineMap m;
    m.size = shadow.depth.width();
    m.depth = readDepthMap(shadow.depth);
    if (shadow.receivers) {
        m.receiverDepth = gl::readTexels<float>(*shadow.receivers->depth, GL_RED, GL_FLOAT);
        gl::throwIfErrors("receiver target read-back");
        m.unwarp = shadow.receivers->unwarp;
        m.inverseLightViewProj = shadow.receivers->inverseLightViewProj;
    }
    m.lightViewProj = shadow.lightViewProj;
    m.warp = shadow.warp;
    m.light = light;
    return m;
}

glm::vec4 lineMapReceiver(const LineMap& m, glm::ivec2 t) {
    return shadowmap::receiverPosition(
        m.receiverDepth[std::size_t(t.y) * std::size_t(m.size) + t.x], t, m.size, m.unwarp,
        m.inverseLightViewProj);
}

float lineMapDepth(const LineMap& m, glm::ivec2 t) {
    const float d = m.receiverDepth[std::size_t(t.y) * std::size_t(m.size) + t.x];
    if (d == shadowmap::kNoReceiver) return 0.0f;
    const glm::vec3 p = mapUnproject(m, glm::vec2(t) + 0.5f, d);
    return glm::dot(p - m.light.center, m.light.normal);
}

float lineMapHardShadow(const LineMap& m, glm::vec3 p) {
    // shadow_lookup.glsl's shadowCoord: lit off the map or behind the light.
    const std::optional<glm::vec3> coord = shadowmap::mapCoord(m.lightViewProj, m.warp, p);
    if (!coord || glm::any(glm::lessThan(*coord, glm::vec3(0.0f))) ||
        glm::any(glm::greaterThan(*coord, glm::vec3(1.0f))))
        return 1.0f;
    const glm::vec3 uvz = *coord;
    const int x = std::clamp(int(std::floor(uvz.x * float(m.size))), 0, m.size - 1);
    const int y = std::clamp(int(std::floor(uvz.y * float(m.size))), 0, m.size - 1);
    return uvz.z <= m.depth[std::size_t(y) * std::size_t(m.size) + x] ? 1.0f : 0.0f;
}

OccluderLines occluderLines(const LineMap& m, glm::ivec2 t, glm::vec3 p, glm::vec3 n) {
    OccluderLines lines;
    const LineWindow win = lineWindow(m, t, lightClipPlane(m, p, n));
    int samples = 0;
    float total = 0.0f;
    glm::vec2 sum1(0.0f);
    glm::vec3 sum2(0.0f);
    LineSample s;
    for (int j = 0; j < kLineSide; ++j)
        for (int i = 0; i < kLineSide; ++i)
            for (int axis = 0; axis < 2; ++axis) {
                if (!lineSample(win, i, j, axis, s)) continue;
                ++samples;
                total += s.weight;
                sum1 += s.weight * s.mid;
                sum2 +=
                    s.weight * glm::vec3(s.mid.x * s.mid.x, s.mid.y * s.mid.y, s.mid.x * s.mid.y);
            }
    if (samples < 2 || !(total > 0.0f)) return lines;
    const glm::vec2 mean = sum1 / total;
    const glm::vec3 m2 =
        sum2 / total - glm::vec3(mean.x * mean.x, mean.y * mean.y, mean.x * mean.y);
    const float angle = 0.5f * std::atan2(2.0f * m2.z, m2.x - m2.y);
    const glm::vec2 dir(std::cos(angle), std::sin(angle));
    const glm::vec2 nrm(-dir.y, dir.x);
    // Edge 0 opens towards +nrm, edge 1 towards -nrm; samples across (a corner's other leg)
    // belong to neither.
    glm::vec2 sum[2]{glm::vec2(0.0f), glm::vec2(0.0f)};
    float depthSum[2]{0.0f, 0.0f}, count[2]{0.0f, 0.0f};
    for (int j = 0; j < kLineSide; ++j)
        for (int i = 0; i < kLineSide; ++i)
            for (int axis = 0; axis < 2; ++axis) {
                if (!lineSample(win, i, j, axis, s)) continue;
                const float along = glm::dot(s.open, nrm);
                if (std::abs(along) < 0.3f || !(s.weight > 0.0f)) continue;
                const int e = along > 0.0f ? 0 : 1;
                sum[e] += s.weight * s.mid;
                depthSum[e] += s.weight * s.depth;
                count[e] += s.weight;
            }
    const glm::vec2 centre = glm::vec2(t) + 0.5f;
    glm::vec2 at[2]{};
    float atDepth[2]{};
    for (int e = 0; e < 2; ++e) {
        if (!(count[e] > 0.0f)) continue;
        const glm::vec2 c = sum[e] / count[e];
        const int k = lines.count++;
        at[k] = c - dir * glm::dot(c, dir);
        atDepth[k] = depthSum[e] / count[e];
        lines.point[k] = mapUnproject(m, centre + at[k], atDepth[k]);
        lines.open[k] =
            mapUnproject(m, centre + at[k] + (e == 0 ? nrm : -nrm), atDepth[k]) - lines.point[k];
    }
    if (lines.count == 0) return lines;
    lines.tangent = mapUnproject(m, centre + at[0] + dir, atDepth[0]) - lines.point[0];
    if (lines.count == 2) lines.slit = glm::dot(at[0] - at[1], nrm) < 0.0f;
    return lines;
}

float occluderLinesVisibilityFused(const LineMap& m, glm::vec3 p, glm::vec3 n,
                                   const OccluderLines& lines, float own) {
    const DiskLight& l = m.light;
    DiskChord c[2];
    bool ok[2]{false, false};
    float share[2]{-1.0f, -1.0f};
    for (int k = 0; k < lines.count; ++k) {
        ok[k] = lineChord(l, p, lines.point[k], lines.tangent, lines.open[k], c[k]);
        if (ok[k]) share[k] = chordOpenShare(l, c[k].s);
    }
    if (lines.count == 1 || !ok[0] || !ok[1]) {
        const int k = ok[0] ? 0 : 1;
        if (!ok[k]) return -1.0f;
        return fusedShare(m, p, n, glm::dot(lines.point[k] - l.center, l.normal), share[k], c[k],
                          c[k], false, false, glm::length(lines.open[k]), own);
    }
    const float both = lines.slit ? std::max(share[0] + share[1] - 1.0f, 0.0f)
                                  : std::min(share[0] + share[1], 1.0f);
    return fusedShare(m, p, n, glm::dot(lines.point[0] - l.center, l.normal), both, c[0], c[1],
                      true, lines.slit, glm::length(lines.open[0]), own);
}

float occluderPointVisibilityFused(const LineMap& m, glm::vec3 p, glm::vec3 n, glm::vec3 o,
                                   bool inside, float own) {
    const DiskLight& l = m.light;
    const std::optional<float> intensity = occluderIntensity(l, p, o, inside);
    const float share = intensity ? *intensity : -1.0f;
    if (!(share > 0.0f)) return share;
    const float dp = glm::dot(p - l.center, l.normal);
    const float dO = glm::dot(o - l.center, l.normal);
    const glm::vec3 q = p + (o - p) * (dp / (dp - dO));
    glm::vec3 cq = q - l.center;
    cq -= glm::dot(cq, l.normal) * l.normal;
    const float d = glm::length(cq);
    if (!(d > 0.0f)) return share;
    DiskChord c;
    c.u = inside ? cq / d : -cq / d;
    c.s = inside ? -d : d;
    return fusedShare(
        m, p, n, dO, share, c, c, false, false,
        inside ? 0.0f : surface::mapTexelWorld(o, m.warp * m.lightViewProj, float(m.size)), own);
}

float occluderShareFused(const LineMap& m, glm::ivec2 own, glm::vec3 p, glm::vec3 n,
                         const OccluderLines& lines, glm::vec3 o, bool inside, bool borrowed) {
    const float ownDepth = inside ? lineMapDepth(m, own) : 0.0f;
    float l = lines.count > 0 ? occluderLinesVisibilityFused(m, p, n, lines, ownDepth)
              : borrowed      ? -1.0f
                              : occluderPointVisibilityFused(m, p, n, o, inside, ownDepth);
    if (borrowed && (inside ? l > 0.5f : l < 0.5f)) l = -1.0f;
    return l;
}

} // namespace fl
