// The stability measures of the trapezoid fit: quantised parameters, texel
// snapping and hysteresis. Why: the paper's fit follows the camera continuously, so its texels
// slide over the scene and shadow edges shimmer; a map that changes in steps, or not at all
// while the old one still serves, keeps its texels fixed on the scene between the steps.

#include "TrapezoidDetail.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace fl::geom {
namespace detail {

Steps stepsOf(const TrapezoidParams& params) {
    Steps s;
    const double q =
        std::isfinite(params.quantize) && params.quantize > 0.0f ? double(params.quantize) : 0.0;
    s.angle = s.slope = s.weight = q;
    const double texel =
        std::isfinite(params.snapTexels) && params.snapTexels > 0.0f && params.mapSize > 0
            ? double(params.snapTexels) * 2.0 / double(params.mapSize)
            : 0.0;
    // Both: quantize's positional step in whole multiples of the snapped texels.
    s.pos = texel > 0.0 ? texel * std::max(1.0, std::round(q / texel)) : q;
    return s;
}

double roundTo(double x, double step) {
    return step > 0.0 ? std::round(x / step) * step : x;
}
double floorTo(double x, double step) {
    return step > 0.0 ? std::floor(x / step) * step : x;
}
double ceilTo(double x, double step) {
    return step > 0.0 ? std::ceil(x / step) * step : x;
}

std::vector<glm::dvec2> scaledAbout(const std::vector<glm::dvec2>& polygon, double factor) {
    if (polygon.empty()) return polygon;
    glm::dvec2 centre(0.0);
    for (const glm::dvec2& p : polygon) centre += p;
    centre /= static_cast<double>(polygon.size());
    std::vector<glm::dvec2> out;
    out.reserve(polygon.size());
    for (const glm::dvec2& p : polygon) out.push_back(centre + (p - centre) * factor);
    return out;
}

TrapezoidFit settle(TrapezoidFit fresh, const TrapezoidFit* previous,
                    const TrapezoidParams& params) {
    if (!previous || !(params.hysteresis > 0.0f) ||
        !keepsPreviousFit(*previous, fresh, params.hysteresis))
        return fresh;
    // The previous map stays; what describes this frame's frustum is this frame's.
    TrapezoidFit kept = *previous;
    kept.hull = std::move(fresh.hull);
    kept.nearCenter = fresh.nearCenter;
    kept.farCenter = fresh.farCenter;
    kept.focusPoint = fresh.focusPoint;
    kept.centerLineRatio = fresh.centerLineRatio;
    kept.wRel = fresh.wRel;
    kept.held = true;
    return kept;
}

} // namespace detail

namespace {

struct MappedSpan {
    bool inside = true;
    glm::dvec2 lo{std::numeric_limits<double>::max()};
    glm::dvec2 hi{std::numeric_limits<double>::lowest()};
};

// Where `nt` puts the hull: whether all of it lands in the map, and its bounding box there.
MappedSpan mappedSpan(const glm::mat4& nt, const std::vector<glm::vec2>& hull) {
    const glm::dmat4 m(nt);
    const double slack = 1e-6; // the fit's own rounding; a point outside by more is outside
    MappedSpan s;
    for (const glm::vec2& p : hull) {
        const glm::dvec4 c = m * glm::dvec4(glm::dvec2(p), 0.0, 1.0);
        if (!(c.w > 0.0)) return {false};
        const glm::dvec2 q = glm::dvec2(c) / c.w;
        s.inside = s.inside && std::abs(q.x) <= 1.0 + slack && std::abs(q.y) <= 1.0 + slack;
        s.lo = glm::min(s.lo, q);
        s.hi = glm::max(s.hi, q);
    }
    return s;
}

double mappedY(const glm::mat4& nt, glm::vec2 p) {
    const glm::dvec4 c = glm::dmat4(nt) * glm::dvec4(glm::dvec2(p), 0.0, 1.0);
    return c.w > 0.0 ? c.y / c.w : std::numeric_limits<double>::infinity();
}

} // namespace

bool keepsPreviousFit(const TrapezoidFit& previous, const TrapezoidFit& fresh, float hysteresis) {
    const double h = hysteresis;
    if (fresh.hull.size() < 3 || previous.hull.size() < 3) return false;
    if (std::abs(double(fresh.weight) - double(previous.weight)) > h) return false;
    const MappedSpan kept = mappedSpan(previous.nt, fresh.hull);
    if (!kept.inside) return false; // part of the frustum would fall off the map
    // Resolution: the hull may shrink in the kept map to (1 - h) of what a refit gives it.
    const MappedSpan refit = mappedSpan(fresh.nt, fresh.hull);
    const glm::dvec2 keptSpan = kept.hi - kept.lo, refitSpan = refit.hi - refit.lo;
    if (keptSpan.x < (1.0 - h) * refitSpan.x || keptSpan.y < (1.0 - h) * refitSpan.y) return false;
    if (fresh.weight > 0.0f && previous.weight > 0.0f) {
        // The focus line: where the focus point lands on the map's y axis.
        if (std::abs(mappedY(previous.nt, fresh.focusPoint) - mappedY(fresh.nt, fresh.focusPoint)) >
            2.0 * h)
            return false;
        const double turn = h * std::numbers::pi / 2.0;
        if (double(glm::dot(fresh.axis, previous.axis)) < std::cos(turn)) return false;
    }
    return true;
}

} // namespace fl::geom
