#pragma once
// One check for every number a user gives us: command-line options (app/Common.h wraps it
// as CLI11 validators), method options (the method table) and the numbers of scripts. A number
// must be finite and within its range; an integer must also be whole. The message says which
// rule failed and quotes what was given.

#include <limits>
#include <string>
#include <string_view>

namespace fl {

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

/// The largest |coordinate| of a position in scene units that any input may give (vertices,
/// camera keys, light positions and sizes): the renderer computes in float, and beyond this
/// interpolation, frusta and the ray tracer's BVH overflow or lose all precision (a camera key
/// at 1.7e38, within a float, gave infinite cameras).
inline constexpr double kMaxWorldCoordinate = 1e15;

/// Reads all of `text` as a decimal number (no spaces, no trailing characters); false if not.
bool parseNumber(std::string_view text, double& out);

/// The rule in words: "an integer in [1, 16384]", "a finite number >= 0", "a finite number".
std::string numberRule(double lo, double hi, bool integer);

/// What is wrong with `value` as a number in [lo, hi] (an integer when `integer`; lo or hi may
/// be +-kUnbounded), in words, e.g. "must be an integer in [1, 16384], got 0"; empty if nothing.
std::string numberProblem(double value, double lo, double hi, bool integer);

/// The same for text, which must parse as a number: "must be a finite number >= 0, got 'abc'".
std::string numberProblem(std::string_view text, double lo, double hi, bool integer);

} // namespace fl
