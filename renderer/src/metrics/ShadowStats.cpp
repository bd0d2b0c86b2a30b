#include <renderer/metrics/ShadowStats.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fl {

double percentile(std::vector<float>& values, double q) {
    if (values.empty()) return 0.0;
    // Nearest rank: the smallest value with at least q of the values at or below it.
    const auto n = values.size();
    auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(n)));
    rank = std::clamp<std::size_t>(rank, 1, n) - 1;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank),
                     values.end());
    return values[rank];
}

ShadowMapStats summarizeShadowDiagnostics(const FloatImage& d) {
    if (d.channels != 4) throw std::invalid_argument("shadow diagnostics need 4 channels");
    ShadowMapStats s;
    std::vector<float> footprint, depth;
    std::size_t flicker = 0, lit = 0;
    for (int y = 0; y < d.height; ++y)
        for (int x = 0; x < d.width; ++x) {
            const float f = d.at(x, y, 0);
            if (!(f > 0.0f)) continue;
            footprint.push_back(f);
            depth.push_back(d.at(x, y, 1));
            const bool now = d.at(x, y, 2) >= 0.5f, before = d.at(x, y, 3) >= 0.5f;
            flicker += now != before;
            lit += now;
        }
    s.receivers = footprint.size();
    if (s.receivers == 0) return s;
    const auto n = static_cast<double>(s.receivers);
    s.flickerShare = static_cast<double>(flicker) / n;
    s.litShare = static_cast<double>(lit) / n;
    std::vector<float> sortedDepth = depth;
    s.nearDepth = percentile(sortedDepth, 0.25);
    std::vector<float> nearFootprint;
    for (std::size_t i = 0; i < footprint.size(); ++i)
        if (depth[i] <= s.nearDepth) nearFootprint.push_back(footprint[i]);
    std::vector<float> all = footprint;
    s.footprint = {percentile(all, 0.5), percentile(footprint, 0.95)};
    std::vector<float> nearCopy = nearFootprint;
    s.footprintNear = {percentile(nearCopy, 0.5), percentile(nearFootprint, 0.95)};
    return s;
}

void writeAliasingMap(const std::filesystem::path& path, const FloatImage& d) {
    if (d.channels != 4) throw std::invalid_argument("shadow diagnostics need 4 channels");
    requireFinite(d, "aliasing map");
    const std::size_t n = static_cast<std::size_t>(d.width) * static_cast<std::size_t>(d.height);
    std::vector<ExrChannel> channels{
        {"footprint", {}}, {"viewDepth", {}}, {"visibility", {}}, {"previousVisibility", {}}};
    for (std::size_t c = 0; c < 4; ++c) {
        channels[c].values.resize(n);
        for (std::size_t i = 0; i < n; ++i) channels[c].values[i] = d.data[i * 4 + c];
    }
    writeExr(path, d.width, d.height, channels);
}

ByteImage footprintHeatMap(const FloatImage& d) {
    ByteImage out{d.width, d.height, 4,
                  std::vector<std::uint8_t>(static_cast<std::size_t>(d.width) * d.height * 4)};
    for (std::size_t i = 0; i < static_cast<std::size_t>(d.width) * d.height; ++i) {
        const float f = d.data[i * 4];
        float r = 0, g = 0, b = 0;
        if (f > 0.0f) {
            // t = 0 at 1/4 pixel per texel, 0.5 at 1, 1 at 16 or more.
            const float l = std::log2(f);
            const float t = l < 0.0f ? std::clamp(0.5f + l / 4.0f, 0.0f, 0.5f)
                                     : std::clamp(0.5f + l / 8.0f, 0.5f, 1.0f);
            if (t < 0.5f) {
                g = t * 2.0f;
                b = 1.0f - g;
            } else {
                r = (t - 0.5f) * 2.0f;
                g = 1.0f - r;
            }
        }
        out.data[i * 4 + 0] = static_cast<std::uint8_t>(std::lround(r * 255.0f));
        out.data[i * 4 + 1] = static_cast<std::uint8_t>(std::lround(g * 255.0f));
        out.data[i * 4 + 2] = static_cast<std::uint8_t>(std::lround(b * 255.0f));
        out.data[i * 4 + 3] = 255;
    }
    return out;
}

ByteImage sideBySide(const std::vector<ByteImage>& images, int gap) {
    if (images.empty()) throw std::invalid_argument("sideBySide: no images");
    const int h = images.front().height;
    int w = 0;
    for (const ByteImage& im : images) {
        if (im.height != h || im.channels != 4)
            throw std::invalid_argument("sideBySide: images must be RGBA and equally tall");
        w += im.width;
    }
    w += gap * static_cast<int>(images.size() - 1);
    ByteImage out{w, h, 4, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 4, 255)};
    int x0 = 0;
    for (const ByteImage& im : images) {
        for (int y = 0; y < h; ++y)
            std::copy_n(&im.data[static_cast<std::size_t>(y) * im.width * 4],
                        static_cast<std::size_t>(im.width) * 4,
                        &out.data[(static_cast<std::size_t>(y) * w + x0) * 4]);
        x0 += im.width + gap;
    }
    return out;
}

ByteImage tileGrid(const std::vector<ByteImage>& tiles, int columns, int gap) {
    if (tiles.empty() || columns < 1) throw std::invalid_argument("tileGrid: no tiles");
    const int w = tiles.front().width, h = tiles.front().height;
    for (const ByteImage& t : tiles)
        if (t.width != w || t.height != h || t.channels != 4)
            throw std::invalid_argument("tileGrid: tiles must be RGBA and of one size");
    const int rows = (static_cast<int>(tiles.size()) + columns - 1) / columns;
    const int W = columns * w + (columns - 1) * gap, H = rows * h + (rows - 1) * gap;
    ByteImage out{W, H, 4, std::vector<std::uint8_t>(static_cast<std::size_t>(W) * H * 4, 255)};
    for (std::size_t t = 0; t < tiles.size(); ++t) {
        const int x0 = static_cast<int>(t) % columns * (w + gap);
        const int y0 = static_cast<int>(t) / columns * (h + gap);
        for (int y = 0; y < h; ++y)
            std::copy_n(&tiles[t].data[static_cast<std::size_t>(y) * w * 4],
                        static_cast<std::size_t>(w) * 4,
                        &out.data[(static_cast<std::size_t>(y0 + y) * W + x0) * 4]);
    }
    return out;
}

} // namespace fl
