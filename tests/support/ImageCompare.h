#pragma once
// Golden-image comparison with explicit tolerances; on failure writes actual and diff images.

#include <io/ImageIO.h>

#include <filesystem>
#include <string>

namespace fl {
struct FrameImages;
}

namespace fl::test {

struct Tolerance {
    int maxAbs = 255;          // largest per-channel difference allowed (0..255)
    double meanAbs = 0.0;      // mean per-channel difference allowed over all pixels
    int pixelThreshold = 8;    // a pixel "differs" if any channel differs by more than this
    double maxPercentOver = 0; // % of pixels allowed to differ
};

struct CompareResult {
    bool sizeMatches = true;
    int maxAbs = 0;
    double meanAbs = 0.0;
    double percentOver = 0.0;
    bool pass = false;
    std::string report; // one line with every number and the tolerance
};

/// Compares RGB of two 8-bit RGBA images under `tol`.
CompareResult compareImages(const ByteImage& actual, const ByteImage& golden, const Tolerance& tol);

/// Compares `actual` with tests/golden/NAME.png. If FLOODLIGHT_UPDATE_GOLDENS=1, rewrites the
/// golden instead and passes. On failure writes NAME.actual.png and NAME.diff.png (differences
/// amplified x4, red where a pixel is over the threshold) to the test output folder and names
/// them in the report.
CompareResult compareWithGolden(const ByteImage& actual, const std::string& name,
                                const Tolerance& tol);

/// Writes FILE: |a - b| x4 per RGB channel, red where a pixel differs by more than
/// tol.pixelThreshold (the diff of compareWithGolden).
void writeImageDiff(const ByteImage& a, const ByteImage& b, const Tolerance& tol,
                    const std::filesystem::path& file);

/// For a failed comparison of two visibility images of one frame (e.g. a method against an
/// exact answer): writes NAME.a.png, NAME.b.png (grey) and NAME.diff.png (|a - b| x4, grey) to
/// the test output folder and returns a line naming them.
std::string writeVisibilityDiff(const FloatImage& a, const FloatImage& b, const std::string& name);

/// The tolerance of the goldens of rendered frames (colour, and soft visibility as grey levels).
/// They are bit-exact on the machine that made them; another driver may round shading by a few
/// steps and flip shadow tests within float precision at single pixels, so any pixel may differ
/// but the mean stays under 1.5 steps and under 1% of pixels differ by more than 16. A wrong
/// method, camera or light changes far more than that.
Tolerance frameTolerance();

/// Expects `frame`'s colour and visibility to match goldens NAME_colour and NAME_visibility under
/// frameTolerance().
void expectFrameMatchesGoldens(const FrameImages& frame, const std::string& name);

} // namespace fl::test
