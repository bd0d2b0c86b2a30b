// jfa-e and flood-e (thesis §5.4): hard shadows of the frame's surfaces, boundary seeds, the
// flood in eye space and the visibility composite (EyeSoftShadowPass).

#include <renderer/methods/OptionStructs.h>
#include <renderer/methods/ShadowMethod.h>
#include <renderer/soft/EyeDecode.h>
#include <renderer/soft/EyeSoftShadow.h>

#include <algorithm>
#include <optional>

namespace fl {

namespace {

// Eye space: a grid of the frame's pixels, cells packed against phase 2's occluders.
class EyeFloodSpace final : public FloodSpace {
  public:
    explicit EyeFloodSpace(const gl::ShaderLibrary& shaders) : shaders_(shaders) {}
    [[nodiscard]] Placement placement() const override { return Placement::WholeFrame; }
    [[nodiscard]] jfa::Plan plan(const FloodFrame& f, bool standardFlooding) const override {
        return eyeSoftPlan(f.passes, standardFlooding, f.seeds->width(), f.seeds->height());
    }
    const gl::Texture& rerun(const FloodFrame& f, const jfa::Plan& plan,
                             const DiskLight& light) const override {
        if (!kernel_) kernel_.emplace(shaders_, jfa::GlKernelKind::Fragment); // on first use
        EyeSoftCriterion c;
        c.reachBound = f.reach;
        kernel_->setRegion(f.region, f.kernel ? f.kernel->bandTile() : jfa::kDefaultBandTile);
        c.light = light;
        c.objectIdFix = f.objectIdFix;
        c.midpointFix = f.midpointFix;
        c.cells = f.eyeCells;
        return kernel_->run(plan, *f.seeds, c);
    }
    [[nodiscard]] const gl::Texture& unpackSource(const FloodFrame& f) const override {
        // Phase 3's occluder per seed (walked to the silhouette), which the flood carried;
        // phase 2's where phase 3 has not run.
        return f.eyeCells->seedOccluders ? *f.eyeCells->seedOccluders
                                         : f.eyeCells->decoded().second;
    }
    [[nodiscard]] jfa::Grid unpack(const gl::Texture& grid,
                                   const jfa::Grid& source) const override {
        return readEyeGrid(grid, source);
    }
    [[nodiscard]] const gl::Texture& occluderPositions(const FloodFrame& f) const override {
        return f.eyeCells->decoded().first; // the eye's points
    }
    [[nodiscard]] bool positionsAreEyePoints() const override { return true; }
    [[nodiscard]] std::string_view seedsCaption() const override {
        return "boundary seeds (eye space, JFA-E phase 3)";
    }
    [[nodiscard]] std::string_view floodCaption() const override {
        return "eye-space flood (JFA-E phase 4)";
    }
    [[nodiscard]] std::string_view seedKind() const override { return "boundary"; }
    void appendKey(const FloodFrame& f, std::vector<float>& key) const override {
        key.push_back(1.0f); // eye space
        key.push_back(f.objectIdFix ? 1.0f : 0.0f);
        key.push_back(f.midpointFix ? 1.0f : 0.0f);
    }

  private:
    gl::ShaderLibrary shaders_;
    mutable std::optional<jfa::GlFloodKernel<EyeSoftCriterion>> kernel_; // the overlays' re-runs
};

class EyeMethod final : public ShadowMethod {
  public:
    EyeMethod(const gl::ShaderLibrary& shaders, bool standardFlooding)
        : standardFlooding_(standardFlooding), pass_(shaders), space_(shaders) {}
    void resize(int, int) override {} // the pass sizes itself to the frame

    const gl::Texture& execute(const FrameInputs& in) override {
        const EyeFloodOptions& o = in.options<EyeFloodOptions>();
        EyeSoftSettings es;
        es.objectIdFix = !o.noObjectIdFix;
        es.midpointFix = !o.noMidpointFix;
        es.boundaryThreshold = o.boundaryThreshold;
        es.occluderPoints = o.occluderPoints;
        es.silhouetteThreshold = silhouetteThreshold(in.sceneBounds.radius());
        es.autoPasses = o.autoPasses;
        const int passes = requestedPasses(MethodSpace::Eye, o.flood, in.shadow.depth.width(),
                                           in.width(), in.height());
        const jfa::FloodRegion region = o.flood.region;
        const PenumbraReach reach = penumbraReach(in.disk, in.camera.proj * in.camera.view,
                                                  {in.width(), in.height()}, in.sceneBounds);
        const EyeSoftShadowPass::Outputs out = pass_.execute(
            {in.scene, in.camera, in.surfaces.positions(), in.surfaces.normals, in.surfaces.lift,
             in.shadow, in.shadowSettings, in.disk, es, passes, standardFlooding_, in.width(),
             in.height(), region, reach, o.flood.bandTile},
            in.timer);
        flood_ = {.seeds = &out.seeds,
                  .flooded = &out.flooded,
                  .space = &space_,
                  .standardFlooding = standardFlooding_,
                  .passes = out.jfaPasses,
                  .region = region,
                  .reach = reach,
                  .kernel = &pass_.kernel(),
                  .eyeCells = &out.eye,
                  .objectIdFix = es.objectIdFix,
                  .midpointFix = es.midpointFix};
        return out.visibility;
    }
    [[nodiscard]] const FloodFrame* flood() const override { return &flood_; }

  private:
    bool standardFlooding_;
    EyeSoftShadowPass pass_;
    EyeFloodSpace space_;
    FloodFrame flood_;
};

} // namespace

std::unique_ptr<ShadowMethod> makeJfaE(const gl::ShaderLibrary& shaders) {
    return std::make_unique<EyeMethod>(shaders, false);
}
std::unique_ptr<ShadowMethod> makeFloodE(const gl::ShaderLibrary& shaders) {
    return std::make_unique<EyeMethod>(shaders, true);
}

} // namespace fl
