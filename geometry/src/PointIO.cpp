#include <geometry/PointIO.h>

#include "PointIODetail.h"

#include <base/InputFile.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <type_traits>
#include <utility>

namespace fl::geom {

// --- PointFileError ---------------------------------------------------------------------------

PointFileError::PointFileError(std::string file, std::size_t line, std::int64_t byteOffset,
                               std::string problem, const std::string& what)
    : std::runtime_error(what), file_(std::move(file)), line_(line), byteOffset_(byteOffset),
      problem_(std::move(problem)) {}

PointFileError::PointFileError(const std::string& file, std::size_t line,
                               const std::string& problem)
    : PointFileError(file, line, -1, problem, file + ":" + std::to_string(line) + ": " + problem) {}

PointFileError::PointFileError(const std::string& file, const std::string& problem)
    : PointFileError(file, 0, -1, problem, file + ": " + problem) {}

PointFileError PointFileError::atByte(const std::string& file, std::uint64_t offset,
                                      const std::string& problem) {
    return PointFileError(file, 0, static_cast<std::int64_t>(offset), problem,
                          file + ": byte " + std::to_string(offset) + ": " + problem);
}

namespace {

// --- Lines and fields ---------------------------------------------------------------------------

// Where a parse problem is: thrown as "name:line: problem".
struct Where {
    const std::string& name;
    std::size_t line = 0;
    [[noreturn]] void fail(const std::string& problem) const {
        throw PointFileError(name, line, problem);
    }
};

// A token for an error message: binary junk in a misnamed file must not flood the terminal or
// garble it with control bytes.
std::string quote(std::string_view token) {
    constexpr std::size_t kMax = 40;
    std::string out = "'";
    for (std::size_t i = 0; i < token.size() && i < kMax; ++i) {
        const auto c = static_cast<unsigned char>(token[i]);
        out += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : '?';
    }
    if (token.size() > kMax) out += "...";
    return out + "'";
}

// Splits text into lines (LF or CRLF), dropping comments; counts line numbers from 1.
class LineReader {
  public:
    explicit LineReader(std::string_view text) : text_(text) {
        // A UTF-8 byte order mark (some Windows editors add one) is not part of the first value.
        if (text_.starts_with("\xEF\xBB\xBF")) text_.remove_prefix(3);
    }
    /// The next line without its comment; false at the end of the text.
    bool next(std::string_view& content) {
        if (pos_ >= text_.size()) return false;
        const std::size_t nl = text_.find('\n', pos_);
        const std::size_t end = nl == std::string_view::npos ? text_.size() : nl;
        content = text_.substr(pos_, end - pos_);
        pos_ = nl == std::string_view::npos ? text_.size() : nl + 1;
        ++line_;
        if (const std::size_t hash = content.find('#'); hash != std::string_view::npos)
            content = content.substr(0, hash);
        return true;
    }
    /// The number of the line next() returned last (0 before the first).
    [[nodiscard]] std::size_t line() const { return line_; }

