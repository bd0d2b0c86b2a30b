#include <renderer/metrics/SoftStats.h>

#include <renderer/metrics/Metrics.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fl {

SoftStats compareSoftShadows(const FloatImage& m, const FloatImage& r) {
    if (m.width != r.width || m.height != r.height || m.channels != 1 || r.channels != 1)
        throw std::invalid_argument(
            "compareSoftShadows: two equally sized 1-channel images needed");
    SoftStats s;
    s.pixels = m.data.size();
    std::array<std::size_t, 4> buckets{};
    std::size_t parity = 0;
    double sum = 0.0;
    for (std::size_t i = 0; i < m.data.size(); ++i) {
        const float a = m.data[i], b = r.data[i];
        const bool pa = isPenumbra(a), pb = isPenumbra(b);
        s.penumbraMethod += pa;
        s.penumbraReference += pb;
        parity += pa != pb;
        const double d = std::abs(static_cast<double>(a) - static_cast<double>(b));
        sum += d;
        s.maxDelta = std::max(s.maxDelta, d);
        if (!pa && !pb) continue;
        ++s.penumbraEither;
        ++buckets[d < 0.05 ? 0 : d < 0.1 ? 1 : d < 0.2 ? 2 : 3];
    }
    if (s.penumbraEither > 0)
        for (std::size_t k = 0; k < 4; ++k)
            s.deltaBuckets[k] =
                static_cast<double>(buckets[k]) / static_cast<double>(s.penumbraEither);
    if (s.pixels > 0) {
        s.parityShare = static_cast<double>(parity) / static_cast<double>(s.pixels);
        s.meanDelta = sum / static_cast<double>(s.pixels);
    }
    return s;
}

ByteImage differencePicture(const FloatImage& m, const FloatImage& r, float gain,
                            const FloatImage& receivers) {
    if (m.data.size() != r.data.size() ||
        (!receivers.data.empty() && receivers.data.size() != m.data.size()))
        throw std::invalid_argument("differencePicture: sizes");
    ByteImage out{m.width, m.height, 4, std::vector<std::uint8_t>(m.data.size() * 4, 255)};
    for (std::size_t i = 0; i < m.data.size(); ++i) {
        const float d = isReceiver(receivers, i)
                            ? std::min(1.0f, std::abs(m.data[i] - r.data[i]) * gain)
                            : 0.0f;
        const auto g = static_cast<std::uint8_t>(std::lround(d * 255.0f));
        out.data[i * 4] = out.data[i * 4 + 1] = out.data[i * 4 + 2] = g;
    }
    return out;
}

ByteImage signedDifferencePicture(const FloatImage& m, const FloatImage& r, float range,
                                  const FloatImage& receivers) {
    if (m.data.size() != r.data.size() ||
        (!receivers.data.empty() && receivers.data.size() != m.data.size()))
        throw std::invalid_argument("signedDifferencePicture: sizes");
    ByteImage out{m.width, m.height, 4, std::vector<std::uint8_t>(m.data.size() * 4, 255)};
    for (std::size_t i = 0; i < m.data.size(); ++i) {
        std::uint8_t* px = &out.data[i * 4];
        if (!isReceiver(receivers, i)) {
            px[0] = px[1] = px[2] = 0;
            continue;
        }
        const float d = m.data[i] - r.data[i];
        const auto keep = static_cast<std::uint8_t>(
            std::lround((1.0f - std::min(1.0f, std::abs(d) / range)) * 255.0f));
        // The other two channels fade: red keeps R, blue keeps B.
        px[0] = d < 0.0f ? keep : 255;
        px[1] = keep;
        px[2] = d > 0.0f ? keep : 255;
    }
    return out;
}

} // namespace fl
