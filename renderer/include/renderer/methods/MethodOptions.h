#pragma once
// A shadow method's options: each is declared once (CLI flag, capture-script key, kind, range,
// default, help) and listed by the rows of the method table that take it; values are kept as
// text by flag, so every command and script path validates them the same way.

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace fl {

enum class OptionKind { Int, Float, Choice, Flag };

struct MethodOption {
    std::string_view flag; // CLI flag, unique in the table: "--jfa-passes"
    std::string_view key;  // capture-script key within a method entry: "passes"
    OptionKind kind = OptionKind::Int;
    std::string_view defaultValue; // as text: "6", "16/24", "false"
    std::string_view help;
    double min = 0.0, max = 0.0;   // Int / Float: the closed range
    std::string_view choices = {}; // Choice: the values, '|'-separated
    std::string_view word = {};    // Int: a word accepted besides the range ("auto"); integer()
                                   // reads it as 0
    int multipleOf = 0;            // Int: the value must be a multiple of this (0: any)
};

/// A Choice option's values, in the order `choices` lists them.
std::vector<std::string> optionChoices(const MethodOption& o);

/// "" when `value` is valid for `o`, else the problem in words ("must be an integer in
/// [1, 13], got 'abc'"), for messages that add the flag or the script field.
std::string checkOptionValue(const MethodOption& o, std::string_view value);

/// Option values as text, by flag. A flag not set takes its option's default.
class MethodOptions {
  public:
    void set(std::string_view flag, std::string value) { values_[std::string(flag)] = value; }
    void set(std::string_view flag, const char* value) { set(flag, std::string(value)); }
    void set(std::string_view flag, int value) { set(flag, std::to_string(value)); }
    void set(std::string_view flag, float value);
    void set(std::string_view flag, bool value) {
        set(flag, std::string(value ? "true" : "false"));
    }
    [[nodiscard]] bool has(std::string_view flag) const { return values_.count(flag) != 0; }
    /// The value for `o` (its default when unset); throws std::invalid_argument naming the flag
    /// when the value is invalid.
    [[nodiscard]] std::string text(const MethodOption& o) const;
    [[nodiscard]] int integer(const MethodOption& o) const;
    [[nodiscard]] float real(const MethodOption& o) const;
    [[nodiscard]] bool flag(const MethodOption& o) const;
    [[nodiscard]] const std::map<std::string, std::string, std::less<>>& values() const {
        return values_;
    }

  private:
    std::map<std::string, std::string, std::less<>> values_;
};

} // namespace fl
