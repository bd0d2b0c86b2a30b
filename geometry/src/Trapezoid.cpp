#include <geometry/Trapezoid.h>

#include "TrapezoidDetail.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace fl::geom {
namespace {

using glm::dmat4;
using glm::dvec2;
using glm::dvec4;

double cross2(dvec2 o, dvec2 a, dvec2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

double smoothStep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

bool finite(const dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// glm is column-major; the maps are easier to read as rows acting on (x, y, z, w).
dmat4 fromRows(dvec4 x, dvec4 y, dvec4 z, dvec4 w) {
    return glm::transpose(dmat4(x, y, z, w));
}

// The focused uniform map: the hull's bounding box onto [-1,1]^2, w kept, z row zero (see the
// header for why depth does not go through N_T).
dmat4 uniformMap(dvec2 lo, dvec2 hi) {
    const double minExtent = 1e-6; // a flat hull must not produce an infinite scale
    const double dx = std::max(hi.x - lo.x, minExtent);
    const double dy = std::max(hi.y - lo.y, minExtent);
    return fromRows(dvec4(2.0 / dx, 0.0, 0.0, -(lo.x + hi.x) / dx),
                    dvec4(0.0, 2.0 / dy, 0.0, -(lo.y + hi.y) / dy), dvec4(0.0), dvec4(0, 0, 0, 1));
}

TrapezoidFit finish(TrapezoidFit fit, const dmat4& m, double weight) {
    fit.nt = glm::mat4(m);
    fit.weight = static_cast<float>(weight);
    fit.degenerate = weight < 1.0;
    return fit;
}

} // namespace

std::vector<dvec2> convexHull2d(std::vector<dvec2> points) {
    std::sort(points.begin(), points.end(),
              [](dvec2 a, dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3) return points;
    std::vector<dvec2> hull(2 * points.size());
    size_t k = 0;
    for (const dvec2& p : points) { // lower chain
        while (k >= 2 && cross2(hull[k - 2], hull[k - 1], p) <= 0.0) --k;
        hull[k++] = p;
    }
    for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) { // upper chain
        while (k >= lower && cross2(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1); // the last point repeats the first
    return hull;
}

std::vector<dvec2> clipToSquare(const std::vector<dvec2>& polygon) {
    // Each half-plane is n . p <= 1 for the four axis normals.
    const std::array<dvec2, 4> normals{dvec2(1, 0), dvec2(-1, 0), dvec2(0, 1), dvec2(0, -1)};
    std::vector<dvec2> poly = polygon;
    for (const dvec2& n : normals) {
        if (poly.empty()) break;
        std::vector<dvec2> out;
        for (size_t i = 0; i < poly.size(); ++i) {
            const dvec2 a = poly[i];
            const dvec2 b = poly[(i + 1) % poly.size()];
            const double da = 1.0 - glm::dot(n, a);
            const double db = 1.0 - glm::dot(n, b);
            if (da >= 0.0) out.push_back(a);
            if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
        }
        poly = std::move(out);
    }
    return poly;
}

std::array<dvec4, 8> projectFrustumCorners(const glm::dmat4& lightViewProj,
                                           const glm::dmat4& eyeViewProjInverse) {
    const dmat4 light(lightViewProj);
    const dmat4 inv(eyeViewProjInverse);
    std::array<dvec4, 8> out{};
    for (int i = 0; i < 8; ++i) {
        const dvec4 ndc((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0, 1.0);
        const dvec4 world = inv * ndc;
        // Dehomogenise in world space so that averages of these corners are world averages.
        out[static_cast<size_t>(i)] = light * (world / world.w);
    }
    return out;
}

namespace {

// The points of the eye frustum in front of the light, projected: corners with w above wEps
// plus the frustum edges cut at that epsilon (they project far out and are then clipped by the
// square, which is what keeps the hull continuous as w crosses zero).
std::vector<dvec2> frontPoints(const std::array<dvec4, 8>& c, double wEps) {
    std::vector<dvec2> pts;
    for (int i = 0; i < 8; ++i) {
        const dvec4& a = c[static_cast<size_t>(i)];
        if (a.w >= wEps) pts.push_back(dvec2(a) / a.w);
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (i & bit) continue; // each edge once, from its lower-index end
            const dvec4& b = c[static_cast<size_t>(i | bit)];
            if ((a.w >= wEps) == (b.w >= wEps)) continue;
            const dvec4 cut = a + (b - a) * ((wEps - a.w) / (b.w - a.w));
            pts.push_back(dvec2(cut) / wEps);
        }
    }
    return pts;
}

// The trapezoid around the centre line through nearC along u, with the focus point `focus`,
// holding `hull` with `margin` (a fraction of its extents) to spare; fills fit's trapezoid
// fields. With steps, the direction, lines and slopes are rounded (extents outwards). nullopt
// when the hull has no depth along u.
std::optional<dmat4> trapezoidMap(TrapezoidFit& fit, const std::vector<dvec2>& hull, dvec2 nearC,
                                  dvec2 u, dvec2 focus, double xiParam, const detail::Steps& st,
                                  double margin) {
    if (st.angle > 0.0) {
        const double a = detail::roundTo(std::atan2(u.y, u.x), st.angle);
        u = dvec2(std::cos(a), std::sin(a));
    }
    // Frame along the centre line: u towards the far plane, v its CCW perpendicular. A quantised
    // fit measures from a fixed origin (the light NDC origin, the centre line's offset rounded)
    // so that its lines land on a fixed grid.
    const dvec2 v(-u.y, u.x);
    const dvec2 origin = st.pos > 0.0 ? detail::roundTo(glm::dot(nearC, v), st.pos) * v : nearC;
    double sMin = std::numeric_limits<double>::max();
    double sMax = std::numeric_limits<double>::lowest();
    for (const dvec2& p : hull) {
        sMin = std::min(sMin, glm::dot(p - origin, u));
        sMax = std::max(sMax, glm::dot(p - origin, u));
    }
    // The hysteresis margin: mostly at the far end and the sides, where rows and columns are
    // cheap; the near end is magnified, so a margin there would cost most of the map's rows.
    const double reach = sMax - sMin;
    sMin = detail::floorTo(sMin - 0.25 * margin * reach, st.pos);
    sMax = detail::ceilTo(sMax + margin * reach, st.pos);
    const double lambda = sMax - sMin; // top line at s = sMin, base line at s = sMax
    if (!(lambda > 1e-9)) return std::nullopt;
    const double delta =
        std::clamp(detail::roundTo(glm::dot(focus - origin, u), st.pos) - sMin, 0.0, lambda);

    // The 80% rule: with y(d) = B / d - A over the distance d from q, top (d = eta) -> +1,
    // base (d = eta + lambda) -> -1 and focus (d = eta + delta') -> xi give
    // eta = lambda delta' (1 + xi) / (lambda (1 - xi) - 2 delta'). The denominator reaches zero
    // when the focus is too far for the rule (q at infinity, a rectangle); cap eta there, and keep
    // it off zero, where the side lines would become vertical.
    const double xi = std::clamp(xiParam, -0.999, 0.999);
    const double etaMax = 50.0 * lambda;
    const double etaMin = 0.01 * lambda;
    const double num = lambda * delta * (1.0 + xi);
    const double den = lambda * (1.0 - xi) - 2.0 * delta;
    const double eta = std::clamp(den * etaMax > num ? num / den : etaMax, etaMin, etaMax);
    const dvec2 q = origin + (sMin - eta) * u;

    // Side lines through q tangent to the hull: the extreme slopes b / a over the hull.
    double kMin = std::numeric_limits<double>::max();
    double kMax = std::numeric_limits<double>::lowest();
    for (const dvec2& p : hull) {
        const double k = glm::dot(p - q, v) / glm::dot(p - q, u); // a >= eta > 0
        kMin = std::min(kMin, k);
        kMax = std::max(kMax, k);
    }
    const double spread = kMax - kMin;
    kMin = detail::floorTo(kMin - 0.5 * margin * spread, st.slope);
    kMax = detail::ceilTo(kMax + 0.5 * margin * spread, st.slope);
    const double dk = std::max(kMax - kMin, 1e-9);

    // In light clip coordinates a = dot(xy - q w, u) and b = dot(xy - q w, v); then
    // x' = (2b - (kMin + kMax) a) / dk / a and y' = (B w - A a) / a. Dividing every row by
    // eta + lambda keeps w' in (0, 1] on the hull, comparable with the uniform map's w.
    const double A = 1.0 + 2.0 * eta / lambda;
    const double B = 2.0 * eta * (eta + lambda) / lambda;
    const double s = 1.0 / (eta + lambda);
    const dvec4 rowA(u.x, u.y, 0.0, -glm::dot(u, q));
    const dvec4 rowB(v.x, v.y, 0.0, -glm::dot(v, q));
    const dvec4 rowW(0.0, 0.0, 0.0, 1.0);
    const dmat4 trapezoid = fromRows((2.0 * rowB - (kMin + kMax) * rowA) * (s / dk),
                                     (B * rowW - A * rowA) * s, dvec4(0.0), rowA * s);

    const std::array<dvec2, 4> ab{dvec2(eta, kMin * eta), dvec2(eta, kMax * eta),
                                  dvec2(eta + lambda, kMax * (eta + lambda)),
                                  dvec2(eta + lambda, kMin * (eta + lambda))};
    for (size_t i = 0; i < 4; ++i) fit.corners[i] = glm::vec2(q + ab[i].x * u + ab[i].y * v);
    fit.q = q;
    fit.lambda = static_cast<float>(lambda);
    fit.deltaPrime = static_cast<float>(delta);
    fit.eta = static_cast<float>(eta);
    fit.axis = glm::vec2(u);
    return trapezoid;
}

// The paper's fit with the stateless stability steps; fitTrapezoid adds the hysteresis.
TrapezoidFit freshFit(const glm::dmat4& lightViewProj, const glm::dmat4& eyeViewProjInverse,
                      const TrapezoidParams& params) {
    TrapezoidFit fit;
    // Whole-map fallback for inputs with nothing to focus on: identity in x, y, w.
    const dmat4 wholeMap = uniformMap(dvec2(-1.0), dvec2(1.0));
    const std::array<dvec4, 8> c = projectFrustumCorners(lightViewProj, eyeViewProjInverse);

    double maxAbsW = 0.0;
    double minW = std::numeric_limits<double>::max();
    for (const dvec4& p : c) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.w))
            return finish(fit, wholeMap, 0.0);
        maxAbsW = std::max(maxAbsW, std::abs(p.w));
        minW = std::min(minW, p.w);
    }
    if (!(maxAbsW > 0.0)) return finish(fit, wholeMap, 0.0);
    const double wRel = minW / maxAbsW;
    fit.wRel = static_cast<float>(wRel);

    const double wEps = 1e-6 * maxAbsW;
    const std::vector<dvec2> hull = clipToSquare(convexHull2d(frontPoints(c, wEps)));
    if (hull.size() < 3) return finish(fit, wholeMap, 0.0); // the light sees none of the frustum
    dvec2 lo(std::numeric_limits<double>::max());
    dvec2 hi(std::numeric_limits<double>::lowest());
    for (const dvec2& p : hull) {
        fit.hull.emplace_back(p);
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // With hysteresis the maps leave a margin, so that the next frames' hulls fit in them: the
    // uniform map around the hull scaled by 1 + hysteresis, the trapezoid see trapezoidMap.
    const detail::Steps st = detail::stepsOf(params);
    const double margin = std::max(double(params.hysteresis), 0.0);
    dvec2 mapLo = lo, mapHi = hi;
    for (const dvec2& p : clipToSquare(detail::scaledAbout(hull, 1.0 + margin))) {
        mapLo = glm::min(mapLo, p);
        mapHi = glm::max(mapHi, p);
    }
    for (int k = 0; k < 2; ++k) {
        mapLo[k] = detail::floorTo(mapLo[k], st.pos);
        mapHi[k] = detail::ceilTo(mapHi[k], st.pos);
    }
    const dmat4 uniform = uniformMap(mapLo, mapHi);

    // Centre line through the projected near- and far-plane centres; the focus point sits on
    // the view axis at focusFraction of the depth (linear in world space along that axis).
    const dvec4 nearClip = 0.25 * (c[0] + c[1] + c[2] + c[3]);
    const dvec4 farClip = 0.25 * (c[4] + c[5] + c[6] + c[7]);
    const dvec4 focusClip =
        glm::mix(nearClip, farClip, std::clamp(double(params.focusFraction), 0.0, 1.0));
    if (nearClip.w < wEps || farClip.w < wEps || focusClip.w < wEps)
        return finish(fit, uniform, 0.0);
    const dvec2 nearC = dvec2(nearClip) / nearClip.w;
    const dvec2 farC = dvec2(farClip) / farClip.w;
    fit.nearCenter = nearC;
    fit.farCenter = farC;
    const dvec2 focus = dvec2(focusClip) / focusClip.w;
    fit.focusPoint = focus;

    const double len = glm::length(farC - nearC);
    const double r = len / std::max(std::max(hi.x - lo.x, hi.y - lo.y), 1e-12);
    fit.centerLineRatio = static_cast<float>(r);
    double weight = smoothStep(params.rLow, params.rHigh, r) *
                    smoothStep(0.0, std::max(double(params.wBand), 1e-9), wRel);
    weight = std::clamp(detail::roundTo(weight, st.weight), 0.0, 1.0);
    if (!(weight > 0.0)) return finish(fit, uniform, 0.0);

    const std::optional<dmat4> trapezoid =
        trapezoidMap(fit, hull, nearC, (farC - nearC) / len, focus, params.xi, st, margin);
    if (!trapezoid) return finish(fit, uniform, 0.0);
    const dmat4 blended = (1.0 - weight) * uniform + weight * *trapezoid;
    if (!finite(blended)) return finish(fit, uniform, 0.0);
    return finish(fit, blended, weight);
}

} // namespace

TrapezoidFit fitTrapezoid(const glm::dmat4& lightViewProj, const glm::dmat4& eyeViewProjInverse,
                          const TrapezoidParams& params, const TrapezoidFit* previous) {
    return detail::settle(freshFit(lightViewProj, eyeViewProjInverse, params), previous, params);
}

} // namespace fl::geom
