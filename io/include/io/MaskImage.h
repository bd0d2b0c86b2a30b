#pragma once
// Pictures as grids for the distance transforms and Voronoi diagrams of masks (`voronoi --mask
// --labels`): PNG row 0 is the top of the picture, grid row 0 is y = 0, so both flip rows, and
// the picture reads the same way in the grid.

#include <io/ImageIO.h>

#include <cstdint>
#include <vector>

namespace fl {

/// 1 where the pixel's red channel is above 127 (the mask's sites), else 0; width*height.
std::vector<std::uint8_t> maskGrid(const ByteImage& picture);

/// One id per RGB colour, 0, 1, ... in order of first appearance (reading the picture from its
/// top row); width*height.
std::vector<std::int32_t> labelGrid(const ByteImage& picture);

} // namespace fl
