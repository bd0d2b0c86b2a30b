#pragma once
// Per-frame statistics of a soft-shadow method against its standard-flooding reference (thesis
// Fig. 5.4 and 5.8): penumbra pixels, the share of them in each |dI| bucket, and the share of
// pixels whose parity (penumbra or not) differs.

#include <io/ImageIO.h>

#include <array>
#include <cstddef>

namespace fl {

/// A pixel is in penumbra when its visibility is strictly between 0 and 1.
[[nodiscard]] inline bool isPenumbra(float v) {
    return v > 0.0f && v < 1.0f;
}

struct SoftStats {
    std::size_t pixels = 0;
    std::size_t penumbraReference = 0; // penumbra pixels of the reference
    std::size_t penumbraMethod = 0;    // penumbra pixels of the method
    /// Over pixels in penumbra in either image: |dI| in [0, 0.05), [0.05, 0.1), [0.1, 0.2),
    /// >= 0.2, as shares of their number (sum 1; all 0 if there are none).
    std::array<double, 4> deltaBuckets{};
    std::size_t penumbraEither = 0;
    double parityShare = 0.0; // share of all pixels whose penumbra/non-penumbra parity differs
    double maxDelta = 0.0;    // largest |dI| over all pixels
    double meanDelta = 0.0;   // mean |dI| over all pixels
};

/// Compares two single-channel visibility images of equal size; throws std::invalid_argument
/// otherwise.
SoftStats compareSoftShadows(const FloatImage& method, const FloatImage& reference);

/// |method - reference| per pixel as a grey picture scaled by `gain` (white = gain^-1 or more);
/// black outside `receivers` when a mask is given (the pixels metrics do not count).
ByteImage differencePicture(const FloatImage& method, const FloatImage& reference,
                            float gain = 4.0f, const FloatImage& receivers = {});

/// method - reference per pixel in colour: white at 0, red where the method is brighter (too
/// lit), blue where it is darker, saturating at +-`range`; black outside `receivers` when a mask
/// is given (the pixels metrics do not count). Throws std::invalid_argument if sizes differ.
ByteImage signedDifferencePicture(const FloatImage& method, const FloatImage& reference,
                                  float range = 0.5f, const FloatImage& receivers = {});

} // namespace fl
