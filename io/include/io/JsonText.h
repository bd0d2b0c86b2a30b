#pragma once
// JSON documents users write (capture scripts, camera paths): one parse with one kind of
// message, and one check for their numbers (fl::numberProblem, the rule of the command line).
// nlohmann's own messages carry "[json.exception.parse_error.101]" and, for a number beyond a
// double such as 1e400, an out_of_range exception that no caller caught.

#include <nlohmann/json.hpp>

#include <string>

namespace fl {

/// Parses `text`; throws std::runtime_error("not valid JSON: line 3, column 7: ...") for bad
/// syntax and for numbers that do not fit a double.
nlohmann::json parseJsonText(const std::string& text);

/// `j` as a number in [lo, hi] (an integer when `integer`); throws std::runtime_error with
/// "expected a number" or numberProblem's words. The caller adds the field's name.
double jsonNumber(const nlohmann::json& j, double lo, double hi, bool integer = false);

} // namespace fl
