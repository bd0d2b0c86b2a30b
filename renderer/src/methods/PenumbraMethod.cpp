// jfa-l and flood-l (thesis §5.3): silhouettes of the shadow map flooded into a penumbra map
// (PenumbraMapPass), then each pixel's intensity from the occluder at its texel (LightLookup).

#include "LightLookup.h"

#include <renderer/soft/OccluderEdge.h>
#include <renderer/soft/PenumbraMap.h>

#include <algorithm>

namespace fl {

namespace {

class PenumbraMethod final : public ShadowMethod {
  public:
    PenumbraMethod(const gl::ShaderLibrary& shaders, bool standardFlooding)
        : standardFlooding_(standardFlooding), pass_(shaders), lookup_(shaders, true) {}
    void resize(int width, int height) override { lookup_.resize(width, height); }

    const gl::Texture& execute(const FrameInputs& in) override {
        if (in.shadow.receivers == nullptr)
            throw std::invalid_argument("jfa-l needs the shadow map's receiver positions");
        PenumbraSettings ps;
        ps.passes = requestedPasses(in.method, in.options, in.shadow.depth.width(), in.width(),
                                    in.height());
        ps.standardFlooding = standardFlooding_;
        ps.region = floodRegion(in.options);
        ps.bandTile = bandTile(in.options);
        const int size = in.shadow.depth.width();
        const PenumbraReach reach =
            penumbraReach(in.disk, in.shadow.mapViewProj(), {size, size}, in.sceneBounds);
        // A silhouette needs a depth step of a thousandth of the scene: smaller steps are the
        // receiver's own slope, not an occluder's edge.
        const float threshold = silhouetteThreshold(in.sceneBounds.radius());
        const PenumbraMapPass::Outputs pm =
            pass_.execute({*in.shadow.receivers, in.disk, ps, threshold, reach}, in.timer);
        flood_ = {&pm.seeds,
                  &pm.penumbraMap,
                  in.shadow.receivers,
                  nullptr,
                  false,
                  standardFlooding_,
                  pm.jfaPasses,
                  true,
                  true,
                  ps.region,
                  reach,
                  &pass_.kernel()};
        if (in.timer) in.timer->begin("penumbra lookup");
        const gl::Texture& v = lookup_.execute(in, &pm.penumbraMap);
        if (in.timer) in.timer->end();
        return v;
    }
    [[nodiscard]] const FloodFrame* flood() const override { return &flood_; }

  private:
    bool standardFlooding_;
    PenumbraMapPass pass_;
    LightLookup lookup_;
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
