#pragma once
// Helpers shared by PointIO.cpp, MeshIO.cpp and MeshSvg.cpp (private to the library).

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace fl::geom::detail {

/// Appends the shortest decimal text that reads back as exactly `v` (std::to_chars).
void appendDouble(std::string& out, double v);
/// Appends `v` rounded to `digits` significant digits (sizes that need no exact round trip).
void appendRounded(std::string& out, double v, int digits);
/// Appends an unsigned integer.
void appendUint(std::string& out, std::uint64_t v);

/// Writes `contents` to a temporary file next to `path`, then renames it onto `path`. Throws
/// PointFileError naming the path and the system error; never leaves the temporary behind.
void writeFileAtomically(const std::filesystem::path& path, std::string_view contents);

/// Throws std::invalid_argument naming `what` and the index of the first non-finite point.
void requireFinite(const std::vector<glm::dvec2>& points, const char* what);
/// Throws std::invalid_argument unless `triangles` holds whole triples of indices < points.size().
void requireTriangles(const std::vector<glm::dvec2>& points,
                      const std::vector<std::uint32_t>& triangles, const char* what);

} // namespace fl::geom::detail
