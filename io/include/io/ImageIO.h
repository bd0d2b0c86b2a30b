#pragma once
// Image files and the pixels they hold (CPU only; GL read-backs are renderer/io/TextureImage.h):
// writing/reading PNG and EXR, sRGB encoding. Every write goes to a temporary name in the
// destination folder and is renamed into place, so a failure never leaves a half-written file.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace fl {

/// Float pixels, row 0 at the top (file order), `channels` interleaved per pixel.
struct FloatImage {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<float> data;
    [[nodiscard]] float at(int x, int y, int c) const {
        return data[(static_cast<size_t>(y) * width + x) * channels + c];
    }
};

/// 8-bit pixels, row 0 at the top, `channels` interleaved.
struct ByteImage {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<std::uint8_t> data;
};

/// `channels` floats a pixel in GL's row order (row 0 at the bottom) as an image with row 0 at
/// the top: what readTexture and a pixel-buffer read-back (gpu/ReadBack.h) both return.
FloatImage fromGlRows(const float* rows, int width, int height, int channels);

/// The sRGB transfer function (IEC 61966-2-1) for a linear value clamped to [0,1]: the one
/// curve the PNG writer and the surfaces pass's base colour (SurfaceDecode.h) use.
float linearToSrgb(float linear);
/// The sRGB transfer function for a linear value (clamped to [0,1]), as 0..255.
std::uint8_t linearToSrgb8(float linear);
/// Encodes linear RGB(A) floats as 8-bit sRGB (alpha kept linear, forced to 255 if absent).
ByteImage toSrgb8(const FloatImage& linear);

/// Writes an 8-bit PNG; throws std::runtime_error naming the path on failure.
void writePng(const std::filesystem::path& path, const ByteImage& image);
/// The largest PNG readPng decodes, per side (the flood grids' limit; 1 GiB of RGBA).
inline constexpr int kMaxPngSide = 16384;
/// Reads a PNG as 8-bit RGBA; throws std::runtime_error "ROLE PATH: problem" on failure
/// (fl::InputFileError for a file that is missing, not regular or over kImageInputLimitMiB).
ByteImage readPng(const std::filesystem::path& path, std::string_view role = {});

/// One named float channel of an EXR file, width*height values, row 0 at the top.
struct ExrChannel {
    std::string name;
    std::vector<float> values;
};
/// How writeExr stores the pixels: ZIP (small; the outputs) or uncompressed (several times
/// faster to write: files kept only for a while, such as a capture's resume state).
enum class ExrCompression { Zip, None };
/// Writes a 32-bit float EXR with the given channels.
void writeExr(const std::filesystem::path& path, int width, int height,
              const std::vector<ExrChannel>& channels,
              ExrCompression compression = ExrCompression::Zip);
/// Reads every channel of an EXR file as floats.
std::vector<ExrChannel> readExr(const std::filesystem::path& path, int& width, int& height);

/// Writes text (CSV, JSON, HTML) under a temporary name and renames it into place; throws
/// std::runtime_error naming the path on failure.
void writeTextFile(const std::filesystem::path& path, const std::string& text);

/// Throws std::runtime_error if any value is NaN or infinite (we never write such pixels).
void requireFinite(const FloatImage& image, const std::string& what);

} // namespace fl
