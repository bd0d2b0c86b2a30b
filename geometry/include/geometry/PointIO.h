#pragma once
// Reading and writing 2D point sets (the input of `floodlight delaunay`).
//
// Formats
// - Triangle's .node: header `#vertices [dimension=2 [#attributes=0 [#markers=0]]]`, then one
//   line `index x y [attributes...] [marker]` per vertex. Indices start at 0 or 1 (the first
//   vertex decides) and must be consecutive. Attributes and markers are validated and dropped.
//   We write 0-based files: Triangle takes its index base from the first vertex of the .node, so
//   it reads them, and the .ele files written next to them (MeshIO.h), as they are.
// - Text (.txt, .xy): `x y` or `x, y` per line.
// - Binary (.bin, .f64): raw little-endian float64 pairs x, y; no header.
// In the text formats `#` starts a comment and blank lines are skipped. An empty file holds 0
// points; whether that is acceptable is the caller's decision. Points are returned as written,
// duplicates included (the triangulator deals with those).
//
// Numbers are parsed with std::from_chars and written with std::to_chars (shortest round trip),
// so every finite double, denormals and -0 included, survives a write/read cycle bit for bit,
// whatever the C locale. NaN, infinities and values outside the double range are rejected.

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fl::geom {

/// Any problem reading or writing a point or mesh file. what() is "FILE:LINE: problem" for text
/// files, "FILE: byte OFFSET: problem" for binary files and "FILE: problem" otherwise.
class PointFileError : public std::runtime_error {
  public:
    /// A problem on a line of a text file (1-based line number).
    PointFileError(const std::string& file, std::size_t line, const std::string& problem);
    /// A problem with the file as a whole (cannot open, cannot write, unknown extension).
    PointFileError(const std::string& file, const std::string& problem);
    /// A problem at a byte offset of a binary file.
    static PointFileError atByte(const std::string& file, std::uint64_t offset,
                                 const std::string& problem);

    [[nodiscard]] const std::string& file() const { return file_; }
    /// 1-based line number, 0 when the problem is not on a line.
    [[nodiscard]] std::size_t line() const { return line_; }
    /// Byte offset for binary files, -1 when not applicable.
    [[nodiscard]] std::int64_t byteOffset() const { return byteOffset_; }
    /// The problem without the location prefix.
    [[nodiscard]] const std::string& problem() const { return problem_; }

  private:
    PointFileError(std::string file, std::size_t line, std::int64_t byteOffset, std::string problem,
                   const std::string& what);
    std::string file_;
    std::size_t line_ = 0;
    std::int64_t byteOffset_ = -1;
    std::string problem_;
};

/// How to read or write a point file; Auto picks from the extension.
enum class PointFormat { Auto, Node, Text, Binary };

/// The format a file name's extension stands for (case-insensitive); throws PointFileError for
/// an unknown extension.
PointFormat pointFormatFromExtension(const std::filesystem::path& path);

/// A Triangle .node file's contents.
struct NodeFile {
    std::vector<glm::dvec2> points;
    int indexBase = 0;              ///< index of the first vertex in the file: 0 or 1
    std::size_t attributeCount = 0; ///< attributes per vertex (checked to be numbers, dropped)
    bool hasBoundaryMarkers = false;
};

/// Parses .node text; `name` is the file name used in error messages.
NodeFile parseNode(std::string_view text, const std::string& name);
/// Parses `x y` / `x, y` text; `name` is the file name used in error messages.
std::vector<glm::dvec2> parseTextPoints(std::string_view text, const std::string& name);
/// Decodes little-endian float64 pairs; `name` is the file name used in error messages.
std::vector<glm::dvec2> parseBinaryPoints(std::span<const std::byte> bytes,
                                          const std::string& name);

/// Reads a Triangle .node file, keeping its index base.
NodeFile readNodeFile(const std::filesystem::path& path);
/// Reads a point file in the given format (Auto: from the extension).
std::vector<glm::dvec2> readPoints(const std::filesystem::path& path,
                                   PointFormat format = PointFormat::Auto);

/// Writes a 0-based .node file (`N 2 0 0` header); readable by readNodeFile and by Triangle.
void writeNodeFile(const std::filesystem::path& path, const std::vector<glm::dvec2>& points);
/// Writes one `x y` line per point.
void writeTextPoints(const std::filesystem::path& path, const std::vector<glm::dvec2>& points);
/// Writes raw little-endian float64 x, y pairs.
void writeBinaryPoints(const std::filesystem::path& path, const std::vector<glm::dvec2>& points);
/// Writes points in the given format (Auto: from the extension).
void writePoints(const std::filesystem::path& path, const std::vector<glm::dvec2>& points,
                 PointFormat format = PointFormat::Auto);

// Every writer throws std::invalid_argument for non-finite points (they could not be read back)
// before touching the disk, and PointFileError (path and system error text) when the file cannot
// be written. Files are written under a temporary name in the target folder and renamed into
// place, so readers never see a half-written file; the temporary is removed on failure. (Not
// fsynced: a crash of the program cannot leave a partial file, a power cut may. A symbolic link
// at the path is replaced, not written through.)

} // namespace fl::geom
