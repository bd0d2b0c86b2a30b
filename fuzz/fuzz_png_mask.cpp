// libFuzzer target: PNG masks and label images (voronoi --mask/--labels) on any bytes. Each
// input goes to a per-process temporary .png and is read by readPng, as the command reads both
// files; an image that decodes is then used as the mask and as its own label image (same size,
// as the command requires), converted as the command does (io/MaskImage.h), and seeded
// with jfa::seedMask with and without the labels. A bad file must throw std::runtime_error
// (readPng, InputFileError); what decodes must be within kMaxPngSide and seed without error.
#include "FuzzInput.h"

#include <io/ImageIO.h>
#include <io/MaskImage.h>

#include <jfa/Sites.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::filesystem::path file = fl::fuzz::tempFile("png_mask", "png");
    fl::fuzz::writeInput(file, data, size);
    fl::ByteImage img;
    try {
        img = fl::readPng(file, "--mask");
    } catch (const std::runtime_error&) {
        return 0;
    }
    REQUIRE(img.width >= 1 && img.height >= 1 && img.width <= fl::kMaxPngSide &&
            img.height <= fl::kMaxPngSide && img.channels == 4 &&
            img.data.size() == std::size_t(img.width) * std::size_t(img.height) * 4);
    const std::vector<std::uint8_t> mask = fl::maskGrid(img);
    const std::vector<std::int32_t> labels = fl::labelGrid(img);
    // Fewer colours than pixels, and far fewer than kMaxSiteId + 1 in an input of this size:
    // seedMask must accept both.
    const fl::jfa::Grid plain = fl::jfa::seedMask(mask, img.width, img.height);
    const fl::jfa::Grid labelled = fl::jfa::seedMask(mask, img.width, img.height, &labels);
    REQUIRE(plain.width == img.width && labelled.height == img.height);
    return 0;
}
