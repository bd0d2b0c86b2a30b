// jfa-l and flood-l (thesis §5.3): silhouettes of the shadow map flooded into a penumbra map
// (PenumbraMapPass), then each pixel's intensity from the occluder at its texel (LightLookup);
// with --penumbra both (the default) on both sides of the hard shadow's edge, the thesis' lit
// side only with outer.

#include "LightLookup.h"

#include <renderer/methods/OptionStructs.h>
#include <renderer/passes/Phases.h>

#include <renderer/soft/OccluderEdge.h>
#include <renderer/soft/PenumbraMap.h>
#include <renderer/soft/PenumbraReach.h>

#include <jfa_gl/GlKernel.h>

#include <algorithm>
#include <optional>

namespace fl {

namespace {

// Light space: the shadow map's grid, cells packed against the map's receiver positions.
class LightFloodSpace final : public FloodSpace {
  public:
    explicit LightFloodSpace(const gl::ShaderLibrary& shaders) : shaders_(shaders) {}
    [[nodiscard]] Placement placement() const override { return Placement::CentredSquare; }
    [[nodiscard]] jfa::Plan plan(const FloodFrame& f, bool standardFlooding) const override {
        PenumbraSettings ps;
        ps.passes = f.passes;
        ps.standardFlooding = standardFlooding;
        return penumbraPlan(ps, f.seeds->width());
    }
    const gl::Texture& rerun(const FloodFrame& f, const jfa::Plan& plan,
                             const DiskLight& light) const override {
        if (!kernel_) kernel_.emplace(shaders_, jfa::GlKernelKind::Fragment); // on first use
        PenumbraCriterion c;
        c.reachBound = f.reach;
        c.umbraDepth = f.umbraDepth;
        kernel_->setRegion(f.region, f.kernel ? f.kernel->bandTile() : jfa::kDefaultBandTile);
        c.light = light;
        c.map = *f.map;
        return kernel_->run(plan, *f.seeds, c);
    }
    [[nodiscard]] const gl::Texture& unpackSource(const FloodFrame& f) const override {
        if (f.map == nullptr)
            throw std::logic_error("FloodGridReader: a light-space flood without its shadow map");
        return f.map->decoded();
    }
    [[nodiscard]] jfa::Grid unpack(const gl::Texture& grid,
                                   const jfa::Grid& source) const override {
        return readPenumbraGrid(grid, source);
    }
    [[nodiscard]] const gl::Texture& occluderPositions(const FloodFrame& f) const override {
        return unpackSource(f); // the map's positions decoded (the bits the criterion read)
    }
    [[nodiscard]] bool positionsAreEyePoints() const override { return false; }
    [[nodiscard]] std::string_view seedsCaption() const override {
        return "silhouette seeds (light space, JFA-L phase 2)";
    }
    [[nodiscard]] std::string_view floodCaption() const override { return "penumbra map (JFA-L)"; }
    [[nodiscard]] std::string_view seedKind() const override { return "silhouette"; }
    void appendKey(const FloodFrame&, std::vector<float>& key) const override {
        key.insert(key.end(), {0.0f, 1.0f, 1.0f}); // light space; no eye-space switches
    }

  private:
    gl::ShaderLibrary shaders_;
    mutable std::optional<jfa::GlFloodKernel<PenumbraCriterion>> kernel_; // the overlays' re-runs
};

class PenumbraMethod final : public ShadowMethod {
  public:
    PenumbraMethod(const gl::ShaderLibrary& shaders, bool standardFlooding)
        : standardFlooding_(standardFlooding), pass_(shaders), lookup_(shaders, true),
          space_(shaders) {}
    void resize(int width, int height) override { lookup_.resize(width, height); }

