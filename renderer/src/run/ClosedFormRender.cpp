#include <renderer/run/ClosedFormRender.h>

#include <renderer/io/TextureImage.h>

namespace fl {

ClosedFormFrame renderClosedForm(const gl::ShaderLibrary& shaders, const ClosedFormCase& c,
                                 const RenderSettings& settings, int size) {
    Renderer r(shaders, c.scene, settings);
    r.resize(size, size);
    r.render(makeCameraView(c.scene, c.camera, 1.0f));
    ClosedFormFrame f{readTexture(r.visibility(), 1), {}};
    f.error = closedFormError(c, r.surfaces().positions().read(), f.visibility);
    return f;
}

} // namespace fl
