// Capture along a time axis (issue 15, item 2): a script's "animation" clip poses frame i at
// start + i / fps, so the skinned bar of assimp's simple_skin moves from frame to frame while the
// camera stands still; an animation the scene does not have is refused with the field named.

#include "CliRun.h"
#include "TestPaths.h"

#include <io/ImageIO.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <unistd.h>

namespace fl::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSimpleSkin = "/usr/share/assimp/models/glTF2/simple_skin/simple_skin.gltf";

// A still camera on the bar; frames at t = 0, 0.5, 1 (the bar turns 90 degrees by t = 1).
std::string script(const std::string& animation) {
    return R"({"scene": ")" + kSimpleSkin.string() + R"(",
  "camera": {"frames": 3, "keys": [{"eye": [3, 3, 4], "target": [0, 1, 0]},
                                    {"eye": [3, 3, 4], "target": [0, 1, 0]}]},
  "resolutions": [[64, 64]],
  "shadowMap": {"size": 256},
  "reference": {"kind": "raytrace", "samples": 4},
  "methods": ["hard"],
  "animation": )" +
           animation + "}";
}

fs::path writeScript(const std::string& name, const std::string& text) {
    const fs::path dir = outputDir("capture_animation") / std::to_string(::getpid());
    fs::create_directories(dir);
    std::ofstream(dir / name) << text;
    return dir / name;
}

std::vector<float> visibility(const fs::path& exr) {
    int w = 0, h = 0;
    for (ExrChannel& c : readExr(exr, w, h))
        if (c.name == "visibility") return std::move(c.values);
    ADD_FAILURE() << exr << " has no visibility";
    return {};
}

TEST(CaptureAnimation, FramesFollowTheClip) {
    if (!fs::exists(kSimpleSkin)) GTEST_SKIP() << kSimpleSkin << " (assimp-testmodels) missing";
    const fs::path s = writeScript("clip.json", script(R"({"start": 0, "fps": 2})"));
    const fs::path out = s.parent_path() / "clip";
    const Outcome o = runCommand(std::string(FLOODLIGHT_BINARY) + " capture " + s.string() +
                                 " --out " + out.string());
    ASSERT_EQ(o.code, 0) << o.output;
    const fs::path frames = out / "frames" / "64x64" / "hard";
    const std::vector<float> a = visibility(frames / "frame_00000.exr");
    const std::vector<float> b = visibility(frames / "frame_00002.exr");
    ASSERT_EQ(a.size(), b.size());
    std::size_t changed = 0;
    for (std::size_t i = 0; i < a.size(); ++i) changed += std::abs(a[i] - b[i]) > 0.5f;
    EXPECT_GT(changed, 10u) << "the bar's shadow moves with the clip";

    // fps 0: every frame at `start`; the same still camera gives the same frames.
    const fs::path still = writeScript("still.json", script(R"({"start": 1})"));
    const fs::path stillOut = still.parent_path() / "still";
    ASSERT_EQ(runCommand(std::string(FLOODLIGHT_BINARY) + " capture " + still.string() + " --out " +
                         stillOut.string())
                  .code,
              0);
    const fs::path stillFrames = stillOut / "frames" / "64x64" / "hard";
    EXPECT_EQ(visibility(stillFrames / "frame_00000.exr"),
              visibility(stillFrames / "frame_00002.exr"));
    EXPECT_EQ(visibility(stillFrames / "frame_00000.exr"), b) << "t = 1 either way";
}

TEST(CaptureAnimation, UnknownAnimationIsRefusedWithTheFieldNamed) {
    if (!fs::exists(kSimpleSkin)) GTEST_SKIP() << kSimpleSkin << " (assimp-testmodels) missing";
    const fs::path s = writeScript("walk.json", script(R"({"name": "walk"})"));
    const Outcome o = runCommand(std::string(FLOODLIGHT_BINARY) + " capture " + s.string() +
                                 " --out " + (s.parent_path() / "walk").string());
    EXPECT_NE(o.code, 0);
    EXPECT_NE(o.output.find("animation.name: animation walk: not all, none"), std::string::npos)
        << o.output;
}

} // namespace
} // namespace fl::test
