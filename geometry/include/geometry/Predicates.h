#pragma once
// Exact 2D geometric predicates: the orientation and in-circle tests every Delaunay step
// (thesis ch. 6, C1-C4) and every mesh check rests on. Rounding in a naive determinant flips
// signs for nearly collinear or nearly cocircular points, which makes flip algorithms loop and
// checks lie; these never do.
//
// Guarantee: for every finite double input the sign of the result is the sign of the exact
// determinant of the input values (no input is rounded, whatever the magnitudes: 1e-300 next to
// 1e300, subnormals, signed zeros all included). The magnitude is only an estimate: it is the
// plain floating-point determinant when the filter below finds its sign certain (then the error
// is smaller than the value itself, usually far smaller), otherwise the exact determinant rounded
// to a double, where a nonzero determinant too small for a double comes back as the smallest
// subnormal of its sign and one too large as the largest finite double. Zero is exactly 0.
//
// Method (Shewchuk-style adaptive precision, our own code): a floating-point filter with a
// proven error bound (extended by an absolute term for underflow) decides almost every call;
// otherwise the inputs are scaled by a power of two (exact) into a range where floating-point
// expansions cannot overflow or underflow and the determinant is evaluated exactly; inputs that
// span too many binades for that (more than ~1000 for orient2d, ~480 for incircle) go to a
// slow big-integer evaluation. A NaN or infinite coordinate throws std::invalid_argument.
//
// Needs IEEE double arithmetic rounding to nearest-even and no fused multiply-adds in this
// library (the build passes -ffp-contract=off).

#include <glm/glm.hpp>

namespace fl::geom {

/// Twice the signed area of triangle abc: > 0 iff a, b, c turn counter-clockwise, 0 iff they
/// are collinear; the sign is exact.
double orient2d(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c);
/// The exact sign of orient2d: +1 counter-clockwise, 0 collinear, -1 clockwise.
int orient2dSign(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c);

/// > 0 iff d lies strictly inside the circle through a, b, c (which must turn counter-clockwise;
/// the sign flips for clockwise a, b, c), 0 iff on it, < 0 outside; the sign is exact. This is
/// the determinant of the rows (p.x - d.x, p.y - d.y, |p - d|^2) for p = a, b, c.
double incircle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d);
/// The exact sign of incircle: +1 inside, 0 on the circle, -1 outside (for CCW a, b, c).
int incircleSign(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d);

namespace detail {

/// Which exact method evaluates a call that the filter cannot decide (exposed for tests).
enum class ExactMethod { Expansion, BigInteger };

/// The method orient2d falls back to for these inputs.
ExactMethod orient2dExactMethod(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c);
/// The method incircle falls back to for these inputs.
ExactMethod incircleExactMethod(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d);
/// orient2d without the filter (scaled expansions, or big integers when out of range).
double orient2dExact(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c);
/// orient2d evaluated with big integers only.
double orient2dBigInteger(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c);
/// incircle without the filter (scaled expansions, or big integers when out of range).
double incircleExact(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d);
/// incircle evaluated with big integers only.
double incircleBigInteger(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d);

} // namespace detail
} // namespace fl::geom
