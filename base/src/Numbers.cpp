#include <base/Numbers.h>

#include <base/Text.h>

#include <charconv>
#include <cmath>

namespace fl {

bool parseNumber(std::string_view text, double& out) {
    if (text.empty()) return false;
    const char* end = text.data() + text.size();
    const auto r = std::from_chars(text.data(), end, out);
    return r.ec == std::errc() && r.ptr == end;
}

namespace {

// 16384 rather than 16384 or 1.6384e+04; fractions as the stream writes them (0.95).
std::string show(double v) {
    if (std::isfinite(v) && v == std::floor(v) && std::abs(v) < 1e15)
        return std::to_string(static_cast<long long>(v));
    return cat(v);
}

bool fits(double v, double lo, double hi, bool integer) {
    return std::isfinite(v) && v >= lo && v <= hi && (!integer || v == std::floor(v));
}

} // namespace

std::string numberRule(double lo, double hi, bool integer) {
    const std::string what = integer ? "an integer" : "a finite number";
    const bool hasLo = std::isfinite(lo), hasHi = std::isfinite(hi);
    if (hasLo && hasHi) return cat(what, " in [", show(lo), ", ", show(hi), "]");
    if (hasLo) return cat(what, " >= ", show(lo));
    if (hasHi) return cat(what, " <= ", show(hi));
    return what;
}

std::string numberProblem(double value, double lo, double hi, bool integer) {
    if (fits(value, lo, hi, integer)) return {};
    return cat("must be ", numberRule(lo, hi, integer), ", got ", show(value));
}

std::string numberProblem(std::string_view text, double lo, double hi, bool integer) {
    double v = 0.0;
    if (parseNumber(text, v) && fits(v, lo, hi, integer)) return {};
    return cat("must be ", numberRule(lo, hi, integer), ", got '", text, "'");
}

} // namespace fl
