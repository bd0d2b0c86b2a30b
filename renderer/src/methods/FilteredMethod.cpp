// pcf and pcss: the shadow map filtered per pixel of the frame's surfaces (FilteredShadowPass).

#include <renderer/methods/OptionStructs.h>
#include <renderer/methods/ShadowMethod.h>
#include <renderer/soft/FilteredShadow.h>

namespace fl {

namespace {

class FilteredMethod final : public ShadowMethod {
  public:
    FilteredMethod(const gl::ShaderLibrary& shaders, bool pcss) : pcss_(pcss), pass_(shaders) {}
    void resize(int, int) override {} // the pass sizes itself to the frame

    const gl::Texture& execute(const FrameInputs& in) override {
        FilteredShadowSettings fs;
        if (pcss_)
            fs.pcss = in.options<PcssOptions>().preset;
        else
            fs.pcfKernel = in.options<PcfOptions>().kernel;
        return pass_.execute({in.surfaces, in.shadow, in.lightVolume, in.disk, fs, pcss_}, in.timer)
            .visibility;
    }

  private:
    bool pcss_;
    FilteredShadowPass pass_;
};

} // namespace

std::unique_ptr<ShadowMethod> makePcf(const gl::ShaderLibrary& shaders) {
    return std::make_unique<FilteredMethod>(shaders, false);
}
std::unique_ptr<ShadowMethod> makePcss(const gl::ShaderLibrary& shaders) {
    return std::make_unique<FilteredMethod>(shaders, true);
}

} // namespace fl
