#pragma once
// Saving a rendered frame: PNG (sRGB, for looking) and EXR (linear float, for measuring).

#include <gpu/ReadBack.h>
#include <io/ImageIO.h>
#include <renderer/Renderer.h>

#include <filesystem>
#include <string>

namespace fl {

struct CapturePaths {
    std::filesystem::path png;
    std::filesystem::path visibilityPng;
    std::filesystem::path exr;
};

/// The last frame's colour (RGBA linear), visibility and receiver mask read back from the GPU.
struct FrameImages {
    FloatImage color;      // 4 channels
    FloatImage visibility; // 1 channel
    FloatImage receivers;  // 1 channel: 1 where a visible surface faces the light, else 0
    /// 4 channels: each pixel's surface point in the previous frame, pixel x, y (row 0 at the
    /// top, as here), depth there; and its depth now (SurfacesPass's motion target); empty when the
    /// frame wrote none (Renderer::render).
    FloatImage motion;
    /// 1 channel each, empty unless the frame loop was asked for them (FramePlan::biasMasks):
    /// the acne candidates' geometry (receivers whose triangle faces the light's centre) and the
    /// contact pixels (renderer/metrics/BiasArtifacts.h).
    FloatImage facingLight, contact;
};
FrameImages readFrame(const Renderer& renderer);

/// readFrame through pixel buffers (gpu/ReadBack.h): start() queues the copies of the renderer's
/// targets and returns at once; finish() waits for them (long done a frame later) and returns
/// what readFrame would have returned then. Keep one per renderer: the buffers are reused.
class FrameReadBack {
  public:
    void start(const Renderer& renderer);
    [[nodiscard]] bool pending() const { return color_.pending(); }
    [[nodiscard]] FrameImages finish();

  private:
    gl::TextureReadBack color_, visibility_, receivers_, motion_;
};

/// Visibility as a grey PNG image: white lit, black shadowed.
ByteImage visibilityToGrey(const FloatImage& visibility);

/// Writes DIR/STEM.png (sRGB colour), DIR/STEM.visibility.png (grey) and DIR/STEM.exr (channels R,
/// G, B, A, visibility, and receiver when the frame has its mask; linear float). Throws
/// std::runtime_error if a pixel is not finite or a file cannot be written.
CapturePaths writeFrame(const FrameImages& frame, const std::filesystem::path& dir,
                        const std::string& stem);
/// The files writeFrame(frame, dir, stem) writes: DIR/STEM.png, .visibility.png and .exr.
CapturePaths capturePaths(const std::filesystem::path& dir, const std::string& stem);

} // namespace fl
