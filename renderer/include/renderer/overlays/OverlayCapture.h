#pragma once
// Overlays drawn off screen: the picture `floodlight render --overlay` writes and the tests
// compare with goldens and CPU references.

#include <io/ImageIO.h>
#include <renderer/overlays/Overlay.h>

#include <string>
#include <vector>

namespace fl {

/// An overlay picture and the HUD lines that came with it.
struct OverlayCapture {
    ByteImage image; // RGBA8, row 0 = top of the picture (as PNG files store it)
    std::vector<std::string> hud;
};

/// Draws `mode` for the renderer's last frame into a w x h RGBA8 target cleared to black and
/// reads it back; leaves the default framebuffer bound.
OverlayCapture captureOverlay(OverlayRenderer& overlays, OverlayMode mode, const Renderer& renderer,
                              const CameraView& camera, OverlayControls& controls, int w, int h);

} // namespace fl
