#include <renderer/io/Capture.h>

#include <algorithm>
#include <cmath>

namespace fl {

FrameImages readFrame(const Renderer& renderer) {
    FloatImage motion; // empty when the frame wrote no motion target
    if (renderer.motion()) motion = readTexture(*renderer.motion(), 4);
    // The target holds GL window coordinates (y up from the bottom edge); the images here have
    // row 0 at the top.
    for (std::size_t i = 1; i < motion.data.size(); i += 4)
        motion.data[i] = static_cast<float>(motion.height) - motion.data[i];
    return {readTexture(renderer.color(), 4), readTexture(renderer.visibility(), 1),
            readTexture(renderer.receivers(), 1), std::move(motion)};
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

CapturePaths writeFrame(const FrameImages& frame, const std::filesystem::path& dir,
                        const std::string& stem) {
    requireFinite(frame.color, stem + " colour");
    requireFinite(frame.visibility, stem + " visibility");
    CapturePaths paths{dir / (stem + ".png"), dir / (stem + ".visibility.png"),
                       dir / (stem + ".exr")};
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
