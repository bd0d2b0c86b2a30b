#pragma once
// Error metrics of a soft-shadow visibility image against the ground-truth `reference` method
// (capture runs, `floodlight capture`). Pure CPU functions on 1-channel visibility images
// (1 = lit, 0 = umbra).
//
// Definitions (stated once here, used by the CSV, the JSON summary and the report):
// - Classes: umbra v <= 0.02, lit v >= 0.98, penumbra in between. The 2% margins keep the
//   reference's Monte-Carlo noise and float rounding from turning lit or umbra pixels into
//   "penumbra".
// - Penumbra pixels: pixels the reference classifies as penumbra.
// - 10-90% transition width: for a visibility ramp rising from 0 to 1 over W pixels, the
//   distance between the 10% and 90% levels is 0.8 W = 0.8 / |grad V|. It is estimated at every
//   pixel with 0.1 <= v <= 0.9 as 0.8 / |grad V|, where each axis' derivative is the central
//   difference, or, when a neighbour is umbra or lit, the larger one-sided difference (exact on
//   a linear ramp, also at its ends), and the image's width is the median of these (robust to
//   depth edges, plateaus and noise). An image with no such pixel (a hard edge, or no shadow) has
//   width 0.

#include <renderer/ImageIO.h>

#include <cstddef>
#include <cstdint>

namespace fl {

inline constexpr float kUmbraAtMost = 0.02f; // v <= this: umbra
inline constexpr float kLitAtLeast = 0.98f;  // v >= this: lit

enum class ShadowClass : std::uint8_t { Umbra, Penumbra, Lit };

/// The class of one visibility value (thresholds above).
[[nodiscard]] ShadowClass classifyVisibility(float v);

/// One frame of a method against the reference.
struct FrameMetrics {
    std::size_t pixels = 0;
    std::size_t penumbraPixels = 0;  // reference penumbra pixels
    double sumSquared = 0.0;         // sum of (m - r)^2 over all pixels (for pooled RMSE)
    double sumSquaredPenumbra = 0.0; // ... over penumbra pixels
    double rmse = 0.0;               // over all pixels
    double rmsePenumbra = 0.0;       // over penumbra pixels; 0 when there are none
    double misclassified = 0.0;      // share of pixels whose class differs (0..1)
    double widthMethod = 0.0;        // 10-90% transition width, pixels
    double widthReference = 0.0;
    double widthError = 0.0; // widthMethod - widthReference, pixels
};

/// Compares two equally sized 1-channel images; throws std::invalid_argument otherwise.
[[nodiscard]] FrameMetrics compareWithReference(const FloatImage& method,
                                                const FloatImage& reference);

/// The 10-90% transition width of a visibility image in pixels (estimator above).
[[nodiscard]] double transitionWidth(const FloatImage& visibility);

/// Mean |current - previous| over all pixels (equal sizes, else std::invalid_argument).
[[nodiscard]] double meanAbsoluteChange(const FloatImage& previous, const FloatImage& current);

/// Added flicker between two consecutive frames: the method's mean |change| minus the
/// reference's own (negative when the method changes less than the ground truth does).
[[nodiscard]] double addedFlicker(const FloatImage& methodPrevious, const FloatImage& method,
                                  const FloatImage& referencePrevious, const FloatImage& reference);

} // namespace fl
