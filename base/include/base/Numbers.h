#pragma once
// One check for every number a user gives us: command-line options (app/src/Common.h wraps it
// as CLI11 validators), method options (the method table) and the numbers of scripts. A number
// must be finite and within its range; an integer must also be whole. The message says which
// rule failed and quotes what was given.

#include <limits>
#include <string>
#include <string_view>

namespace fl {

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

/// Reads all of `text` as a decimal number (no spaces, no trailing characters); false if not.
bool parseNumber(std::string_view text, double& out);

/// What is wrong with `value` as a number in [lo, hi] (an integer when `integer`; lo or hi may
/// be +-kUnbounded), in words, e.g. "must be an integer in [1, 16384], got 0"; empty if nothing.
std::string numberProblem(double value, double lo, double hi, bool integer);

/// The same for text, which must parse as a number: "must be a finite number >= 0, got 'abc'".
std::string numberProblem(std::string_view text, double lo, double hi, bool integer);

} // namespace fl
