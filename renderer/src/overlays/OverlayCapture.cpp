#include <renderer/overlays/OverlayCapture.h>

#include <gpu/Gl.h>

#include <cstring>

namespace fl {

OverlayCapture captureOverlay(OverlayRenderer& overlays, OverlayMode mode, const Renderer& renderer,
                              const CameraView& camera, OverlayControls& controls, int w, int h) {
    const gl::Texture target(GL_RGBA8, w, h);
    const gl::Framebuffer fbo = gl::Framebuffer::forColor(target, "overlay capture");
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, w, h);
    const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, black);
    OverlayCapture out;
    out.hud = overlays.draw(mode, renderer, camera, controls, w, h);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    std::vector<std::uint8_t> pixels(std::size_t(w) * std::size_t(h) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(target.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(pixels.size()),
                      pixels.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    out.image = ByteImage{w, h, 4, std::vector<std::uint8_t>(pixels.size())};
    const std::size_t row = std::size_t(w) * 4;
    for (int y = 0; y < h; ++y) // GL row 0 is the bottom
        std::memcpy(&out.image.data[std::size_t(h - 1 - y) * row], &pixels[std::size_t(y) * row],
                    row);
    gl::throwIfErrors("overlay capture");
    return out;
}

} // namespace fl