  private:
    std::string_view text_;
    std::size_t pos_ = 0;
    std::size_t line_ = 0;
};

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// Splits a line into fields separated by white space and, when allowComma, one comma each.
void splitFields(std::string_view s, bool allowComma, const Where& where,
                 std::vector<std::string_view>& fields) {
    fields.clear();
    std::size_t pos = 0;
    bool afterComma = false;
    for (;;) {
        while (pos < s.size() && isSpace(s[pos])) ++pos;
        if (pos == s.size()) {
            if (afterComma) where.fail("missing value after ','");
            return;
        }
        if (allowComma && s[pos] == ',') where.fail("empty value before ','");
        const std::size_t start = pos;
        while (pos < s.size() && !isSpace(s[pos]) && !(allowComma && s[pos] == ',')) ++pos;
        fields.push_back(s.substr(start, pos - start));
        afterComma = false;
        while (pos < s.size() && isSpace(s[pos])) ++pos;
        if (allowComma && pos < s.size() && s[pos] == ',') {
            ++pos;
            afterComma = true;
        }
    }
}

// --- Numbers ------------------------------------------------------------------------------------

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

// For a decimal that std::from_chars found out of range: whether it is too large (overflow) or
// too close to zero (underflow). Only the order of magnitude matters, and it is far from 0.
bool tooLarge(std::string_view s) {
    if (!s.empty() && (s[0] == '-' || s[0] == '+')) s.remove_prefix(1);
    std::size_t i = 0;
    while (i < s.size() && s[i] == '0') ++i;
    const std::size_t intStart = i;
    while (i < s.size() && isDigit(s[i])) ++i;
    long long order = static_cast<long long>(i - intStart);
    if (order == 0 && i < s.size() && s[i] == '.') {
        for (++i; i < s.size() && s[i] == '0'; ++i) --order;
    }
    if (const std::size_t e = s.find_first_of("eE"); e != std::string_view::npos) {
        std::string_view ex = s.substr(e + 1);
        const bool negative = ex.starts_with('-');
        if (ex.starts_with('-') || ex.starts_with('+')) ex.remove_prefix(1);
        long long exponent = 0;
        const auto [p, ec] = std::from_chars(ex.data(), ex.data() + ex.size(), exponent);
        // An exponent beyond any count of digits decides alone; adding it to `order` could
        // overflow (fuzz_points: 4e000000009223372036854775807).
        constexpr long long kDecisive = 1LL << 50;
        if (ec == std::errc::result_out_of_range || exponent > kDecisive) return !negative;
        order += negative ? -exponent : exponent;
    }
    return order > 0;
}

// Parses a finite double; `field` names it in messages ("x", "attribute 2").
double toDouble(std::string_view token, const Where& where, const std::string& field) {
    std::string_view s = token;
    // from_chars rejects a leading '+', which other programs write.
    if (s.size() > 1 && s[0] == '+' && (isDigit(s[1]) || s[1] == '.')) s.remove_prefix(1);
    double v = 0.0;
    const char* end = s.data() + s.size();
    const auto [p, ec] = std::from_chars(s.data(), end, v, std::chars_format::general);
    if (ec == std::errc::result_out_of_range && p == end) {
        where.fail(field + " " + quote(token) +
                   (tooLarge(s) ? " overflows double (magnitude above 1.8e308)"
                                : " underflows double (nonzero but below 4.9e-324)"));
    }
    if (ec != std::errc{} || p != end) where.fail(field + " " + quote(token) + " is not a number");
    if (std::isnan(v)) where.fail(field + " is NaN");
    if (std::isinf(v)) where.fail(field + " is infinite");
    return v;
}

// Parses a decimal integer into T; `what` names it in messages.
template <typename T>
T toInteger(std::string_view token, const Where& where, const std::string& what) {
    T v{};
    const char* end = token.data() + token.size();
    const auto [p, ec] = std::from_chars(token.data(), end, v);
    if (ec == std::errc::result_out_of_range && p == end)
        where.fail(what + " " + quote(token) + " is out of range");
    if (ec != std::errc{} || p != end) {
        where.fail(what + " " + quote(token) + " is not " +
                   (std::is_signed_v<T> ? "an integer" : "a non-negative integer"));
    }
    return v;
}

std::string plural(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

// --- Files --------------------------------------------------------------------------------------

// Regular files within the limit only (base/InputFile.h): a FIFO or device would be read forever.
std::string readWholeFile(const std::filesystem::path& path, PointFormat format) {
    const std::uintmax_t limit =
        format == PointFormat::Binary ? kBinaryInputLimitMiB : kTextInputLimitMiB;
    try {
        return readInputFile(path, "", limit);
    } catch (const InputFileError& e) {
        throw PointFileError(path.string(), e.problem());
    }
}

} // namespace

// --- Parsers ------------------------------------------------------------------------------------

namespace {

// A .node file's header: "#vertices [dimension [#attributes [#markers]]]", Triangle's defaults
// filling the rest.
struct NodeHeader {
    std::uint64_t count = 0, attributes = 0, markers = 0;
};

NodeHeader parseNodeHeader(const std::vector<std::string_view>& fields, const Where& header) {
    if (fields.size() > 4) {
        header.fail("header has " + std::to_string(fields.size()) +
                    " values; expected '#vertices [dimension [#attributes [#markers]]]'");
    }
    NodeHeader h;
    h.count = toInteger<std::uint64_t>(fields[0], header, "vertex count");
    const auto dim = fields.size() > 1 ? toInteger<std::uint64_t>(fields[1], header, "dimension")
                                       : std::uint64_t{2};
    if (dim != 2) header.fail("dimension is " + std::to_string(dim) + "; only 2D points are read");
    h.attributes = fields.size() > 2
                       ? toInteger<std::uint64_t>(fields[2], header, "attribute count")
                       : std::uint64_t{0};
    // A bound that keeps 3 + attributes from overflowing; no real file comes near it.
    if (h.attributes > 100000)
        header.fail("attribute count " + std::to_string(h.attributes) + " is implausibly large");
    h.markers = fields.size() > 3
                    ? toInteger<std::uint64_t>(fields[3], header, "boundary marker count")
                    : std::uint64_t{0};
    if (h.markers > 1)
        header.fail("boundary marker count is " + std::to_string(h.markers) + "; expected 0 or 1");
    return h;
}

// One vertex line of `fields` (already split, not empty), appended to out.points.
void parseNodeVertex(const std::vector<std::string_view>& fields, const Where& where,
                     const NodeHeader& h, NodeFile& out) {
    const std::size_t perLine = 3 + h.attributes + h.markers;
    if (fields.size() != perLine) {
        std::string layout = "index x y";
        if (h.attributes > 0) layout += " + " + plural(h.attributes, "attribute", "attributes");
        if (h.markers > 0) layout += " + marker";
        where.fail("expected " + std::to_string(perLine) + " values (" + layout + "), found " +
                   std::to_string(fields.size()));
    }
    const auto index = toInteger<long long>(fields[0], where, "vertex index");
    if (out.points.empty()) {
        if (index != 0 && index != 1)
            where.fail("first vertex index is " + std::to_string(index) + "; expected 0 or 1");
        out.indexBase = static_cast<int>(index);
    } else {
        const auto expected = out.indexBase + static_cast<long long>(out.points.size());
        if (index != expected) {
            where.fail("vertex index " + std::to_string(index) + " where " +
                       std::to_string(expected) + " was expected (indices must be consecutive)");
        }
    }
    const double x = toDouble(fields[1], where, "x");
    const double y = toDouble(fields[2], where, "y");
    for (std::size_t a = 0; a < h.attributes; ++a)
        toDouble(fields[3 + a], where, "attribute " + std::to_string(a + 1));
    if (h.markers > 0) toInteger<long long>(fields.back(), where, "boundary marker");
    out.points.emplace_back(x, y);
}

} // namespace

NodeFile parseNode(std::string_view text, const std::string& name) {
    LineReader reader(text);
    std::vector<std::string_view> fields;
    std::string_view line;
    NodeFile out;
    for (;;) {
        if (!reader.next(line)) return out; // nothing but comments: 0 points
        splitFields(line, false, {name, reader.line()}, fields);
        if (!fields.empty()) break;
    }
    const NodeHeader h = parseNodeHeader(fields, Where{name, reader.line()});
    out.attributeCount = h.attributes;
    out.hasBoundaryMarkers = h.markers == 1;
    // The header may lie; never reserve more than the text could hold.
    out.points.reserve(std::min<std::uint64_t>(h.count, text.size() / 6 + 1));
    while (out.points.size() < h.count) {
        if (!reader.next(line)) {
            Where{name, reader.line()}.fail("file ends after " + std::to_string(out.points.size()) +
                                            " of the " + plural(h.count, "vertex", "vertices") +
                                            " the header announced");
        }
        const Where where{name, reader.line()};
        splitFields(line, false, where, fields);
        if (!fields.empty()) parseNodeVertex(fields, where, h, out);
    }
    // Content after the announced vertices means the header and the body disagree.
    while (reader.next(line)) {
        const Where where{name, reader.line()};
        splitFields(line, false, where, fields);
        if (!fields.empty()) {
            where.fail("unexpected values after the " + plural(h.count, "vertex", "vertices") +
                       " the header announced");
        }
    }
    return out;
}

std::vector<glm::dvec2> parseTextPoints(std::string_view text, const std::string& name) {
    LineReader reader(text);
    std::vector<std::string_view> fields;
    std::string_view line;
    std::vector<glm::dvec2> points;
    while (reader.next(line)) {
        const Where where{name, reader.line()};
        splitFields(line, true, where, fields);
        if (fields.empty()) continue;
        if (fields.size() != 2)
            where.fail("expected 2 values (x y), found " + std::to_string(fields.size()));
        const double x = toDouble(fields[0], where, "x");
        const double y = toDouble(fields[1], where, "y");
        points.emplace_back(x, y);
    }
    return points;
}

std::vector<glm::dvec2> parseBinaryPoints(std::span<const std::byte> bytes,
                                          const std::string& name) {
    constexpr std::size_t kPair = 2 * sizeof(double);
    if (const std::size_t extra = bytes.size() % kPair; extra != 0) {
        throw PointFileError::atByte(name, bytes.size() - extra,
                                     "file size " + std::to_string(bytes.size()) +
                                         " is not a multiple of 16 (float64 x, y pairs): " +
                                         plural(extra, "byte", "bytes") + " left over");
    }
    std::vector<glm::dvec2> points(bytes.size() / kPair);
    for (std::size_t i = 0; i < 2 * points.size(); ++i) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, bytes.data() + i * sizeof bits, sizeof bits);
        if constexpr (std::endian::native == std::endian::big) bits = __builtin_bswap64(bits);
        const double v = std::bit_cast<double>(bits);
        if (!std::isfinite(v)) {
            throw PointFileError::atByte(name, i * sizeof bits,
                                         std::string(i % 2 == 0 ? "x" : "y") + " of point " +
                                             std::to_string(i / 2) + " is " +
                                             (std::isnan(v) ? "NaN" : "infinite"));
        }
        points[i / 2][static_cast<int>(i % 2)] = v;
    }
    return points;
}

