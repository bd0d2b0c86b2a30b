#pragma once
// Writing triangulations: Triangle's .ele (next to a .node from PointIO.h) and Wavefront OBJ.
// Triangles are flat index triples into the point list; both writers check every index against
// points.size() (std::invalid_argument) before touching the disk, write under a temporary name and
// rename (see PointIO.h), and throw PointFileError when the file cannot be written.

#include <geometry/PointIO.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace fl::geom {

/// Writes a Triangle .ele file: header `#triangles 3 0`, then `index a b c` per triangle, with
/// triangle and vertex indices starting at `indexBase` (0 to match writeNodeFile, or the
/// NodeFile::indexBase of the .node the points came from).
void writeEleFile(const std::filesystem::path& path, const std::vector<glm::dvec2>& points,
                  const std::vector<std::uint32_t>& triangles, int indexBase = 0);

/// Writes a Wavefront OBJ: `v x y 0` per point and `f a b c` (1-based) per triangle.
void writeObjFile(const std::filesystem::path& path, const std::vector<glm::dvec2>& points,
                  const std::vector<std::uint32_t>& triangles);

} // namespace fl::geom