    const gl::Texture& execute(const FrameInputs& in) override {
        if (in.shadow.receivers == nullptr)
            throw std::invalid_argument("jfa-l needs the shadow map's receiver positions");
        const LightFloodOptions& o = in.options<LightFloodOptions>();
        PenumbraSettings ps;
        ps.passes = requestedPasses(MethodSpace::Light, o.flood, in.shadow.depth.width(),
                                    in.width(), in.height());
        ps.standardFlooding = standardFlooding_;
        ps.region = o.flood.region;
        ps.bandTile = o.flood.bandTile;
        const int size = in.shadow.depth.width();
        PenumbraReach reach =
            penumbraReach(in.disk, in.shadow.mapViewProj(), {size, size}, in.sceneBounds);
        // A silhouette needs a depth step of a thousandth of the scene: smaller steps are the
        // receiver's own slope, not an occluder's edge.
        const float threshold = silhouetteThreshold(in.sceneBounds.radius());
        // --flood-region view: the lookup below reads one texel per eye pixel, so the flood
        // need be exact there only (jfa/Band.h, the view limit), and only seeds within the
        // flood's reach of those texels, or (auto) within the widest penumbra's, count.
        const PenumbraView view{in.surfaces.positions(), in.shadow.lightViewProj, in.shadow.warp};
        PenumbraMapPass::Inputs pi{*in.shadow.receivers, in.disk, ps, threshold, reach, &view};
        if (ps.region == jfa::FloodRegion::View) pi.viewSeedReach = viewSeedReach(in, ps, size);
        // --penumbra both: a texel whose surface may hide a receiver in an occluder's umbra
        // ranks occluders for one at the deepest a receiver lies (PenumbraCriterion::umbraDepth).
        const bool both = o.bothSides;
        pi.umbraDepth = both ? reach.farDepth : 0.0f;
        const PenumbraMapPass::Outputs pm = pass_.execute(pi, in.timer);
        flood_ = {.seeds = &pm.seeds,
                  .flooded = &pm.penumbraMap,
                  .space = &space_,
                  .standardFlooding = standardFlooding_,
                  .passes = pm.jfaPasses,
                  .region = ps.region,
                  .reach = reach,
                  .kernel = &pass_.kernel(),
                  .map = in.shadow.receivers,
                  .umbraDepth = pi.umbraDepth};
        gl::TimedPass timedPenumbraLookup(in.timer, phase::kPenumbraLookup);
        const gl::Texture& v = lookup_.execute(in, &pm.penumbraMap, both);
        timedPenumbraLookup.wrote(gl::textureBytes(v));
        timedPenumbraLookup.end();
        return v;
    }
    [[nodiscard]] const FloodFrame* flood() const override { return &flood_; }

  private:
    /// How far from the view's texels seeds and receivers count: the plan's reach plus a texel
    /// (jfa::viewTileReach) for a fixed pass count; with auto, the widest penumbra any occluder
    /// can cast plus a texel (widestPenumbraTexels: the uniform map of a point or spot light),
    /// so that every penumbra that reaches the view counts. -1 (the whole map) when nothing
    /// bounds it.
    long long viewSeedReach(const FrameInputs& in, const PenumbraSettings& ps, int size) {
        if (ps.passes != kAutoPasses) return 1LL << ps.passes;
        if (in.shadowSettings.provider != ShadowMapProvider::Uniform) return -1;
        // The occluders' nearest depths, from the posed vertices: once per pose and light.
        const glm::vec3 axis = -glm::normalize(glm::vec3(glm::inverse(in.lightVolume.view)[2]));
        const NearestKey key{in.scene.poseVersion(), in.disk.center, in.disk.normal, axis};
        if (!nearestKey_ || !(*nearestKey_ == key)) {
            const Scene& scene = in.scene.source();
            const Pose rest = in.scene.pose() ? Pose{} : evaluatePose(scene, {}, 0.0);
            nearest_ =
                nearestLightDepths(scene, in.scene.pose() ? *in.scene.pose() : rest, in.disk, axis);
            nearestKey_ = key;
        }
        const std::optional<long long> widest =
            widestPenumbraTexels(in.disk, in.lightVolume, size, nearest_,
                                 farthestLightDepth(in.disk, in.sceneBounds) * 1.001f + 1e-4f);
        if (!widest) return -1;
        return *widest + 1; // PenumbraMapPass widens it to the passes auto then chooses
    }
    struct NearestKey {
        std::uint64_t pose;
        glm::vec3 center, normal, axis;
        bool operator==(const NearestKey&) const = default;
    };
    std::optional<NearestKey> nearestKey_;
    glm::vec2 nearest_{0.0f};

    bool standardFlooding_;
    PenumbraMapPass pass_;
    LightLookup lookup_;
    LightFloodSpace space_;
    FloodFrame flood_;
};

} // namespace

std::unique_ptr<ShadowMethod> makeJfaL(const gl::ShaderLibrary& shaders) {
    return std::make_unique<PenumbraMethod>(shaders, false);
}
std::unique_ptr<ShadowMethod> makeFloodL(const gl::ShaderLibrary& shaders) {
    return std::make_unique<PenumbraMethod>(shaders, true);
}

} // namespace fl