// --- Files --------------------------------------------------------------------------------------

PointFormat pointFormatFromExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".node") return PointFormat::Node;
    if (ext == ".txt" || ext == ".xy") return PointFormat::Text;
    if (ext == ".bin" || ext == ".f64") return PointFormat::Binary;
    throw PointFileError(path.string(),
                         "unknown point file extension " + quote(ext) +
                             " (expected .node, .txt, .xy, .bin or .f64, or name the format)");
}

NodeFile readNodeFile(const std::filesystem::path& path) {
    return parseNode(readWholeFile(path, PointFormat::Node), path.string());
}

std::vector<glm::dvec2> readPoints(const std::filesystem::path& path, PointFormat format) {
    if (format == PointFormat::Auto) format = pointFormatFromExtension(path);
    const std::string data = readWholeFile(path, format);
    switch (format) {
    case PointFormat::Node:
        return parseNode(data, path.string()).points;
    case PointFormat::Text:
        return parseTextPoints(data, path.string());
    case PointFormat::Binary:
        return parseBinaryPoints(std::as_bytes(std::span(data)), path.string());
    case PointFormat::Auto:
        break;
    }
    throw std::logic_error("readPoints: unreachable format");
}

void writeNodeFile(const std::filesystem::path& path, const std::vector<glm::dvec2>& points) {
    detail::requireFinite(points, "writeNodeFile");
    std::string out;
    out.reserve(points.size() * 48 + 32);
    detail::appendUint(out, points.size());
    out += " 2 0 0\n";
    for (std::size_t i = 0; i < points.size(); ++i) {
        detail::appendUint(out, i);
        out += ' ';
        detail::appendDouble(out, points[i].x);
        out += ' ';
        detail::appendDouble(out, points[i].y);
        out += '\n';
    }
    detail::writeFileAtomically(path, out);
}

