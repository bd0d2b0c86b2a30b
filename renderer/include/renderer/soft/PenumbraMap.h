#pragma once
// JFA-L phases 2 and 3 (thesis §5.3.1; the thesis' numbers, both inside frame step 3, the shadow
// method; its phase 1 is the shadow map, frame step 1): silhouette pixels of the shadow map
// become seeds carrying their world position, and jump flooding with PenumbraCriterion spreads
// them into the penumbra map. The CPU functions are the reference the GL pass is tested against.

#include <renderer/soft/PenumbraCriterion.h>

#include <gpu/PassTimer.h>
#include <gpu/ShaderLibrary.h>
#include <jfa/GlKernel.h>
#include <jfa/Plan.h>

namespace fl {

/// How the penumbra map is flooded.
struct PenumbraSettings {
    /// JFA passes with steps 2^(passes-1), ..., 2, 1: penumbrae up to 2^passes - 1 texels wide
    /// (thesis default 6 -> 63). Must be in [1, log2(shadow-map size)], or 0 (auto): the fewest
    /// that cover the widest penumbra any silhouette can cast (PenumbraReach), found per frame.
    int passes = 6;
    /// The standard-flooding reference: 2^passes - 1 passes of step 1 (same reach).
    bool standardFlooding = false;
    /// Band-limited (jfa/Band.h; identical result) or full-grid flooding.
    jfa::FloodRegion region = jfa::FloodRegion::Band;
    int bandTile = jfa::kDefaultBandTile;
};

/// The most JFA passes a size x size map can use: log2(size), rounded down.
int penumbraMaxPasses(int size);

/// The flood plan for a size x size shadow map. Throws std::invalid_argument when passes is
/// outside [1, log2(size)] (the message names the valid range).
jfa::Plan penumbraPlan(const PenumbraSettings& settings, int size);

/// CPU reference of the silhouette pass (shaders/silhouette.frag.glsl).
jfa::Grid silhouetteSeeds(const ReceiverGrid& receivers, const DiskLight& light, float threshold);

/// The technique: silhouettes, then the flood.
class PenumbraMapPass {
  public:
    explicit PenumbraMapPass(const gl::ShaderLibrary& shaders);

    struct Inputs {
        const gl::Texture& receivers; // ShadowMapPass::Outputs::receivers
        const DiskLight& light;
        const PenumbraSettings& settings;
        float threshold;            // resolved silhouette threshold (world units)
        const PenumbraReach& reach; // the map's penumbra bound (band and auto passes)
    };
    struct Outputs {
        const gl::Texture& seeds;       // RGBA32F silhouette seeds (w = 1) or empty cells
        const gl::Texture& penumbraMap; // RGBA32F occluder per texel (w = 1) or empty
        int passes;                     // flood passes run
        int jfaPasses;                  // the JFA pass count used (auto resolved)
    };
    /// Runs both phases; `timer` (optional) times them as "silhouettes", "band" (the flood's
    /// band and pass count) and "flood".
    Outputs execute(const Inputs& in, gl::PassTimer* timer = nullptr);

  private:
    gl::Program silhouette_;
    gl::VertexArray emptyVao_;
    gl::Texture seeds_;
    gl::Framebuffer fbo_;
    jfa::GlFloodKernel<PenumbraCriterion> kernel_;
    ReceiverBoundsPyramid bounds_; // tightens the band's bound (PenumbraReach)

  public:
    /// The flood's kernel (its region and the last run's active share).
    [[nodiscard]] const jfa::GlFloodKernelBase& kernel() const { return kernel_; }
};

} // namespace fl
