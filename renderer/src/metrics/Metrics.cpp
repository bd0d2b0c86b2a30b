#include <renderer/metrics/Metrics.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace fl {

namespace {

void requireSameShape(const FloatImage& a, const FloatImage& b, const char* who) {
    if (a.width != b.width || a.height != b.height || a.channels != 1 || b.channels != 1 ||
        a.data.size() != b.data.size())
        throw std::invalid_argument(std::string(who) +
                                    ": two equally sized 1-channel images needed");
}

// An empty mask counts every pixel; otherwise it must match the image.
void requireMaskFor(const FloatImage& image, const FloatImage& mask, const char* who) {
    if (!mask.data.empty()) requireSameShape(image, mask, who);
}

// Central differences average out noise; where a neighbour is already saturated (umbra or lit,
// e.g. the first and last pixel of a linear ramp) the difference towards the other neighbour is
// the one that sees the slope, so the larger one-sided difference is used there.
float axisDerivative(float left, float centre, float right, bool hasLeft, bool hasRight) {
    auto inside = [](float v) { return v > kUmbraAtMost && v < kLitAtLeast; };
    if (hasLeft && hasRight && inside(left) && inside(right)) return std::abs(right - left) * 0.5f;
    const float back = hasLeft ? centre - left : 0.0f;
    const float fwd = hasRight ? right - centre : 0.0f;
    return std::max(std::abs(back), std::abs(fwd));
}

} // namespace

ShadowClass classifyVisibility(float v) {
    if (v <= kUmbraAtMost) return ShadowClass::Umbra;
    if (v >= kLitAtLeast) return ShadowClass::Lit;
    return ShadowClass::Penumbra;
}

double transitionWidth(const FloatImage& img, const FloatImage& mask) {
    if (img.channels != 1) throw std::invalid_argument("transitionWidth: 1-channel image needed");
    requireMaskFor(img, mask, "transitionWidth");
    const int w = img.width, h = img.height;
    // A neighbour counts only if it is a receiver too: a back face or the sky beside a penumbra
    // says nothing about the penumbra's slope.
    auto has = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < w && y < h &&
               isReceiver(mask, static_cast<std::size_t>(y) * w + x);
    };
    std::vector<double> widths;
    // A pixel whose gradient is below this is on a plateau, not on a transition; counting it
    // would report the image size as a width.
    constexpr float kFlat = 1e-4f;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!has(x, y)) continue;
            const float v = img.at(x, y, 0);
            if (v < 0.1f || v > 0.9f) continue;
            const bool l = has(x - 1, y), r = has(x + 1, y), u = has(x, y - 1), d = has(x, y + 1);
            const float gx =
                axisDerivative(l ? img.at(x - 1, y, 0) : v, v, r ? img.at(x + 1, y, 0) : v, l, r);
            const float gy =
                axisDerivative(u ? img.at(x, y - 1, 0) : v, v, d ? img.at(x, y + 1, 0) : v, u, d);
            const float g = std::sqrt(gx * gx + gy * gy);
            if (g < kFlat) continue;
            widths.push_back(0.8 / static_cast<double>(g));
        }
    if (widths.empty()) return 0.0;
    // Median (lower middle for an even count, so the result is one of the estimates).
    const auto mid = widths.begin() + static_cast<std::ptrdiff_t>((widths.size() - 1) / 2);
    std::nth_element(widths.begin(), mid, widths.end());
    return *mid;
}

FrameMetrics compareWithReference(const FloatImage& m, const FloatImage& r,
                                  const FloatImage& mask) {
    requireSameShape(m, r, "compareWithReference");
    requireMaskFor(m, mask, "compareWithReference");
    FrameMetrics f;
    std::size_t wrongClass = 0;
    for (std::size_t i = 0; i < m.data.size(); ++i) {
        if (!isReceiver(mask, i)) continue;
        ++f.pixels;
        const double d = static_cast<double>(m.data[i]) - static_cast<double>(r.data[i]);
        f.sumSquared += d * d;
        const ShadowClass cr = classifyVisibility(r.data[i]);
        if (cr == ShadowClass::Penumbra) {
            ++f.penumbraPixels;
            f.sumSquaredPenumbra += d * d;
        }
        wrongClass += classifyVisibility(m.data[i]) != cr;
    }
    if (f.pixels > 0) {
        f.rmse = std::sqrt(f.sumSquared / static_cast<double>(f.pixels));
        f.misclassified = static_cast<double>(wrongClass) / static_cast<double>(f.pixels);
    }
    if (f.penumbraPixels > 0)
        f.rmsePenumbra = std::sqrt(f.sumSquaredPenumbra / static_cast<double>(f.penumbraPixels));
    f.widthMethod = transitionWidth(m, mask);
    f.widthReference = transitionWidth(r, mask);
    f.widthError = f.widthMethod - f.widthReference;
    return f;
}

double meanAbsoluteChange(const FloatImage& previous, const FloatImage& current,
                          const FloatImage& mask) {
    requireSameShape(previous, current, "meanAbsoluteChange");
    requireMaskFor(current, mask, "meanAbsoluteChange");
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < current.data.size(); ++i) {
        if (!isReceiver(mask, i)) continue;
        sum += std::abs(static_cast<double>(current.data[i]) - previous.data[i]);
        ++n;
    }
    return n > 0 ? sum / static_cast<double>(n) : 0.0;
}

double addedFlicker(const FloatImage& methodPrevious, const FloatImage& method,
                    const FloatImage& referencePrevious, const FloatImage& reference,
                    const FloatImage& mask) {
    return meanAbsoluteChange(methodPrevious, method, mask) -
           meanAbsoluteChange(referencePrevious, reference, mask);
}

FloatImage bothReceivers(const FloatImage& a, const FloatImage& b) {
    if (a.data.empty()) return b;
    if (b.data.empty()) return a;
    requireSameShape(a, b, "bothReceivers");
    FloatImage out{a.width, a.height, 1, std::vector<float>(a.data.size())};
    for (std::size_t i = 0; i < a.data.size(); ++i)
        out.data[i] = isReceiver(a, i) && isReceiver(b, i) ? 1.0f : 0.0f;
    return out;
}

} // namespace fl
