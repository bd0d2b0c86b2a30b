#include <io/JsonText.h>

#include <base/Numbers.h>

#include <stdexcept>
#include <string_view>

namespace fl {

namespace {
// nlohmann's what() without its "[json.exception.KIND.N] " prefix.
std::string plain(const nlohmann::json::exception& e) {
    const std::string_view w = e.what();
    const std::size_t close = w.find("] ");
    return std::string(w.rfind("[json.exception.", 0) == 0 && close != std::string_view::npos
                           ? w.substr(close + 2)
                           : w);
}
} // namespace

nlohmann::json parseJsonText(const std::string& text) {
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw std::runtime_error("not valid JSON: " + plain(e));
    } catch (const nlohmann::json::out_of_range& e) {
        throw std::runtime_error("not valid JSON: " + plain(e) +
                                 " (numbers must fit a double: finite, below 1.8e308)");
    }
}

double jsonNumber(const nlohmann::json& j, double lo, double hi, bool integer) {
    if (!j.is_number())
        throw std::runtime_error(integer ? "expected an integer" : "expected a number");
    const double v = j.get<double>();
    if (std::string problem = numberProblem(v, lo, hi, integer); !problem.empty())
        throw std::runtime_error(problem);
    return v;
}

} // namespace fl
