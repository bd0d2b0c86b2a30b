#pragma once
// String building without <format> (GCC 12) and without chains of operator+ (which GCC 12 flags
// with -Wrestrict), and escaping for the XML/SVG/HTML we write.

#include <sstream>
#include <string>
#include <string_view>

namespace fl {

/// Concatenates anything streamable: cat("meshes[", 3, "]") == "meshes[3]".
template <class... Args>
std::string cat(const Args&... args) {
    std::ostringstream s;
    (s << ... << args);
    return s.str();
}

/// `v` with `digits` digits after the point ("%.*f"): fixed(3.14159, 2) == "3.14".
std::string fixed(double v, int digits);

/// An errno value in words ("No such file or directory"), for file messages.
std::string systemMessage(int err);

/// `text` with &, <, > and " replaced by XML entities (element text and attribute values).
std::string xmlEscape(std::string_view text);

} // namespace fl
