#pragma once
// A shadow method's options: each is declared once (CLI flag, capture-script key, kind, range,
// default, help) and bound, by a field descriptor (field()), to a member of the options struct of
// every method that takes it (MethodOptionSet, one per row of the method table). Settings keep
// the values as text by flag, so every command and script path validates them the same way; the
// renderer parses them into the method's struct once per settings, and the method reads fields.

#include <any>
#include <cstddef>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
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
    /// The values the baselines bench renders its method at, one entry each ('|'-separated;
    /// "LABEL=VALUE" names an entry other than by its value; "*": every choice); "" none.
    std::string_view sweep = {};
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

/// Identifies an options struct S by address (compared at compile time by optionSet<S>()).
template <class S>
inline constexpr char kOptionStructTag = 0;

/// One member of a method's options struct bound to its option's metadata: `read` parses the
/// option's value (validated as MethodOptions::text does) into that member of `out`, an S.
struct OptionField {
    const MethodOption* option = nullptr;
    const void* structTag = nullptr; // &kOptionStructTag<S>
    void (*read)(const MethodOptions& values, const MethodOption& o, void* out) = nullptr;
};

namespace detail {
template <class M>
struct MemberPointer;
template <class C, class T>
struct MemberPointer<T C::*> {
    using Class = C;
};
template <auto First, auto...>
struct FirstOf {
    using Class = typename MemberPointer<decltype(First)>::Class;
};
/// obj.*P0.*P1...: a member of a member (FloodOptions inside a method's struct).
template <auto P, auto... Rest>
constexpr auto& memberAt(auto& obj) {
    if constexpr (sizeof...(Rest) == 0)
        return obj.*P;
    else
        return memberAt<Rest...>(obj.*P);
}
template <class T>
T readOption(const MethodOptions& values, const MethodOption& o) {
    if constexpr (std::is_same_v<T, int>)
        return values.integer(o);
    else if constexpr (std::is_same_v<T, float>)
        return values.real(o);
    else if constexpr (std::is_same_v<T, bool>)
        return values.flag(o);
    else if constexpr (std::is_same_v<T, std::string>)
        return values.text(o);
    else
        static_assert(sizeof(T) == 0, "give this field a parser: parsedField<parse, ...>");
}
} // namespace detail

/// The field at member path `Path` (&S::kernel, or &S::flood, &FloodOptions::passes) of an
/// options struct, read as int, float, bool or std::string by its kind.
template <auto... Path>
constexpr OptionField field(const MethodOption& o) {
    using S = typename detail::FirstOf<Path...>::Class;
    return {&o, &kOptionStructTag<S>,
            [](const MethodOptions& v, const MethodOption& opt, void* out) {
                auto& member = detail::memberAt<Path...>(*static_cast<S*>(out));
                member = detail::readOption<std::remove_cvref_t<decltype(member)>>(v, opt);
            }};
}
/// The same for a member of another type: `Parse` turns the option's validated text into it (a
/// choice into an enum).
template <auto Parse, auto... Path>
constexpr OptionField parsedField(const MethodOption& o) {
    using S = typename detail::FirstOf<Path...>::Class;
    return {&o, &kOptionStructTag<S>,
            [](const MethodOptions& v, const MethodOption& opt, void* out) {
                detail::memberAt<Path...>(*static_cast<S*>(out)) = Parse(v.text(opt));
            }};
}

/// A method's options: its struct's fields in --help order, and how to parse values into it.
/// Iterates as the fields' metadata (const MethodOption*).
class MethodOptionSet {
  public:
    constexpr MethodOptionSet() = default;
    constexpr MethodOptionSet(std::span<const OptionField> fields,
                              std::any (*parser)(std::span<const OptionField>,
                                                 const MethodOptions&))
        : fields_(fields), parse_(parser) {}

    /// The method's options struct with `values` parsed into it (defaults where unset); empty
    /// for a method without options. Throws std::invalid_argument naming the first invalid
    /// field's flag.
    [[nodiscard]] std::any parse(const MethodOptions& values) const {
        return parse_ ? parse_(fields_, values) : std::any{};
    }
    [[nodiscard]] std::span<const OptionField> fields() const { return fields_; }

    struct Iterator {
        const OptionField* at;
        const MethodOption* operator*() const { return at->option; }
        Iterator& operator++() {
            ++at;
            return *this;
        }
        bool operator==(const Iterator&) const = default;
    };
    [[nodiscard]] Iterator begin() const { return {fields_.data()}; }
    [[nodiscard]] Iterator end() const { return {fields_.data() + fields_.size()}; }
    [[nodiscard]] bool empty() const { return fields_.empty(); }
    [[nodiscard]] std::size_t size() const { return fields_.size(); }
    [[nodiscard]] const MethodOption* front() const { return fields_.front().option; }

  private:
    std::span<const OptionField> fields_;
    std::any (*parse_)(std::span<const OptionField>, const MethodOptions&) = nullptr;
};

namespace detail {
template <class S>
std::any parseOptionStruct(std::span<const OptionField> fields, const MethodOptions& values) {
    S out{};
    for (const OptionField& f : fields) f.read(values, *f.option, &out);
    return out;
}
} // namespace detail

/// The option set of struct S: a field of another struct in `fields` is a compile error.
template <class S>
consteval MethodOptionSet optionSet(std::span<const OptionField> fields) {
    for (const OptionField& f : fields)
        if (f.structTag != &kOptionStructTag<S>)
            throw std::logic_error("optionSet: a field of another options struct");
    return {fields, &detail::parseOptionStruct<S>};
}

} // namespace fl
