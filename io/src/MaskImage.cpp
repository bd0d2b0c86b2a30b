#include <io/MaskImage.h>

#include <map>

namespace fl {

namespace {

std::size_t gridIndex(const ByteImage& p, int x, int y) {
    return static_cast<std::size_t>(p.height - 1 - y) * static_cast<std::size_t>(p.width) +
           static_cast<std::size_t>(x);
}

const std::uint8_t* pixel(const ByteImage& p, int x, int y) {
    return &p.data[(static_cast<std::size_t>(y) * static_cast<std::size_t>(p.width) +
                    static_cast<std::size_t>(x)) *
                   static_cast<std::size_t>(p.channels)];
}

} // namespace

std::vector<std::uint8_t> maskGrid(const ByteImage& picture) {
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(picture.width) *
                                   static_cast<std::size_t>(picture.height));
    for (int y = 0; y < picture.height; ++y)
        for (int x = 0; x < picture.width; ++x)
            mask[gridIndex(picture, x, y)] = pixel(picture, x, y)[0] > 127;
    return mask;
}

std::vector<std::int32_t> labelGrid(const ByteImage& picture) {
    std::map<std::uint32_t, std::int32_t> ids; // colour -> id, in order of appearance
    std::vector<std::int32_t> labels(static_cast<std::size_t>(picture.width) *
                                     static_cast<std::size_t>(picture.height));
    const bool rgb = picture.channels >= 3;
    for (int y = 0; y < picture.height; ++y)
        for (int x = 0; x < picture.width; ++x) {
            const std::uint8_t* p = pixel(picture, x, y);
            const std::uint32_t colour =
                rgb ? std::uint32_t(p[0]) << 16 | std::uint32_t(p[1]) << 8 | p[2] : p[0];
            labels[gridIndex(picture, x, y)] =
                ids.try_emplace(colour, static_cast<std::int32_t>(ids.size())).first->second;
        }
    return labels;
}

} // namespace fl
