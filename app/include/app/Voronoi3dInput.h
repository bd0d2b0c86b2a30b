#pragma once
// The sites of `floodlight voronoi3d`: random, or read from a text file of "x y z" per line.
// No GL and no CLI here, so that tests and fuzz targets can drive the reader alone.

#include <jfa/Jfa3d.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace fl::app {

/// Most sites voronoi3d takes (from --sites or a file): ids and indices stay exact in the
/// float channels of the EXR.
inline constexpr int kMaxSites3d = 1 << 24;

/// Parses `text`, one site "x y z" per line (integer voxel coordinates in 0..size-1; blank lines
/// and lines starting with # skipped); a site's id is its order in the file (0, 1, ...). Throws
/// std::invalid_argument "FILE:LINE: problem" for a line that is not three whole numbers, a
/// coordinate outside the grid (naming the range), a duplicate (naming the first line), more
/// than kMaxSites3d sites, or "FILE: no sites".
std::vector<jfa::Site3> parseSites3d(std::string_view text, const std::string& file, int size);

} // namespace fl::app
