// Capture metrics (renderer/metrics/Metrics.h) on synthetic images with known answers: RMSE,
// penumbra RMSE, misclassification, the 10-90% width of ramps of known width, and added flicker.

#include <renderer/metrics/Metrics.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace fl {
namespace {

FloatImage image(int w, int h, const std::function<float(int, int)>& f) {
    FloatImage img{w, h, 1, std::vector<float>(static_cast<std::size_t>(w) * h)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) img.data[static_cast<std::size_t>(y) * w + x] = f(x, y);
    return img;
}

// A linear ramp from 0 to 1 over `width` pixels along the unit direction (dx, dy), centred on
// the picture's centre; its exact 10-90% width is 0.8 * width.
FloatImage ramp(int size, double width, double dx, double dy) {
    return image(size, size, [=](int x, int y) {
        const double s = ((x + 0.5 - size / 2.0) * dx + (y + 0.5 - size / 2.0) * dy) / width;
        return static_cast<float>(std::clamp(s + 0.5, 0.0, 1.0));
    });
}

FloatImage constant(int w, int h, float v) {
    return image(w, h, [=](int, int) { return v; });
}

TEST(Metrics, Classes) {
    EXPECT_EQ(classifyVisibility(0.0f), ShadowClass::Umbra);
    EXPECT_EQ(classifyVisibility(0.02f), ShadowClass::Umbra);
    EXPECT_EQ(classifyVisibility(0.021f), ShadowClass::Penumbra);
    EXPECT_EQ(classifyVisibility(0.5f), ShadowClass::Penumbra);
    EXPECT_EQ(classifyVisibility(0.979f), ShadowClass::Penumbra);
    EXPECT_EQ(classifyVisibility(0.98f), ShadowClass::Lit);
    EXPECT_EQ(classifyVisibility(1.0f), ShadowClass::Lit);
}

TEST(Metrics, RampWidthsAlongEachAxisAndTheDiagonal) {
    const double diag = 1.0 / std::sqrt(2.0);
    for (double w : {2.0, 3.0, 4.0, 5.5, 8.0, 16.0, 32.0}) {
        EXPECT_NEAR(transitionWidth(ramp(96, w, 1, 0)), 0.8 * w, 1e-4 * w) << "x, width " << w;
        EXPECT_NEAR(transitionWidth(ramp(96, w, 0, 1)), 0.8 * w, 1e-4 * w) << "y, width " << w;
        EXPECT_NEAR(transitionWidth(ramp(96, w, -diag, diag)), 0.8 * w, 1e-3 * w)
            << "diagonal, width " << w;
    }
}

TEST(Metrics, StepEdgeAndFlatImagesHaveNoWidth) {
    EXPECT_EQ(transitionWidth(image(32, 32, [](int x, int) { return x < 16 ? 0.0f : 1.0f; })), 0.0);
    EXPECT_EQ(transitionWidth(constant(16, 16, 1.0f)), 0.0);
    // A half-lit plateau has no transition either (its gradient is zero).
    EXPECT_EQ(transitionWidth(constant(16, 16, 0.5f)), 0.0);
}

TEST(Metrics, WidthIsRobustToNoiseAndToAHardEdgeElsewhere) {
    // A 16-pixel ramp in the left half, a hard edge in the right half, and +-0.01 noise: the
    // median still finds 0.8 * 16 within 10%.
    const FloatImage clean = ramp(128, 16.0, 1, 0);
    FloatImage noisy = image(128, 128, [&](int x, int y) {
        const float n = 0.01f * static_cast<float>(((x * 7 + y * 13) % 5) - 2) / 2.0f;
        const float v = y < 64 ? clean.at(x, y, 0) : (x < 64 ? 0.0f : 1.0f);
        return std::clamp(v + n, 0.0f, 1.0f);
    });
    EXPECT_NEAR(transitionWidth(noisy), 12.8, 1.28);
}

TEST(Metrics, StepAgainstRampWidthErrorAndRmse) {
    // Method: a hard edge at the centre; reference: an 8-pixel ramp around it.
    const int n = 64;
    const FloatImage ref = ramp(n, 8.0, 1, 0);
    const FloatImage step = image(n, n, [=](int x, int) { return x < n / 2 ? 0.0f : 1.0f; });
    const FrameMetrics f = compareWithReference(step, ref);
    EXPECT_NEAR(f.widthReference, 6.4, 1e-4);
    EXPECT_EQ(f.widthMethod, 0.0);
    EXPECT_NEAR(f.widthError, -6.4, 1e-4);
    // Per row the ramp's values are (k + 0.5) / 8, k = 0..7; the step differs by those below
    // 0.5 on the left and 1 - value on the right: |d| = 1/16, 3/16, 5/16, 7/16 twice each.
    const double rowSq = 2.0 * (1.0 + 9.0 + 25.0 + 49.0) / 256.0;
    EXPECT_NEAR(f.rmse, std::sqrt(rowSq / n), 1e-6);
    // Penumbra pixels of the reference: all 8 ramp pixels of each row (0.0625 .. 0.9375).
    EXPECT_EQ(f.penumbraPixels, static_cast<std::size_t>(8 * n));
    EXPECT_NEAR(f.rmsePenumbra, std::sqrt(rowSq / 8.0), 1e-6);
    // The step has no penumbra: all 8 ramp pixels per row are misclassified.
    EXPECT_NEAR(f.misclassified, 8.0 / n, 1e-12);
}

TEST(Metrics, KnownRmseAndMisclassification) {
    // 4 pixels: reference umbra, penumbra, penumbra, lit; the method is 0.1 brighter, which
    // moves pixel 0 (0 -> 0.1) into penumbra and pixel 2 (0.9 -> 1.0) to lit.
    const FloatImage ref{4, 1, 1, {0.0f, 0.5f, 0.9f, 0.9f + 0.09f}};
    const FloatImage m{4, 1, 1, {0.1f, 0.6f, 1.0f, 1.0f + 0.08f}};
    const FrameMetrics f = compareWithReference(m, ref);
    EXPECT_NEAR(f.rmse, std::sqrt((0.01 + 0.01 + 0.01 + 0.0081) / 4.0), 1e-6);
    EXPECT_EQ(f.penumbraPixels, 2u); // 0.5 and 0.9; 0.99 is lit
    EXPECT_NEAR(f.rmsePenumbra, 0.1, 1e-6);
    EXPECT_DOUBLE_EQ(f.misclassified, 0.5);
}

TEST(Metrics, IdenticalImagesHaveNoError) {
    const FloatImage a = ramp(32, 6.0, 0, 1);
    const FrameMetrics f = compareWithReference(a, a);
    EXPECT_EQ(f.rmse, 0.0);
    EXPECT_EQ(f.rmsePenumbra, 0.0);
    EXPECT_EQ(f.misclassified, 0.0);
    EXPECT_EQ(f.widthError, 0.0);
    EXPECT_GT(f.penumbraPixels, 0u);
}

TEST(Metrics, AddedFlicker) {
    // The reference is static; the method toggles one pixel of four: it adds 0.25 of flicker.
    const FloatImage still = constant(2, 2, 0.5f);
    const FloatImage a{2, 2, 1, {0.0f, 0.5f, 0.5f, 0.5f}};
    const FloatImage b{2, 2, 1, {1.0f, 0.5f, 0.5f, 0.5f}};
    EXPECT_DOUBLE_EQ(meanAbsoluteChange(a, b), 0.25);
    EXPECT_DOUBLE_EQ(addedFlicker(a, b, still, still), 0.25);
    // Moving exactly as the reference does adds nothing; changing less is negative.
    EXPECT_DOUBLE_EQ(addedFlicker(a, b, a, b), 0.0);
    EXPECT_DOUBLE_EQ(addedFlicker(still, still, a, b), -0.25);
}

// A motion image that says each pixel's point was `shift` pixels to the left in the previous
// frame, at depth `depth` (and at depth `depth` now).
FloatImage shiftedMotion(int w, int h, float shift, float depth) {
    FloatImage m{w, h, 4, {}};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            m.data.insert(m.data.end(), {static_cast<float>(x) + 0.5f - shift,
                                         static_cast<float>(y) + 0.5f, depth, depth});
    return m;
}

TEST(Metrics, SurfaceFlickerFollowsThePointNotThePixel) {
    // A shadow edge that moved one pixel right on screen because the camera moved, not because
    // the shadow moved on the surface: the screen-space change is large, the same-point one 0.
    const int w = 8, h = 4;
    const FloatImage before = image(w, h, [](int x, int) { return x < 4 ? 0.0f : 1.0f; });
    const FloatImage after = image(w, h, [](int x, int) { return x < 5 ? 0.0f : 1.0f; });
    const FloatImage motion = shiftedMotion(w, h, 1.0f, 5.0f);
    const Reprojection r(motion, depthOf(motion), {}, {});
    EXPECT_EQ(r.pixels(), static_cast<std::size_t>((w - 1) * h)) << "column 0 came from outside";
    EXPECT_DOUBLE_EQ(r.meanAbsoluteChange(before, after), 0.0);
    EXPECT_GT(meanAbsoluteChange(before, after), 0.1);
    // A half-pixel shift samples the previous image between two pixels: at the edge the point
    // held something between 0 and 1, so the edge's value now (either) is no change.
    const Reprojection half(shiftedMotion(w, h, 0.5f, 5.0f), depthOf(motion), {}, {});
    EXPECT_DOUBLE_EQ(half.meanAbsoluteChange(before, before), 0.0);
    // A change beyond that range counts: here the edge moved 2 pixels on screen where the
    // surface moved half a pixel, so the surface's edge moved 1.5 pixels; one pixel per row
    // lies beyond what its previous texels held.
    const FloatImage moved = image(w, h, [](int x, int) { return x < 6 ? 0.0f : 1.0f; });
    EXPECT_DOUBLE_EQ(half.meanAbsoluteChange(before, moved),
                     h * 1.0 / static_cast<double>(half.pixels()));
    // The method flickers on one pixel the reference does not.
    FloatImage method = after;
    method.data[6] = 0.0f;
    EXPECT_DOUBLE_EQ(addedSurfaceFlicker(r, before, method, before, after),
                     1.0 / static_cast<double>(r.pixels()));
}

TEST(Metrics, SurfaceFlickerSkipsPointsHiddenOrUncovered) {
    const int w = 4, h = 2;
    const FloatImage motion = shiftedMotion(w, h, 0.0f, 5.0f);
    // Another depth there before (something stood in front, or behind): not the same point.
    FloatImage previousDepth = depthOf(motion);
    previousDepth.data[1] = 4.0f;
    const Reprojection occluded(motion, previousDepth, {}, {});
    EXPECT_EQ(occluded.pixels(), 7u);
    // Within 1% of the depth: the same point.
    previousDepth.data[1] = 5.04f;
    EXPECT_EQ(Reprojection(motion, previousDepth, {}, {}).pixels(), 8u);
    // Not a receiver now, or not then.
    const FloatImage mask{w, h, 1, {1, 1, 1, 1, 1, 1, 0, 1}};
    EXPECT_EQ(Reprojection(motion, depthOf(motion), mask, {}).pixels(), 7u);
    EXPECT_EQ(Reprojection(motion, depthOf(motion), {}, mask).pixels(), 7u);
    EXPECT_THROW(Reprojection(motion, motion, {}, {}), std::invalid_argument);
    EXPECT_THROW(Reprojection(constant(w, h, 1.0f), depthOf(motion), {}, {}),
                 std::invalid_argument);
}

TEST(Metrics, MismatchedSizesThrow) {
    EXPECT_THROW((void)compareWithReference(constant(2, 2, 0.0f), constant(3, 2, 0.0f)),
                 std::invalid_argument);
    EXPECT_THROW((void)meanAbsoluteChange(constant(2, 2, 0.0f), constant(2, 1, 0.0f)),
                 std::invalid_argument);
}

// Pixels outside the receiver mask (back faces, sky) do not count: a method that differs from
// the reference only there has no error, and the pixel counts are the mask's.
TEST(Metrics, OnlyReceiversCount) {
    const FloatImage ref = image(8, 4, [](int x, int) { return x < 4 ? 0.0f : 0.5f; });
    const FloatImage method = image(8, 4, [](int x, int) { return x < 4 ? 1.0f : 0.5f; });
    const FloatImage mask = image(8, 4, [](int x, int) { return x < 4 ? 0.0f : 1.0f; });
    const FrameMetrics masked = compareWithReference(method, ref, mask);
    EXPECT_EQ(masked.pixels, 16u);
    EXPECT_EQ(masked.penumbraPixels, 16u);
    EXPECT_EQ(masked.rmse, 0.0);
    EXPECT_EQ(masked.misclassified, 0.0);
    const FrameMetrics all = compareWithReference(method, ref);
    EXPECT_EQ(all.pixels, 32u);
    EXPECT_NEAR(all.rmse, std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(all.misclassified, 0.5, 1e-12);
    EXPECT_THROW((void)compareWithReference(method, ref, constant(4, 4, 1.0f)),
                 std::invalid_argument);
}

// A ramp next to non-receivers keeps its width: the estimator does not take a slope from a
// neighbour that is not a receiver (here the left half is a back face at 0).
TEST(Metrics, WidthIgnoresNeighboursOutsideTheReceivers) {
    const int n = 64;
    const double width = 8.0;
    FloatImage v = ramp(n, width, 1, 0);
    FloatImage mask = constant(n, n, 1.0f);
    // Cut the ramp past its middle: left of column 33 the surface turns away and reads 0, so
    // each row keeps two ramp pixels in [0.1, 0.9] (v = 0.69, 0.81).
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < 33; ++x) {
            v.data[static_cast<std::size_t>(y) * n + x] = 0.0f;
            mask.data[static_cast<std::size_t>(y) * n + x] = 0.0f;
        }
    EXPECT_NEAR(transitionWidth(v, mask), 0.8 * width, 1e-4);
    // Without the mask the step from 0 to the ramp's middle is taken for a steep slope.
    EXPECT_LT(transitionWidth(v), 0.8 * width - 1.0);
}

TEST(Metrics, FlickerCountsReceiversInBothFrames) {
    const FloatImage a = constant(4, 1, 0.0f);
    const FloatImage b = image(4, 1, [](int x, int) { return x == 0 ? 1.0f : 0.0f; });
    const FloatImage maskA = image(4, 1, [](int x, int) { return x < 2 ? 1.0f : 0.0f; });
    const FloatImage maskB = image(4, 1, [](int x, int) { return x == 0 || x == 3 ? 1.0f : 0.0f; });
    const FloatImage both = bothReceivers(maskA, maskB);
    EXPECT_EQ(both.data, (std::vector<float>{1.0f, 0.0f, 0.0f, 0.0f}));
    EXPECT_EQ(meanAbsoluteChange(a, b, both), 1.0);
    EXPECT_EQ(meanAbsoluteChange(a, b), 0.25);
    EXPECT_EQ(meanAbsoluteChange(a, b, constant(4, 1, 0.0f)), 0.0) << "no receiver: no change";
    EXPECT_EQ(addedFlicker(a, b, a, a, both), 1.0);
    EXPECT_EQ(bothReceivers({}, maskB).data, maskB.data);
}

TEST(Metrics, LeakCountsTheTruthsUmbraLitAndDarkItsLitDarkened) {
    // truth:  umbra 0.0 (x4), 0.05, lit 1.0 (x3), 0.95, penumbra 0.5
    const FloatImage truth = image(10, 1, [](int x, int) {
        return x < 4 ? 0.0f : x == 4 ? 0.05f : x < 8 ? 1.0f : x == 8 ? 0.95f : 0.5f;
    });
    // method: two umbra pixels lit by more than 0.3 (0.31 and 0.36; 0.3 itself is not), one
    // lit pixel darkened by more than 0.3; the penumbra pixel counts in neither.
    const std::vector<float> m = {0.31f, 0.3f, 0.0f, 0.0f, 0.36f, 0.6f, 1.0f, 1.0f, 0.95f, 0.0f};
    const FloatImage method{10, 1, 1, m};
    const ShadowLeaks l = shadowLeaks(method, truth);
    EXPECT_EQ(l.umbra, 5u);
    EXPECT_EQ(l.lit, 4u);
    EXPECT_DOUBLE_EQ(l.leak, 2.0 / 5.0);
    EXPECT_DOUBLE_EQ(l.dark, 1.0 / 4.0);
    // Only receivers count: without pixels 0 and 5 one leak and no dark pixel remain.
    const FloatImage mask = image(10, 1, [](int x, int) { return x == 0 || x == 5 ? 0.0f : 1.0f; });
    const ShadowLeaks r = shadowLeaks(method, truth, mask);
    EXPECT_DOUBLE_EQ(r.leak, 1.0 / 4.0);
    EXPECT_DOUBLE_EQ(r.dark, 0.0);
    EXPECT_EQ(shadowLeaks(truth, truth).leak, 0.0);
    EXPECT_THROW((void)shadowLeaks(constant(2, 1, 0.0f), truth), std::invalid_argument);
}

} // namespace
} // namespace fl
