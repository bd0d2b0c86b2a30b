#pragma once
// PNG files written byte by byte, for the readers' tests of files that claim more than they hold.

#include <cstdint>
#include <string>

namespace fl::test {

/// A PNG chunk: its length field (`length`, which may lie), type, data and a zero CRC (neither
/// stb_image nor our checks read it).
std::string pngChunk(const std::string& type, const std::string& data, std::uint32_t length);
/// The PNG signature and an IHDR of w x h at `depth` bits of colour type `colour`.
std::string pngStart(std::uint32_t w, std::uint32_t h, int depth, int colour);

} // namespace fl::test
