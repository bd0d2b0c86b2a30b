#include "PngBytes.h"

namespace fl::test {

std::string pngChunk(const std::string& type, const std::string& data, std::uint32_t length) {
    std::string out;
    for (int shift = 24; shift >= 0; shift -= 8) out += static_cast<char>(length >> shift);
    return out + type + data + std::string(4, '\0');
}

std::string pngStart(std::uint32_t w, std::uint32_t h, int depth, int colour) {
    std::string ihdr;
    for (const std::uint32_t v : {w, h})
        for (int shift = 24; shift >= 0; shift -= 8) ihdr += static_cast<char>(v >> shift);
    ihdr += {static_cast<char>(depth), static_cast<char>(colour), 0, 0, 0};
    return "\x89PNG\r\n\x1a\n" + pngChunk("IHDR", ihdr, 13);
}

} // namespace fl::test
