#pragma once
// Private to the Delaunay pipeline: inline front ends to the exact predicates (Predicates.h) for
// the CPU steps' hot loops. Each evaluates the plain floating-point determinant with Shewchuk's
// error bound (the same bound Predicates.cpp uses, doubled) and answers only when the sign is
// certain; otherwise it calls the library predicate, which decides exactly. So the signs are the
// library's, just cheaper to get.
//
// The library's filter now has the same fast path (Predicates.cpp, kFastFloor); these inline
// copies only save the call in the CPU steps' hot loops. The bound: answer only when the
// determinant is far above the underflow range, |det| > 2^-900 and the operands (lifts, minors)
// below 2^140, so the library's underflow term (< 2^-1050 * 2^141) is under half of |det|, and
// the other half covers the rounding bound.

#include <geometry/Predicates.h>

#include <glm/glm.hpp>

#include <cmath>

namespace fl::geom::detail {

inline constexpr double kFastEpsilon = 0x1p-53;
inline constexpr double kFastOrientBound = 2.0 * (3.0 + 16.0 * kFastEpsilon) * kFastEpsilon;
inline constexpr double kFastIncircleBound = 2.0 * (10.0 + 96.0 * kFastEpsilon) * kFastEpsilon;
inline constexpr double kFastFloor = 0x1p-900; // far above any underflow effect
inline constexpr double kFastCeiling = 0x1p140;

/// orient2dSign(a, b, c), usually without leaving this function.
[[nodiscard]] inline int fastOrientSign(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    const double left = (a.x - c.x) * (b.y - c.y);
    const double right = (a.y - c.y) * (b.x - c.x);
    const double det = left - right;
    const double magnitude = std::fabs(det);
    if (magnitude > kFastOrientBound * (std::fabs(left) + std::fabs(right)) &&
        magnitude > kFastFloor)
        return det > 0.0 ? 1 : -1;
    return orient2dSign(a, b, c);
}

/// incircleSign(a, b, c, d), usually without leaving this function.
[[nodiscard]] inline int fastIncircleSign(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d) {
    const double adx = a.x - d.x, ady = a.y - d.y;
    const double bdx = b.x - d.x, bdy = b.y - d.y;
    const double cdx = c.x - d.x, cdy = c.y - d.y;
    const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    const double cdxady = cdx * ady, adxcdy = adx * cdy;
    const double adxbdy = adx * bdy, bdxady = bdx * ady;
    const double aLift = adx * adx + ady * ady;
    const double bLift = bdx * bdx + bdy * bdy;
    const double cLift = cdx * cdx + cdy * cdy;
    const double det =
        aLift * (bdxcdy - cdxbdy) + bLift * (cdxady - adxcdy) + cLift * (adxbdy - bdxady);
    const double aMinor = std::fabs(bdxcdy) + std::fabs(cdxbdy);
    const double bMinor = std::fabs(cdxady) + std::fabs(adxcdy);
    const double cMinor = std::fabs(adxbdy) + std::fabs(bdxady);
    const double permanent = aMinor * aLift + bMinor * bLift + cMinor * cLift;
    const double operands = aLift + bLift + cLift + aMinor + bMinor + cMinor;
    const double magnitude = std::fabs(det);
    if (magnitude > kFastIncircleBound * permanent && magnitude > kFastFloor &&
        operands < kFastCeiling)
        return det > 0.0 ? 1 : -1;
    return incircleSign(a, b, c, d);
}

} // namespace fl::geom::detail
