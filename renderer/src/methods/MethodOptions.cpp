#include <renderer/methods/MethodOptions.h>
#include <renderer/methods/ShadowMethod.h>

#include <base/Numbers.h>
#include <base/Text.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace fl {

namespace {

std::string range(const MethodOption& o) {
    return cat("[", o.min, ", ", o.max, "]");
}

} // namespace

std::string checkOptionValue(const MethodOption& o, std::string_view value) {
    double v = 0.0;
    switch (o.kind) {
    case OptionKind::Int: {
        if (!o.word.empty() && value == o.word) return {};
        if (std::string problem = numberProblem(value, o.min, o.max, true); !problem.empty())
            return o.word.empty() ? problem
                                  : cat("must be ", o.word, " or ", numberRule(o.min, o.max, true),
                                        ", got '", value, "'");
        parseNumber(value, v);
        if (o.multipleOf > 0 && static_cast<long long>(v) % o.multipleOf != 0)
            return cat("must be a multiple of ", o.multipleOf, " in ", range(o), ", got '", value,
                       "'");
        return {};
    }
    case OptionKind::Float:
        return numberProblem(value, o.min, o.max, false);
    case OptionKind::Flag:
        if (value != "true" && value != "false")
            return cat("must be true or false, got '", value, "'");
        return {};
    case OptionKind::Choice: {
        std::string list;
        for (const std::string& c : optionChoices(o)) {
            if (c == value) return {};
            list += (list.empty() ? "" : ",") + c;
        }
        return cat("must be one of ", list, ", got '", value, "'");
    }
    }
    return "unknown option kind";
}

std::vector<std::string> optionChoices(const MethodOption& o) {
    std::vector<std::string> out;
    std::string_view rest = o.choices;
    while (!rest.empty()) {
        const std::size_t bar = rest.find('|');
        out.emplace_back(rest.substr(0, bar));
        rest = bar == std::string_view::npos ? std::string_view{} : rest.substr(bar + 1);
    }
    return out;
}

void MethodOptions::set(std::string_view flag, float value) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(value));
    set(flag, std::string(buf));
}

std::string MethodOptions::text(const MethodOption& o) const {
    const auto it = values_.find(o.flag);
    const std::string value = it == values_.end() ? std::string(o.defaultValue) : it->second;
    const std::string problem = checkOptionValue(o, value);
    if (!problem.empty()) throw std::invalid_argument(cat(o.flag, ": ", problem));
    return value;
}

int MethodOptions::integer(const MethodOption& o) const {
    double v = 0.0;
    parseNumber(text(o), v); // o.word leaves it 0
    return static_cast<int>(v);
}

float MethodOptions::real(const MethodOption& o) const {
    double v = 0.0;
    parseNumber(text(o), v);
    return static_cast<float>(v);
}

bool MethodOptions::flag(const MethodOption& o) const {
    return text(o) == "true";
}

const MethodOption* MethodDescriptor::option(std::string_view key) const {
    for (const MethodOption* o : options)
        if (o->key == key) return o;
    return nullptr;
}

bool MethodDescriptor::takesFlag(std::string_view flag) const {
    for (const MethodOption* o : options)
        if (o->flag == flag) return true;
    return false;
}

} // namespace fl
