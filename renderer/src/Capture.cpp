#include <renderer/Capture.h>

namespace fl {

FrameImages readFrame(const Renderer& renderer) {
    return {readTexture(renderer.color(), 4), readTexture(renderer.visibility(), 1)};
}

CapturePaths writeFrame(const FrameImages& frame, const std::filesystem::path& dir,
                        const std::string& stem) {
    requireFinite(frame.color, stem + " colour");
    requireFinite(frame.visibility, stem + " visibility");
    CapturePaths paths{dir / (stem + ".png"), dir / (stem + ".exr")};
    writePng(paths.png, toSrgb8(frame.color));
    const size_t n = frame.visibility.data.size();
    std::vector<ExrChannel> channels{{"R", {}}, {"G", {}}, {"B", {}}, {"A", {}},
                                     {"visibility", frame.visibility.data}};
    for (int c = 0; c < 4; ++c) {
        channels[static_cast<size_t>(c)].values.resize(n);
        for (size_t i = 0; i < n; ++i)
            channels[static_cast<size_t>(c)].values[i] = frame.color.data[i * 4 + static_cast<size_t>(c)];
    }
    writeExr(paths.exr, frame.color.width, frame.color.height, channels);
    return paths;
}

} // namespace fl
