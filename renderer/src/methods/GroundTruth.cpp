// reference: the ground truth, N point-light shadow maps over the disk averaged per pixel of the
// frame's surfaces (ReferenceShadowPass).

#include <renderer/methods/OptionStructs.h>
#include <renderer/methods/ShadowMethod.h>
#include <renderer/soft/ReferenceShadow.h>

namespace fl {

namespace {

class GroundTruth final : public ShadowMethod {
  public:
    explicit GroundTruth(const gl::ShaderLibrary& shaders) : pass_(shaders) {}
    void resize(int, int) override {} // the pass sizes itself to the frame

    const gl::Texture& execute(const FrameInputs& in) override {
        const GroundTruthOptions& o = in.options<GroundTruthOptions>();
        ReferenceSettings rs;
        rs.samples = o.samples;
        rs.mapSize = o.mapSize;
        rs.pattern = o.pattern;
        return pass_
            .execute({in.scene, in.surfaces.positions(), in.sceneBounds, in.casterBounds, in.disk,
                      in.shadowSettings, rs, in.surfaces.lift, in.surfaces.normals},
                     in.timer)
            .visibility;
    }

  private:
    ReferenceShadowPass pass_;
};

} // namespace

std::unique_ptr<ShadowMethod> makeGroundTruth(const gl::ShaderLibrary& shaders) {
    return std::make_unique<GroundTruth>(shaders);
}

} // namespace fl
