#pragma once
// JFA-L phases 2 and 3 (thesis §5.3.1; the thesis' numbers, both inside frame step 3, the shadow
// method; its phase 1 is the shadow map, frame step 1): silhouette pixels of the shadow map
// become seeds carrying their world position, and jump flooding with PenumbraCriterion spreads
// them into the penumbra map. The CPU functions are the reference the GL pass is tested against.

#include <renderer/passes/SurfacesPass.h>
#include <renderer/soft/PenumbraCriterion.h>

#include <gpu/PassTimer.h>
#include <gpu/ShaderLibrary.h>
#include <jfa/Plan.h>
#include <jfa_gl/GlKernel.h>

namespace fl {

/// How the penumbra map is flooded.
struct PenumbraSettings {
    /// JFA passes with steps 2^(passes-1), ..., 2, 1: penumbrae up to 2^passes - 1 texels wide
    /// (thesis default 6 -> 63). Must be in [1, log2(shadow-map size)], or 0 (auto): the fewest
    /// that cover the widest penumbra any silhouette can cast (PenumbraReach), found per frame.
    int passes = 6;
    /// The standard-flooding reference: 2^passes - 1 passes of step 1 (same reach).
    bool standardFlooding = false;
    /// Band-limited (jfa/Band.h; identical result), full-grid flooding, or the band less what
    /// the view does not read (PenumbraMapPass::Inputs::view; the same picture).
    jfa::FloodRegion region = jfa::FloodRegion::Band;
    int bandTile = jfa::kDefaultBandTile;
};

/// The most JFA passes a size x size map can use: log2(size), rounded down.
int penumbraMaxPasses(int size);

/// The flood plan for a size x size shadow map. Throws std::invalid_argument when passes is
/// outside [1, log2(size)] (the message names the valid range).
jfa::Plan penumbraPlan(const PenumbraSettings& settings, int size);

/// CPU reference of the silhouette pass (shaders/silhouette.frag.glsl); with `region`, only the
/// texels of its tiles can be seeds.
/// A JFA-L grid as the GL kernels store it (R32F, packed cells: a seed's tag, 0 empty; see
/// PenumbraCriterion::packedCells) turned back into cells, the occluders taken from `positions`
/// (the map's positions as the shaders decode them: jfa::readGrid of
/// ShadowMapPass::decodedReceivers): the CPU twin of mapSeedCell() in shadow_map_decode.glsl.
jfa::Grid readPenumbraGrid(const gl::Texture& packed, const jfa::Grid& positions);

jfa::Grid silhouetteSeeds(const ReceiverGrid& receivers, const DiskLight& light, float threshold,
                          const jfa::Band* region = nullptr);

/// What reads the penumbra map (--flood-region view): the lookup (soft_penumbra.glsl), one texel
/// per eye pixel, where the pixel's surface point projects.
struct PenumbraView {
    SurfacePositions positions; // SurfacesPass::Outputs::positions()
    glm::mat4 lightViewProj;    // ShadowMapPass::Outputs
    glm::mat4 warp;
};

/// CPU reference of shaders/penumbra_view.frag.glsl: one flag per tile (side `tile`) of a
/// mapSize^2 penumbra map, row-major, 1 where the lookup may read a texel for one of
/// `eyePositions`' points (w != 0). The test of the map's extent has a margin of 1e-4 of the map
/// (the lookup's own rounding may differ from this pass's); jfa::viewTileReach adds one texel.
std::vector<std::uint8_t> penumbraViewTiles(const ReceiverGrid& eyePositions,
                                            const glm::mat4& lightViewProj, const glm::mat4& warp,
                                            int mapSize, int tile);

/// The technique: silhouettes, then the flood.
class PenumbraMapPass {
  public:
    explicit PenumbraMapPass(const gl::ShaderLibrary& shaders);

    struct Inputs {
        const MapPositions& receivers; // ShadowMapPass::Outputs::receivers
        const DiskLight& light;
        const PenumbraSettings& settings;
        float threshold;                    // resolved silhouette threshold (world units)
        const PenumbraReach& reach;         // the map's penumbra bound (band and auto passes)
        const PenumbraView* view = nullptr; // with FloodRegion::View: who reads the map
        /// With a view: how far (texels) from the view's tiles seeds and receivers count at all
        /// (the flood's reach, and with auto passes the widest penumbra too,
        /// widestPenumbraTexels); silhouettes and the bounds pyramid skip the tiles beyond.
        /// -1: the whole map.
        long long viewSeedReach = -1;
        /// --penumbra both: PenumbraCriterion::umbraDepth (the reach's farDepth); 0: outer only.
        float umbraDepth = 0.0f;
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
    /// Phase 2: the silhouette seeds into seeds_ (listed for a band), only within seedRegion_
    /// with `region`.
    void findSeeds(const Inputs& in, bool region);
    /// --flood-region view: the view's tiles and the seed region around them (timed "view");
    /// true when a seed region was marked. `regionReach` is the region's reach in texels.
    bool markViewRegion(const Inputs& in, long long regionReach, gl::PassTimer* timer);
    /// Phase 3's band: the reach bounds and, with auto, the pass count (growing the seed
    /// region while auto asks for more than it covers); returns the settings with the count.
    PenumbraSettings planBand(const Inputs& in, PenumbraCriterion& criterion, bool& region,
                              long long& regionReach, const gl::TimedPass& band);
    /// Fills viewTiles_ from `view` (penumbra_view.frag.glsl).
    void markView(const PenumbraView& view, int size, int tile);
    /// Fills seedRegion_: the view's tiles widened by `reach` texels (jfa::GlTileDilation);
    /// false when that is the whole map.
    bool markSeedRegion(int size, int tile, long long reach);

    gl::Program silhouette_;
    gl::VertexArray emptyVao_;
    gl::Texture seeds_;
    gl::Framebuffer fbo_;
    jfa::GlFloodKernel<PenumbraCriterion> kernel_;
    ReceiverBoundsPyramid bounds_; // tightens the band's bound (PenumbraReach)
    gl::Program viewProgram_;      // penumbra_view.frag.glsl
    gl::Framebuffer viewFbo_;      // its framebuffer, without attachments
    gl::Buffer viewTiles_;         // its flags, one uint per band tile
    int viewTileCount_ = 0;        // of the last run with a view (0: none)
    jfa::GlTileDilation dilation_; // widens the view's tiles into the seed region
    gl::Buffer seedRegion_;
    int seedRegionCount_ = 0; // tiles of the last run's seed region (0: none)
    gl::Buffer rowSpans_;     // first and last tile per row drawn: this region's and the last's
    gl::Buffer lastSpans_;    // this region's alone, for the next one
    bool seedsOffSpansEmpty_ = false; // seeds_ holds nothing off lastSpans_ (tiles of spansTile_)
    int spansTile_ = 0;
    gl::Program silhouetteRows_; // phase 2 over the region's rows' spans

  public:
    /// The view tiles of the last run with a view (penumbra_view.frag.glsl), read back: one
    /// flag per band tile; empty when it had none.
    [[nodiscard]] std::vector<std::uint8_t> viewTiles() const;
    /// The seed region of the last run (Inputs::viewSeedReach), read back the same way; empty
    /// when it had none (the whole map).
    [[nodiscard]] std::vector<std::uint8_t> seedRegion() const;
    /// The flood's kernel (its region and the last run's active share).
    [[nodiscard]] const jfa::GlFloodKernelBase& kernel() const { return kernel_; }
};

} // namespace fl
