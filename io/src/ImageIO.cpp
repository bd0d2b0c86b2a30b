#include <io/ImageIO.h>
#include <io/PngLimits.h>

#include <base/InputFile.h>
#include <base/OutputFiles.h>
#include <base/Text.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#include <stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
#include <stb_image_write.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace fl {

namespace {} // namespace

void writeTextFile(const std::filesystem::path& path, const std::string& text) {
    makeOutputFolder(path.parent_path()); // folders are made on demand
    writeFileAtomically(path, text);      // base/OutputFiles.h
}

FloatImage fromGlRows(const float* rows, int width, int height, int channels) {
    FloatImage img{width, height, channels, {}};
    const size_t row = static_cast<size_t>(width) * static_cast<size_t>(channels);
    // GL stores row 0 at the bottom; files store it at the top.
    img.data.resize(row * static_cast<size_t>(height));
    for (int y = 0; y < height; ++y)
        std::memcpy(&img.data[static_cast<size_t>(y) * row],
                    rows + static_cast<size_t>(height - 1 - y) * row, row * sizeof(float));
    return img;
}

float linearToSrgb(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

std::uint8_t linearToSrgb8(float c) {
    if (!(c > 0.0f)) return 0; // also maps NaN to 0
    if (c >= 1.0f) return 255;
    return static_cast<std::uint8_t>(std::lround(linearToSrgb(c) * 255.0f));
}

ByteImage toSrgb8(const FloatImage& linear) {
    ByteImage out{linear.width, linear.height, 4, {}};
    const size_t n = static_cast<size_t>(linear.width) * static_cast<size_t>(linear.height);
    out.data.resize(n * 4);
    for (size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            const int src = std::min(c, linear.channels - 1);
            out.data[i * 4 + static_cast<size_t>(c)] = linearToSrgb8(
                linear.data[i * static_cast<size_t>(linear.channels) + static_cast<size_t>(src)]);
        }
        out.data[i * 4 + 3] = 255; // PNGs are for looking: opaque, background shows the sky
    }
    return out;
}

void writePng(const std::filesystem::path& path, const ByteImage& image) {
    makeOutputFolder(path.parent_path()); // folders are made on demand
    const std::filesystem::path tmp = temporarySibling(path);
    const int ok = stbi_write_png(tmp.c_str(), image.width, image.height, image.channels,
                                  image.data.data(), image.width * image.channels);
    if (!ok) {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        throw std::runtime_error(path.string() + ": cannot write PNG: " + std::strerror(errno));
    }
    finishOutputFile(tmp, path);
}

ByteImage readPng(const std::filesystem::path& path, std::string_view role) {
    // The bytes through base/InputFile.h (regular files within kImageInputLimitMiB), then the
    // size from the header before decoding: a small PNG can claim a huge image.
    const std::vector<unsigned char> bytes = readInputBytes(path, role, kImageInputLimitMiB);
    const std::string name = role.empty() ? path.string() : cat(role, " ", path.string());
    if (bytes.size() > static_cast<std::size_t>(INT_MAX))
        throw std::runtime_error(name + ": cannot read PNG: file too large");
    const int length = static_cast<int>(bytes.size());
    int w = 0, h = 0, n = 0;
    if (stbi_info_from_memory(bytes.data(), length, &w, &h, &n) &&
        (w > kMaxPngSide || h > kMaxPngSide))
        throw std::runtime_error(cat(name, ": image of ", w, "x", h,
                                     " is larger than the limit of ", kMaxPngSide,
                                     " pixels per side"));
    if (const std::string problem = pngSizeProblem(bytes.data(), bytes.size()); !problem.empty())
        throw std::runtime_error(name + ": " + problem);
    stbi_uc* pixels = stbi_load_from_memory(bytes.data(), length, &w, &h, &n, 4);
    if (!pixels) {
        // stb_image's reason is a short ASCII phrase, but on some corrupt files it is empty or
        // left over from a failed inner step: only a printable one is quoted.
        const char* why = stbi_failure_reason();
        std::string reason = why ? why : "";
        if (reason.empty() || !std::all_of(reason.begin(), reason.end(),
                                           [](unsigned char c) { return c >= 0x20 && c < 0x7f; }))
            reason = "not a valid PNG image";
        throw std::runtime_error(name + ": cannot read PNG: " + reason);
    }
    ByteImage out{w, h, 4,
                  std::vector<std::uint8_t>(pixels, pixels + static_cast<size_t>(w) * h * 4)};
    stbi_image_free(pixels);
    return out;
}

void writeExr(const std::filesystem::path& path, int width, int height,
              const std::vector<ExrChannel>& channels, ExrCompression compression) {
    makeOutputFolder(path.parent_path()); // folders are made on demand
    const std::filesystem::path tmp = temporarySibling(path);
    try {
        Imf::Header header(width, height);
        header.compression() =
            compression == ExrCompression::Zip ? Imf::ZIP_COMPRESSION : Imf::NO_COMPRESSION;
        Imf::FrameBuffer fb;
        for (const ExrChannel& c : channels) {
            if (c.values.size() != static_cast<size_t>(width) * static_cast<size_t>(height))
                throw std::invalid_argument("channel " + c.name + " has the wrong size");
            header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
            fb.insert(c.name,
                      Imf::Slice(Imf::FLOAT,
                                 const_cast<char*>(reinterpret_cast<const char*>(c.values.data())),
                                 sizeof(float), sizeof(float) * static_cast<size_t>(width)));
        }
        Imf::OutputFile file(tmp.c_str(), header);
        file.setFrameBuffer(fb);
        file.writePixels(height);
    } catch (const std::exception& e) {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        throw std::runtime_error(path.string() + ": cannot write EXR: " + e.what());
    }
    finishOutputFile(tmp, path);
}

std::vector<ExrChannel> readExr(const std::filesystem::path& path, int& width, int& height) {
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i dw = file.header().dataWindow();
        width = dw.max.x - dw.min.x + 1;
        height = dw.max.y - dw.min.y + 1;
        std::vector<ExrChannel> out;
        for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it)
            out.push_back({it.name(), std::vector<float>(static_cast<size_t>(width) * height)});
        Imf::FrameBuffer fb;
        for (ExrChannel& c : out) {
            char* base = reinterpret_cast<char*>(c.values.data()) -
                         (static_cast<std::ptrdiff_t>(dw.min.y) * width + dw.min.x) *
                             static_cast<std::ptrdiff_t>(sizeof(float));
            fb.insert(c.name, Imf::Slice(Imf::FLOAT, base, sizeof(float),
                                         sizeof(float) * static_cast<size_t>(width)));
        }
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        return out;
    } catch (const std::exception& e) {
        throw std::runtime_error(path.string() + ": cannot read EXR: " + e.what());
    }
}

void requireFinite(const FloatImage& image, const std::string& what) {
    for (size_t i = 0; i < image.data.size(); ++i) {
        if (!std::isfinite(image.data[i])) {
            const size_t px = i / static_cast<size_t>(image.channels);
            throw std::runtime_error(what + ": non-finite value at pixel (" +
                                     std::to_string(px % static_cast<size_t>(image.width)) + ", " +
                                     std::to_string(px / static_cast<size_t>(image.width)) + ")");
        }
    }
}

} // namespace fl
