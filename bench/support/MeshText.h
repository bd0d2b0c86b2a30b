#pragma once
// What the mesh readers (MeshImport.cpp, MeshPly.cpp) share: lines and words of text, numbers
// read as the file spells them.

#include "MeshImport.h"

#include <cstdint>
#include <string_view>
#include <vector>

namespace fl::bench::detail {

/// Splits text into lines (LF or CRLF), counting them from 1.
class LineReader {
  public:
    explicit LineReader(std::string_view text) : rest_(text) {}
    /// The next line without its line end; false at the end of the text.
    bool next(std::string_view& line);
    [[nodiscard]] std::size_t line() const { return line_; }
    /// The text after the line next() returned last.
    [[nodiscard]] std::string_view rest() const { return rest_; }

  private:
    std::string_view rest_;
    std::size_t line_ = 0;
    bool done_ = false;
};

/// The words of `line` separated by blanks (spaces, tabs), into `out` (cleared first).
void splitWords(std::string_view line, std::vector<std::string_view>& out);

/// `word` as a number (a leading '+' allowed); fails at `where` naming `what` otherwise.
double number(std::string_view word, const MeshWhere& where, std::string_view what);
/// `word` as a whole number in [lo, hi]; fails at `where` naming `what` otherwise.
std::int64_t integer(std::string_view word, const MeshWhere& where, std::string_view what,
                     std::int64_t lo, std::int64_t hi);

/// Appends the fan of a polygon with `corners` (indices into mesh.positions) to mesh.indices;
/// fails at `where` for fewer than 3 corners.
void addFan(Mesh& mesh, std::span<const std::uint32_t> corners, const MeshWhere& where);

} // namespace fl::bench::detail
