#include <io/PngLimits.h>

#include <base/Text.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <span>

namespace fl {

namespace {

// zlib's deflate expands at most 1032 times: a 258-byte match coded in 2 bits is its densest.
constexpr double kMaxDeflateRatio = 1032.0;

} // namespace

// stb_image sizes its buffers from the chunk lengths and the header before it reads the data,
// so 100 bytes claiming a 2 GiB IDAT chunk or a 16384^2 16-bit image would allocate gigabytes
// first. Neither check refuses a file stb_image could decode: it fails on a chunk before IEND
// that runs past the end of the file, and on image data too short for the image.
std::string pngSizeProblem(const unsigned char* data, std::size_t size) {
    const std::span<const unsigned char> bytes(data, size);
    static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (bytes.size() < 8 || !std::equal(kSignature, kSignature + 8, bytes.begin())) return {};
    const auto be32 = [&](std::size_t at) {
        return std::uint32_t{bytes[at]} << 24 | std::uint32_t{bytes[at + 1]} << 16 |
               std::uint32_t{bytes[at + 2]} << 8 | std::uint32_t{bytes[at + 3]};
    };
    std::size_t header = 0;      // offset of IHDR's data (an iPhone PNG puts a CgBI chunk first)
    std::uint64_t imageData = 0; // bytes in IDAT chunks
    for (std::size_t at = 8; at + 8 <= bytes.size();) {
        const std::uint64_t length = be32(at);
        const unsigned char* type = &bytes[at + 4];
        if (std::memcmp(type, "IEND", 4) == 0) break; // stb_image reads nothing after it
        if (length + 12 > bytes.size() - at)
            return cat("the chunk at byte ", at, " claims ", length, " bytes, past the end of the ",
                       bytes.size(), "-byte file (truncated or corrupt PNG)");
        if (std::memcmp(type, "IHDR", 4) == 0 && length >= 13 && header == 0) header = at + 8;
        if (std::memcmp(type, "IDAT", 4) == 0) imageData += length;
        at += 12 + static_cast<std::size_t>(length);
    }
    if (header == 0) return {};
    // Samples per pixel of the colour types 0 (grey), 2 (RGB), 3 (palette), 4, 6 (with alpha).
    constexpr int kSamples[7] = {1, 0, 3, 1, 2, 0, 4};
    const std::uint32_t width = be32(header), height = be32(header + 4);
    const int depth = bytes[header + 8], colourType = bytes[header + 9];
    if (colourType > 6 || kSamples[colourType] == 0) return {};
    const double pixelBytes = double(width) * double(height) * kSamples[colourType] * depth / 8.0;
    if (pixelBytes > kMaxDeflateRatio * static_cast<double>(imageData))
        return cat(imageData, " bytes of image data cannot hold the ", width, "x", height,
                   " image the header claims (truncated or corrupt PNG)");
    return {};
}

} // namespace fl
