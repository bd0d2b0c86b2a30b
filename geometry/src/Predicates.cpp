#include <geometry/Predicates.h>

#include "BigInteger.h"
#include "Expansion.h"
#include <geometry/detail/DelaunayPredicates.h>

#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>

namespace fl::geom {
namespace {

using detail::BigInteger;
using detail::Expansion;
using glm::dvec2;

// The filter (its bounds and fast path) is DelaunayPredicates.h's, shared with the inline front
// ends. Underflow: a product that lands below 2^-1022 is off by up to 2^-1075 absolutely rather
// than relatively, and a later multiplication can magnify that error by the other factor (in
// incircle, a lift or a 2x2 minor). This term covers those errors with room to spare (each
// magnifying factor is added in; the constant is over 2^20 times the worst case). Overflow
// needs no term: it makes the permanent or the determinant infinite or NaN, and the strict
// comparisons below then reject the filter's answer. Shewchuk's shortcut of returning at once
// when two products differ in sign is left out because an underflowed product can read as 0.
constexpr double kUnderflowSlack = 0x1p-1050;
using detail::kIncircleBound;
using detail::kOrientBound;

// Exact-stage ranges: after scaling by 2^s every nonzero coordinate has its lowest set bit at or
// above 2^kLow and its magnitude below 2^kHigh. Then every product the expansions form lies in
// [2^-1000, 2^1000] (orient2d: degree 2; incircle: degree 4 in coordinate differences, each
// below 2^(kHigh+1)), so Two-Product and Two-Sum stay exact and nothing overflows.
constexpr int kOrientLow = -500;
constexpr int kOrientHigh = 500;
constexpr int kIncircleLow = -250;
constexpr int kIncircleHigh = 240;

// The binades the nonzero inputs occupy: `low` is the exponent of the lowest set bit of any of
// them, `high` the smallest e with every |x| < 2^e. Scaling by a power of two keeps the
// predicate's sign (orient2d is homogeneous of degree 2, incircle of degree 4).
struct BinadeRange {
    int low = INT_MAX;
    int high = INT_MIN;

    [[nodiscard]] bool allZero() const { return low == INT_MAX; }

