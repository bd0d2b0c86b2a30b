#pragma once
// The floating-point filter of the exact predicates, written once: Predicates.cpp's orient2d and
// incircle start with it, and the Delaunay pipeline's hot loops call the inline front ends below
// (fastOrientSign, fastIncircleSign), which answer when the filter is certain and otherwise call
// the library predicate, which decides exactly. So the signs are always the library's.
//
// The filter (Shewchuk 1997, section 4.3): with round-to-nearest and no underflow or overflow,
// |computed det - exact det| is below bound * permanent, where the permanent is the same
// expression with every difference of products replaced by a sum of absolute values. The fast
// answer doubles that bound and takes it only when the determinant is far above the underflow
// range: |det| > 2^-900 and (incircle) the operands (lifts, minors) below 2^140, so the library's
// underflow term (< 2^-1050 * 2^141) is under half of |det| and the other half covers the
// rounding bound. Arithmetic on subnormals costs ~30 ns per call on x86 against ~5 ns without,
// so only determinants of tiny magnitude (coordinates near 1e-150 or below) go further.

#include <geometry/Predicates.h>

#include <glm/glm.hpp>

#include <cmath>

namespace fl::geom::detail {

inline constexpr double kFilterEpsilon = 0x1p-53; // half an ulp of 1
inline constexpr double kOrientBound = (3.0 + 16.0 * kFilterEpsilon) * kFilterEpsilon;
inline constexpr double kIncircleBound = (10.0 + 96.0 * kFilterEpsilon) * kFilterEpsilon;
inline constexpr double kFastFloor = 0x1p-900; // far above any underflow effect
inline constexpr double kFastCeiling = 0x1p140;

/// A determinant evaluated in plain floating point, with what its error bound is made of.
struct FilteredDeterminant {
    double det = 0.0;       // the computed determinant
    double permanent = 0.0; // its error scale (Shewchuk's permanent)
    double operands = 0.0;  // sum of the factors an underflowed product can be magnified by
};

/// The orient2d determinant (a - c) x (b - c) in floating point.
[[nodiscard]] inline FilteredDeterminant orientDeterminant(glm::dvec2 a, glm::dvec2 b,
                                                           glm::dvec2 c) {
    const double left = (a.x - c.x) * (b.y - c.y);
    const double right = (a.y - c.y) * (b.x - c.x);
    return {left - right, std::fabs(left) + std::fabs(right), 0.0};
}

/// The incircle determinant (lifted differences to d) in floating point.
[[nodiscard]] inline FilteredDeterminant incircleDeterminant(glm::dvec2 a, glm::dvec2 b,
                                                             glm::dvec2 c, glm::dvec2 d) {
    const double adx = a.x - d.x, ady = a.y - d.y;
    const double bdx = b.x - d.x, bdy = b.y - d.y;
    const double cdx = c.x - d.x, cdy = c.y - d.y;
    const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    const double cdxady = cdx * ady, adxcdy = adx * cdy;
    const double adxbdy = adx * bdy, bdxady = bdx * ady;
    const double aLift = adx * adx + ady * ady;
    const double bLift = bdx * bdx + bdy * bdy;
    const double cLift = cdx * cdx + cdy * cdy;
    const double aMinor = std::fabs(bdxcdy) + std::fabs(cdxbdy);
    const double bMinor = std::fabs(cdxady) + std::fabs(adxcdy);
    const double cMinor = std::fabs(adxbdy) + std::fabs(bdxady);
    return {aLift * (bdxcdy - cdxbdy) + bLift * (cdxady - adxcdy) + cLift * (adxbdy - bdxady),
            aMinor * aLift + bMinor * bLift + cMinor * cLift,
            aLift + bLift + cLift + aMinor + bMinor + cMinor};
}

/// Whether the fast path may answer with the sign of an orient2d determinant.
[[nodiscard]] inline bool fastOrientCertain(const FilteredDeterminant& d) {
    const double magnitude = std::fabs(d.det);
    return magnitude > 2.0 * kOrientBound * d.permanent && magnitude > kFastFloor;
}

/// Whether the fast path may answer with the sign of an incircle determinant.
[[nodiscard]] inline bool fastIncircleCertain(const FilteredDeterminant& d) {
    const double magnitude = std::fabs(d.det);
    return magnitude > 2.0 * kIncircleBound * d.permanent && magnitude > kFastFloor &&
           d.operands < kFastCeiling;
}

/// orient2dSign(a, b, c), usually without leaving this function.
[[nodiscard]] inline int fastOrientSign(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    const FilteredDeterminant d = orientDeterminant(a, b, c);
    if (fastOrientCertain(d)) return d.det > 0.0 ? 1 : -1;
    return orient2dSign(a, b, c);
}

/// incircleSign(a, b, c, d), usually without leaving this function.
[[nodiscard]] inline int fastIncircleSign(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d) {
    const FilteredDeterminant f = incircleDeterminant(a, b, c, d);
    if (fastIncircleCertain(f)) return f.det > 0.0 ? 1 : -1;
    return incircleSign(a, b, c, d);
}

} // namespace fl::geom::detail
