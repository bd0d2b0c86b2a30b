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

ShadowLeaks shadowLeaks(const FloatImage& m, const FloatImage& r, const FloatImage& mask) {
    requireSameShape(m, r, "shadowLeaks");
    requireMaskFor(m, mask, "shadowLeaks");
    ShadowLeaks out;
    std::size_t leaks = 0, darks = 0;
    for (std::size_t i = 0; i < m.data.size(); ++i) {
        if (!isReceiver(mask, i)) continue;
        const float d = m.data[i] - r.data[i];
        if (r.data[i] <= kLeakUmbraAtMost) {
            ++out.umbra;
            leaks += d > kLeakBy;
        }
        if (r.data[i] >= kLeakLitAtLeast) {
            ++out.lit;
            darks += -d > kLeakBy;
        }
    }
    if (out.umbra) out.leak = static_cast<double>(leaks) / static_cast<double>(out.umbra);
    if (out.lit) out.dark = static_cast<double>(darks) / static_cast<double>(out.lit);
    return out;
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

namespace {

/// The bilinear footprint along one axis of a continuous pixel position p (texel centres at
/// half-integers) in n texels: the lower texel and the upper one's weight; false outside.
bool footprint(float p, int n, std::size_t& lower, float& weight) {
    const float f = p - 0.5f;
    if (!(f >= 0.0f && f <= static_cast<float>(n - 1))) return false;
    lower = n > 1 ? std::min(static_cast<std::size_t>(f), static_cast<std::size_t>(n - 2)) : 0;
    weight = n > 1 ? f - static_cast<float>(lower) : 0.0f;
    return true;
}

} // namespace

Reprojection::Reprojection(const FloatImage& motion, const FloatImage& previousDepth,
                           const FloatImage& receivers, const FloatImage& previousReceivers)
    : width_(motion.width), height_(motion.height) {
    const auto fits = [&](const FloatImage& im, int channels) {
        return im.width == width_ && im.height == height_ && im.channels == channels &&
               im.data.size() == static_cast<std::size_t>(width_) *
                                     static_cast<std::size_t>(height_) *
                                     static_cast<std::size_t>(channels);
    };
    if (!fits(motion, 4) || !fits(previousDepth, 1) ||
        (!receivers.data.empty() && !fits(receivers, 1)) ||
        (!previousReceivers.data.empty() && !fits(previousReceivers, 1)))
        throw std::invalid_argument("Reprojection: a 4-channel motion image and 1-channel depth "
                                    "and receiver masks of one size needed");
    const auto w = static_cast<std::size_t>(width_);
    for (std::size_t i = 0; i < motion.data.size() / 4; ++i) {
        if (!isReceiver(receivers, i)) continue;
        const float* m = &motion.data[4 * i];
        std::size_t x0 = 0, y0 = 0;
        float ax = 0.0f, ay = 0.0f;
        if (!footprint(m[0], width_, x0, ax) || !footprint(m[1], height_, y0, ay)) continue;
        const std::size_t x1 = width_ > 1 ? x0 + 1 : x0, y1 = height_ > 1 ? y0 + 1 : y0;
        Tap t{i,
              {y0 * w + x0, y0 * w + x1, y1 * w + x0, y1 * w + x1},
              {(1 - ax) * (1 - ay), ax * (1 - ay), (1 - ax) * ay, ax * ay}};
        // Texels that weigh nothing (the point sits on a texel row or column) need not match.
        bool seen = true;
        for (int k = 0; k < 4; ++k) {
            const std::size_t q = t.texel[k];
            seen = seen && (t.weight[k] == 0.0f ||
                            (isReceiver(previousReceivers, q) &&
                             std::abs(previousDepth.data[q] - m[2]) <= 0.01f * m[2]));
        }
        if (seen) taps_.push_back(t);
    }
}

double Reprojection::meanAbsoluteChange(const FloatImage& previous,
                                        const FloatImage& current) const {
    requireSameShape(previous, current, "Reprojection::meanAbsoluteChange");
    if (current.width != width_ || current.height != height_ || current.channels != 1)
        throw std::invalid_argument("Reprojection::meanAbsoluteChange: a 1-channel image of the "
                                    "motion image's size");
    // The point lies between the previous frame's pixel centres, so its previous value is only
    // known to lie within what the texels around it held: a sharp edge resampled at a new
    // sub-pixel offset reads anything from one side's value to the other's. Only a change
    // beyond that range is the surface's own (a bilinear estimate would count every resampled
    // hard edge as flicker: 0.009 for hard shadows under a slow dolly whose shadows never move).
    double sum = 0.0;
    for (const Tap& t : taps_) {
        double lo = 1e30, hi = -1e30;
        for (int k = 0; k < 4; ++k) {
            if (t.weight[k] == 0.0f) continue;
            lo = std::min<double>(lo, previous.data[t.texel[k]]);
            hi = std::max<double>(hi, previous.data[t.texel[k]]);
        }
        const double v = current.data[t.pixel];
        sum += std::max({0.0, v - hi, lo - v});
    }
    return taps_.empty() ? 0.0 : sum / static_cast<double>(taps_.size());
}

FloatImage depthOf(const FloatImage& motion) {
    if (motion.channels != 4) throw std::invalid_argument("depthOf: a 4-channel motion image");
    FloatImage d{motion.width, motion.height, 1, std::vector<float>(motion.data.size() / 4)};
    for (std::size_t i = 0; i < d.data.size(); ++i) d.data[i] = motion.data[4 * i + 3];
    return d;
}

double addedSurfaceFlicker(const Reprojection& r, const FloatImage& methodPrevious,
                           const FloatImage& method, const FloatImage& referencePrevious,
                           const FloatImage& reference) {
    return r.meanAbsoluteChange(methodPrevious, method) -
           r.meanAbsoluteChange(referencePrevious, reference);
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