    void include(double x) {
        if (!std::isfinite(x))
            throw std::invalid_argument("exact predicate: coordinates must be finite");
        if (x == 0.0) return;
        int exponent = 0;
        const double fraction = std::frexp(std::fabs(x), &exponent);
        const auto mantissa = static_cast<std::uint64_t>(std::ldexp(fraction, 53));
        low = std::min(low, exponent - 53 + std::countr_zero(mantissa));
        high = std::max(high, exponent);
    }
};

BinadeRange rangeOf(std::initializer_list<dvec2> points) {
    BinadeRange r;
    for (const dvec2 p : points) {
        r.include(p.x);
        r.include(p.y);
    }
    return r;
}

// The power-of-two exponent that moves `r` into [lowLimit, highLimit], if one exists.
std::optional<int> scaleInto(const BinadeRange& r, int lowLimit, int highLimit) {
    if (r.allZero()) return 0;
    if (r.high - r.low > highLimit - lowLimit) return std::nullopt;
    if (r.low < lowLimit) return lowLimit - r.low;
    if (r.high > highLimit) return highLimit - r.high;
    return 0;
}

// v * 2^exponent without letting a nonzero value become 0 or infinite.
double rescale(double v, int exponent) {
    if (v == 0.0) return 0.0;
    const double r = std::ldexp(v, exponent);
    if (r == 0.0) return std::copysign(std::numeric_limits<double>::denorm_min(), v);
    if (std::isinf(r)) return std::copysign(std::numeric_limits<double>::max(), v);
    return r;
}

dvec2 scaled(dvec2 p, int s) {
    // Exact: the range check guarantees the result is a normal double with all bits kept.
    return {std::ldexp(p.x, s), std::ldexp(p.y, s)};
}

// orient2d = (ax by - ay bx) + (bx cy - by cx) + (cx ay - cy ax): six exact products summed.
double orient2dExpansion(dvec2 a, dvec2 b, dvec2 c) {
    using detail::diff;
    using detail::product;
    using detail::sum;
    const auto ab = diff(product(a.x, b.y), product(a.y, b.x));
    const auto bc = diff(product(b.x, c.y), product(b.y, c.x));
    const auto ca = diff(product(c.x, a.y), product(c.y, a.x));
    return sum(sum(ab, bc), ca).estimate();
}

// The incircle determinant with exact coordinate differences, as in the filter.
double incircleExpansion(dvec2 a, dvec2 b, dvec2 c, dvec2 d) {
    using detail::diff;
    using detail::difference;
    using detail::product;
    using detail::sum;
    const auto adx = difference(a.x, d.x), ady = difference(a.y, d.y);
    const auto bdx = difference(b.x, d.x), bdy = difference(b.y, d.y);
    const auto cdx = difference(c.x, d.x), cdy = difference(c.y, d.y);
    const auto aLift = sum(product(adx, adx), product(ady, ady));
    const auto bLift = sum(product(bdx, bdx), product(bdy, bdy));
    const auto cLift = sum(product(cdx, cdx), product(cdy, cdy));
    const auto aMinor = diff(product(bdx, cdy), product(cdx, bdy));
    const auto bMinor = diff(product(cdx, ady), product(adx, cdy));
    const auto cMinor = diff(product(adx, bdy), product(bdx, ady));
    const auto aTerm = product(aLift, aMinor);
    const auto bTerm = product(bLift, bMinor);
    const auto cTerm = product(cLift, cMinor);
    return sum(sum(aTerm, bTerm), cTerm).estimate();
}

struct BigPoint {
    BigInteger x, y;
};

BigPoint toBig(dvec2 p, int shift) {
    return {BigInteger::fromScaledDouble(p.x, shift), BigInteger::fromScaledDouble(p.y, shift)};
}

} // namespace

double orient2d(dvec2 a, dvec2 b, dvec2 c) {
    const detail::FilteredDeterminant d = detail::orientDeterminant(a, b, c);
    // Common case first, with no subnormal arithmetic.
    if (detail::fastOrientCertain(d)) return d.det;
    const double bound = kOrientBound * d.permanent + kUnderflowSlack;
    if (d.det > bound || -d.det > bound) return d.det;
    return detail::orient2dExact(a, b, c);
}

int orient2dSign(dvec2 a, dvec2 b, dvec2 c) {
    const double v = orient2d(a, b, c);
    return (v > 0.0) - (v < 0.0);
}

double incircle(dvec2 a, dvec2 b, dvec2 c, dvec2 d) {
    const detail::FilteredDeterminant f = detail::incircleDeterminant(a, b, c, d);
    if (detail::fastIncircleCertain(f)) return f.det;
    const double bound = kIncircleBound * f.permanent + kUnderflowSlack * (f.operands + 1.0);
    if (f.det > bound || -f.det > bound) return f.det;
    return detail::incircleExact(a, b, c, d);
}

int incircleSign(dvec2 a, dvec2 b, dvec2 c, dvec2 d) {
    const double v = incircle(a, b, c, d);
    return (v > 0.0) - (v < 0.0);
}

namespace detail {

ExactMethod orient2dExactMethod(dvec2 a, dvec2 b, dvec2 c) {
    return scaleInto(rangeOf({a, b, c}), kOrientLow, kOrientHigh) ? ExactMethod::Expansion
                                                                  : ExactMethod::BigInteger;
}

ExactMethod incircleExactMethod(dvec2 a, dvec2 b, dvec2 c, dvec2 d) {
    return scaleInto(rangeOf({a, b, c, d}), kIncircleLow, kIncircleHigh) ? ExactMethod::Expansion
                                                                         : ExactMethod::BigInteger;
}

double orient2dExact(dvec2 a, dvec2 b, dvec2 c) {
    const std::optional<int> s = scaleInto(rangeOf({a, b, c}), kOrientLow, kOrientHigh);
    if (!s) return orient2dBigInteger(a, b, c);
    const double v = orient2dExpansion(scaled(a, *s), scaled(b, *s), scaled(c, *s));
    return rescale(v, -2 * *s);
}

double orient2dBigInteger(dvec2 a, dvec2 b, dvec2 c) {
    const BinadeRange r = rangeOf({a, b, c});
    if (r.allZero()) return 0.0;
    // Every coordinate becomes the integer coordinate * 2^-low; the determinant scales by
    // 2^(-2 low).
    const BigPoint A = toBig(a, r.low), B = toBig(b, r.low), C = toBig(c, r.low);
    const BigInteger det =
        (A.x * B.y - A.y * B.x) + (B.x * C.y - B.y * C.x) + (C.x * A.y - C.y * A.x);
    return det.toDouble(2 * r.low);
}

double incircleExact(dvec2 a, dvec2 b, dvec2 c, dvec2 d) {
    const std::optional<int> s = scaleInto(rangeOf({a, b, c, d}), kIncircleLow, kIncircleHigh);
    if (!s) return incircleBigInteger(a, b, c, d);
    const double v = incircleExpansion(scaled(a, *s), scaled(b, *s), scaled(c, *s), scaled(d, *s));
    return rescale(v, -4 * *s);
}

double incircleBigInteger(dvec2 a, dvec2 b, dvec2 c, dvec2 d) {
    const BinadeRange r = rangeOf({a, b, c, d});
    if (r.allZero()) return 0.0;
    const BigPoint A = toBig(a, r.low), B = toBig(b, r.low), C = toBig(c, r.low),
                   D = toBig(d, r.low);
    const BigInteger adx = A.x - D.x, ady = A.y - D.y;
    const BigInteger bdx = B.x - D.x, bdy = B.y - D.y;
    const BigInteger cdx = C.x - D.x, cdy = C.y - D.y;
    const BigInteger aLift = adx * adx + ady * ady;
    const BigInteger bLift = bdx * bdx + bdy * bdy;
    const BigInteger cLift = cdx * cdx + cdy * cdy;
    const BigInteger det = aLift * (bdx * cdy - cdx * bdy) + bLift * (cdx * ady - adx * cdy) +
                           cLift * (adx * bdy - bdx * ady);
    return det.toDouble(4 * r.low);
}

} // namespace detail
} // namespace fl::geom
