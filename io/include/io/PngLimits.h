#pragma once
// A PNG's claims checked against its size before stb_image decodes it: every reader of PNG bytes
// (readPng for masks and labels, the glTF loader for textures) asks this first.

#include <cstddef>
#include <string>

namespace fl {

/// Why the PNG in `data` cannot hold what its chunks and header claim (a chunk past the end of
/// the bytes, or image data too short for the image even at deflate's densest); empty when it
/// may, or when it is no PNG at all (stb_image then says what it is not).
std::string pngSizeProblem(const unsigned char* data, std::size_t size);

} // namespace fl
