#pragma once
// Error metrics of a soft-shadow visibility image against the ground-truth `reference` method
// (capture runs, `floodlight capture`). Pure CPU functions on 1-channel visibility images
// (1 = lit, 0 = umbra).
//
// Definitions (stated once here, used by the CSV, the JSON summary and the report):
// - Receivers: the pixels the metrics count, given as a mask (1-channel, > 0.5 counts): the
//   visible surfaces that face the light (Renderer::receivers()). Elsewhere the visibility does
//   not change the image (shading multiplies it by N.L <= 0, or there is no surface), and the
//   methods legitimately disagree there (a depth test vs 256 differently biased maps on a back
//   face). An empty mask counts every pixel.
// - Classes: umbra v <= 0.02, lit v >= 0.98, penumbra in between. The 2% margins keep the
//   reference's Monte-Carlo noise and float rounding from turning lit or umbra pixels into
//   "penumbra".
// - Penumbra pixels: receivers the reference classifies as penumbra.
// - 10-90% transition width: for a visibility ramp rising from 0 to 1 over W pixels, the
//   distance between the 10% and 90% levels is 0.8 W = 0.8 / |grad V|. It is estimated at every
//   receiver with 0.1 <= v <= 0.9 as 0.8 / |grad V|, where each axis' derivative is the central
//   difference, or, when a neighbour is umbra or lit (or not a receiver), the larger one-sided
//   difference (exact on a linear ramp, also at its ends), and the image's width is the median
//   of these (robust to depth edges, plateaus and noise). An image with no such pixel (a hard
//   edge, or no shadow) has width 0.

#include <io/ImageIO.h>

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
    std::size_t pixels = 0;          // receivers counted
    std::size_t penumbraPixels = 0;  // receivers the reference calls penumbra
    double sumSquared = 0.0;         // sum of (m - r)^2 over the receivers (for pooled RMSE)
    double sumSquaredPenumbra = 0.0; // ... over penumbra pixels
    double rmse = 0.0;               // over the receivers
    double rmsePenumbra = 0.0;       // over penumbra pixels; 0 when there are none
    double misclassified = 0.0;      // share of pixels whose class differs (0..1)
    double widthMethod = 0.0;        // 10-90% transition width, pixels
    double widthReference = 0.0;
    double widthError = 0.0; // widthMethod - widthReference, pixels
};

/// Compares two equally sized 1-channel images over the receivers (an empty mask: all pixels);
/// throws std::invalid_argument if the sizes differ.
[[nodiscard]] FrameMetrics compareWithReference(const FloatImage& method,
                                                const FloatImage& reference,
                                                const FloatImage& receivers = {});

/// Light through solid shadows and dark on lit surfaces: receivers the ground truth
/// puts in its umbra (v <= kLeakUmbraAtMost) that a method lights by more than kLeakBy, and
/// receivers it lights fully (v >= kLeakLitAtLeast) that a method darkens by more than kLeakBy.
/// Wider margins than the classes above: a leak is a gross error, not noise at a class edge.
inline constexpr float kLeakUmbraAtMost = 0.05f;
inline constexpr float kLeakLitAtLeast = 0.95f;
inline constexpr float kLeakBy = 0.3f;

struct ShadowLeaks {
    std::size_t umbra = 0; // receivers in the reference's umbra
    std::size_t lit = 0;   // receivers the reference lights fully
    double leak = 0.0;     // share of `umbra` with method - reference > kLeakBy (0 if none)
    double dark = 0.0;     // share of `lit` with reference - method > kLeakBy (0 if none)
};

/// Leak and dark of `method` against `reference` over the receivers (an empty mask: all
/// pixels); throws std::invalid_argument if the sizes differ.
[[nodiscard]] ShadowLeaks shadowLeaks(const FloatImage& method, const FloatImage& reference,
                                      const FloatImage& receivers = {});

/// The 10-90% transition width of a visibility image in pixels over the receivers (estimator
/// above; an empty mask: all pixels).
[[nodiscard]] double transitionWidth(const FloatImage& visibility,
                                     const FloatImage& receivers = {});

/// Mean |current - previous| over the receivers (an empty mask: all pixels; equal sizes, else
/// std::invalid_argument). 0 when no pixel counts.
[[nodiscard]] double meanAbsoluteChange(const FloatImage& previous, const FloatImage& current,
                                        const FloatImage& receivers = {});

/// Added flicker between two consecutive frames over the receivers: the method's mean |change|
/// minus the reference's own (negative when the method changes less than the ground truth does).
[[nodiscard]] double addedFlicker(const FloatImage& methodPrevious, const FloatImage& method,
                                  const FloatImage& referencePrevious, const FloatImage& reference,
                                  const FloatImage& receivers = {});

/// Where each pixel's surface point lay in the previous frame, from the surfaces pass's motion
/// target (SurfacesPass.h; read back with row 0 at the top: channels x, y = the point's pixel
/// position in the previous frame, z = its depth (clip w) there, w = its depth in this frame).
/// A pixel takes part when it is a receiver now and the point was seen then: its previous
/// position lies inside the frame, and the four pixels around it were receivers whose depth
/// matches the point's (within 1%; else it was hidden, or is newly uncovered).
class Reprojection {
  public:
    /// `previousDepth` is the previous frame's depth (depthOf its motion image). Throws
    /// std::invalid_argument for images of different sizes or a motion image without 4
    /// channels.
    Reprojection(const FloatImage& motion, const FloatImage& previousDepth,
                 const FloatImage& receivers, const FloatImage& previousReceivers);
    /// Mean |current(p) - previous(reproject(p))| over the pixels that take part, where the
    /// previous value is the range the previous image holds at the texels around the point (a
    /// change within it is resampling, not flicker); 0 when no pixel takes part.
    [[nodiscard]] double meanAbsoluteChange(const FloatImage& previous,
                                            const FloatImage& current) const;
    /// How many pixels take part.
    [[nodiscard]] std::size_t pixels() const { return taps_.size(); }

  private:
    struct Tap {
        std::size_t pixel;
        std::size_t texel[4];
        float weight[4];
    };
    int width_ = 0, height_ = 0;
    std::vector<Tap> taps_;
};

/// The motion image's w channel: each pixel's depth (clip w) in its own frame, what the next
/// frame's Reprojection matches against.
[[nodiscard]] FloatImage depthOf(const FloatImage& motion);

/// Added flicker on the same surface point: the method's mean |V_t(p) - V_t-1(reproject(p))|
/// minus the reference's, over the pixels `r` pairs. Camera motion alone moves a still shadow
/// across the screen, not across the surface, so it adds nothing here.
[[nodiscard]] double addedSurfaceFlicker(const Reprojection& r, const FloatImage& methodPrevious,
                                         const FloatImage& method,
                                         const FloatImage& referencePrevious,
                                         const FloatImage& reference);

/// Whether pixel i counts under a receiver mask (> 0.5; an empty mask counts every pixel).
[[nodiscard]] inline bool isReceiver(const FloatImage& receivers, std::size_t i) {
    return receivers.data.empty() || receivers.data[i] > 0.5f;
}

/// The pixels that are receivers in both masks (for a change between two frames); an empty
/// mask stands for all pixels.
[[nodiscard]] FloatImage bothReceivers(const FloatImage& a, const FloatImage& b);

} // namespace fl
