// hard: one shadow-map test at the light's centre per pixel.

#include "LightLookup.h"
#include <renderer/passes/Phases.h>

namespace fl {

namespace {

class Hard final : public ShadowMethod {
  public:
    explicit Hard(const gl::ShaderLibrary& shaders) : lookup_(shaders, false) {}
    void resize(int width, int height) override { lookup_.resize(width, height); }
    const gl::Texture& execute(const FrameInputs& in) override {
        gl::TimedPass timedHardShadows(in.timer, phase::kHardShadows);
        const gl::Texture& v = lookup_.execute(in);
        timedHardShadows.wrote(gl::textureBytes(v));
        timedHardShadows.end();
        return v;
    }

  private:
    LightLookup lookup_;
};

} // namespace

std::unique_ptr<ShadowMethod> makeHard(const gl::ShaderLibrary& shaders) {
    return std::make_unique<Hard>(shaders);
}

} // namespace fl
