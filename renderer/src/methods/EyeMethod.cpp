// jfa-e and flood-e (thesis §5.4): hard shadows of the frame's surfaces, boundary seeds, the
// flood in eye space and the visibility composite (EyeSoftShadowPass).

#include <renderer/methods/OptionStructs.h>
#include <renderer/methods/ShadowMethod.h>
#include <renderer/soft/EyeSoftShadow.h>

#include <algorithm>

namespace fl {

namespace {

class EyeMethod final : public ShadowMethod {
  public:
    EyeMethod(const gl::ShaderLibrary& shaders, bool standardFlooding)
        : standardFlooding_(standardFlooding), pass_(shaders) {}
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
        const EyeSoftShadowPass::Outputs out =
            pass_.execute({in.scene, in.camera, in.surfaces.positions(), in.shadow,
                           in.shadowSettings, in.disk, es, passes, standardFlooding_, in.width(),
                           in.height(), region, reach, o.flood.bandTile},
                          in.timer);
        flood_ = {&out.seeds,     &out.flooded,   &out.eye, true,  standardFlooding_, out.jfaPasses,
                  es.objectIdFix, es.midpointFix, region,   reach, &pass_.kernel()};
        return out.visibility;
    }
    [[nodiscard]] const FloodFrame* flood() const override { return &flood_; }

  private:
    bool standardFlooding_;
    EyeSoftShadowPass pass_;
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