void writeTextPoints(const std::filesystem::path& path, const std::vector<glm::dvec2>& points) {
    detail::requireFinite(points, "writeTextPoints");
    std::string out;
    out.reserve(points.size() * 48);
    for (const glm::dvec2& p : points) {
        detail::appendDouble(out, p.x);
        out += ' ';
        detail::appendDouble(out, p.y);
        out += '\n';
    }
    detail::writeFileAtomically(path, out);
}

void writeBinaryPoints(const std::filesystem::path& path, const std::vector<glm::dvec2>& points) {
    detail::requireFinite(points, "writeBinaryPoints");
    std::string out(points.size() * 2 * sizeof(double), '\0');
    for (std::size_t i = 0; i < 2 * points.size(); ++i) {
        auto bits = std::bit_cast<std::uint64_t>(points[i / 2][static_cast<int>(i % 2)]);
        if constexpr (std::endian::native == std::endian::big) bits = __builtin_bswap64(bits);
        std::memcpy(out.data() + i * sizeof bits, &bits, sizeof bits);
    }
    detail::writeFileAtomically(path, out);
}

void writePoints(const std::filesystem::path& path, const std::vector<glm::dvec2>& points,
                 PointFormat format) {
    if (format == PointFormat::Auto) format = pointFormatFromExtension(path);
    switch (format) {
    case PointFormat::Node:
        return writeNodeFile(path, points);
    case PointFormat::Text:
        return writeTextPoints(path, points);
    case PointFormat::Binary:
        return writeBinaryPoints(path, points);
    case PointFormat::Auto:
        break;
    }
    throw std::logic_error("writePoints: unreachable format");
}

} // namespace fl::geom
