#include <renderer/io/TextureImage.h>
#include <renderer/run/Capture.h>

#include <algorithm>
#include <cmath>

namespace fl {

namespace {

// The motion target holds GL window coordinates (y up from the bottom edge); the images here
// have row 0 at the top.
void motionToImageRows(FloatImage& motion) {
    for (std::size_t i = 1; i < motion.data.size(); i += 4)
        motion.data[i] = static_cast<float>(motion.height) - motion.data[i];
}

FloatImage imageOf(gl::TextureReadBack& read) {
    const gl::TextureReadBack::Mapped m = read.finish();
    return fromGlRows(m.data(), m.width(), m.height(), m.channels());
}

} // namespace

FrameImages readFrame(const Renderer& renderer) {
    FloatImage motion; // empty when the frame wrote no motion target
    if (renderer.motion()) motion = readTexture(*renderer.motion(), 4);
    motionToImageRows(motion);
    return {readTexture(renderer.color(), 4), readTexture(renderer.visibility(), 1),
            readTexture(renderer.receivers(), 1), std::move(motion)};
}

void FrameReadBack::start(const Renderer& renderer) {
    color_.start(renderer.color(), 4);
    visibility_.start(renderer.visibility(), 1);
    receivers_.start(renderer.receivers(), 1);
    if (renderer.motion()) motion_.start(*renderer.motion(), 4);
}

FrameImages FrameReadBack::finish() {
    FrameImages f{imageOf(color_), imageOf(visibility_), imageOf(receivers_), {}};
    if (motion_.pending()) { // only a frame that wrote the motion target started its copy
        f.motion = imageOf(motion_);
        motionToImageRows(f.motion);
    }
    return f;
}

ByteImage visibilityToGrey(const FloatImage& v) {
    ByteImage out{v.width, v.height, 4, std::vector<std::uint8_t>(v.data.size() * 4)};
    for (size_t i = 0; i < v.data.size(); ++i) {
        const float c = std::clamp(v.data[i], 0.0f, 1.0f);
        const auto g = static_cast<std::uint8_t>(std::lround(c * 255.0f));
        out.data[i * 4] = out.data[i * 4 + 1] = out.data[i * 4 + 2] = g;
        out.data[i * 4 + 3] = 255;
    }
    return out;
}

CapturePaths capturePaths(const std::filesystem::path& dir, const std::string& stem) {
    return {dir / (stem + ".png"), dir / (stem + ".visibility.png"), dir / (stem + ".exr")};
}

CapturePaths writeFrame(const FrameImages& frame, const std::filesystem::path& dir,
                        const std::string& stem) {
    requireFinite(frame.color, stem + " colour");
    requireFinite(frame.visibility, stem + " visibility");
    const CapturePaths paths = capturePaths(dir, stem);
    writePng(paths.png, toSrgb8(frame.color));
    writePng(paths.visibilityPng, visibilityToGrey(frame.visibility));
    const size_t n = frame.visibility.data.size();
    std::vector<ExrChannel> channels{
        {"R", {}}, {"G", {}}, {"B", {}}, {"A", {}}, {"visibility", frame.visibility.data}};
    if (!frame.receivers.data.empty()) channels.push_back({"receiver", frame.receivers.data});
    for (int c = 0; c < 4; ++c) {
        channels[static_cast<size_t>(c)].values.resize(n);
        for (size_t i = 0; i < n; ++i)
            channels[static_cast<size_t>(c)].values[i] =
                frame.color.data[i * 4 + static_cast<size_t>(c)];
    }
    writeExr(paths.exr, frame.color.width, frame.color.height, channels);
    return paths;
}

} // namespace fl
