#pragma once
// JFA-E's automatic pass count from what the frame's flood needs.
// The geometric bound (maxSeedReach: the widest penumbra any seed's occluder could cast) cannot
// see that nearer seeds win most of those pixels, so it asks for 9-10 passes where the flood's
// cells travel under 64 pixels (docs/BENCHMARKS.md). Instead, phase 2's images are point-sampled
// at 1/kCoarseFactor resolution, phase 3 finds their boundary seeds and a full JFA with the same
// criterion floods them (1/16 of the pixels: a fraction of one full-resolution pass); every
// flooded cell's distance to its seed pixel (Chebyshev, in coarse pixels) goes into a histogram,
// and the pass count is the fewest that cover the farthest, scaled back to the frame.
// The GL estimator (EyeFloodEstimator) and the CPU reference (coarseFloodTravel) agree bin for
// bin; a test says so.

#include <renderer/soft/EyeSoftShadow.h>

#include <cstdint>
#include <vector>

namespace fl {

/// Resolution divisor of the coarse flood.
inline constexpr int kCoarseFactor = 4;
/// Histogram bins: bin d counts cells whose seed lies d coarse pixels away; the last bin also
/// every farther one (coarse grids are at most 1024 wide: 4K frames).
inline constexpr int kTravelBins = 1024;

/// The coarse grid of a width x height frame: ceil(size / factor) per axis.
glm::ivec2 coarseSize(int width, int height, int factor);
/// Phase 2's images point-sampled at coarse pixel (X, Y) = frame pixel
/// min(factor * (X, Y) + factor / 2, size - 1) (on the GPU eye_decode.glsl's uEyeFactor reads
/// the frame's cells so, with no coarse copy).
EyeImage coarseEyeImage(const EyeImage& image, int factor);
/// The frame's boundary threshold on the coarse grid: neighbours lie `factor` times farther.
BoundaryThreshold coarseThreshold(BoundaryThreshold frame, int factor);
/// CPU reference of shaders/jfae_travel.comp.glsl: per non-empty cell (w = seed index + 1) the
/// Chebyshev distance to its seed pixel, counted in kTravelBins bins.
std::vector<std::uint32_t> floodTravel(const jfa::Grid& flooded);
/// The largest distance with a count in `histogram`; -1 when it is empty.
int maxTravel(const std::vector<std::uint32_t>& histogram);
/// The fewest JFA passes (at most maxPasses) that cover a frame-pixel reach of
/// factor * (travel + 1) - 1: a coarse cell's seed and its sample stand up to factor - 1 frame
/// pixels apart. 1 without cells (travel < 0).
int passesForTravel(int travel, int factor, int maxPasses);

/// What the coarse flood needs from the frame.
struct CoarseFloodSettings {
    glm::vec3 eye{0.0f};
    BoundaryThreshold threshold; // the frame's (boundaryThreshold), not yet coarse
    DiskLight light;
    bool objectIdFix = true;
    bool midpointFix = true;
    int factor = kCoarseFactor;
};

/// CPU reference of the whole estimate: coarse image, boundary seeds, a full JFA
/// (eyeSoftMaxPasses of the coarse grid; none if that is 0) with EyeSoftCriterion, histogram.
std::vector<std::uint32_t> coarseFloodTravel(const EyeImage& image, const CoarseFloodSettings& s);

/// The estimate on the GPU from phase 2's textures; owns the coarse textures and a kernel.
class EyeFloodEstimator {
  public:
    explicit EyeFloodEstimator(const gl::ShaderLibrary& shaders);
    /// Runs the coarse flood on the frame's packed cells (read at the coarse pixels' samples)
    /// and reads the histogram back (one sync point); empty when the coarse grid is too small.
    std::vector<std::uint32_t> travel(const EyeCells& eye, const CoarseFloodSettings& s);
    /// Bytes the last travel() wrote: the coarse seeds, every pass of its flood and the
    /// histogram (what PassTimer counts for the "pass count" phase).
    [[nodiscard]] std::int64_t bytes() const { return bytes_; }

  private:
    void resize(glm::ivec2 size);

    gl::Program boundary_, travel_;
    gl::VertexArray emptyVao_;
    gl::Texture seeds_, seedOccluders_; // phase 3's two targets (jfae_boundary.frag.glsl)
    gl::Framebuffer seedsFbo_;
    gl::Buffer bins_;
    jfa::GlFloodKernel<EyeSoftCriterion> kernel_;
    std::int64_t bytes_ = 0;
};

} // namespace fl
