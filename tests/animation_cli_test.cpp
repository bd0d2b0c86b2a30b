// --time and --animation on the command line (issue 15, item 2): the assimp samples simple_skin
// (a skinned, animated bar) and AnimatedMorphCube (animated morph weights) render differently at
// two times; a bad time or an animation the scene does not have is a usage error.

#include "CliRun.h"
#include "TestPaths.h"

#include <io/ImageIO.h>

#include <gtest/gtest.h>

#include <cmath>

namespace fl::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSamples = "/usr/share/assimp/models/glTF2";
const fs::path kSimpleSkin = kSamples / "simple_skin/simple_skin.gltf";
const fs::path kMorphCube =
    kSamples / "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf";

struct Frame {
    Outcome outcome;
    std::vector<float> visibility, red;
};

Frame render(const fs::path& scene, const std::string& name, const std::string& flags) {
    const fs::path dir = outputDir("animation_cli");
    Frame f;
    f.outcome = runCommand(std::string(FLOODLIGHT_BINARY) + " render --scene " + scene.string() +
                           " --width 96 --height 96 --shadow-map-size 512 --out " + dir.string() +
                           " --name " + name + " " + flags);
    if (f.outcome.code != 0) return f;
    int w = 0, h = 0;
    for (ExrChannel& c : readExr(dir / (name + ".exr"), w, h)) {
        if (c.name == "visibility") f.visibility = std::move(c.values);
        if (c.name == "R") f.red = std::move(c.values);
    }
    return f;
}

// Share of pixels whose value differs by more than 0.05.
double changed(const std::vector<float>& a, const std::vector<float>& b) {
    EXPECT_EQ(a.size(), b.size());
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) n += std::abs(a[i] - b[i]) > 0.05f;
    return a.empty() ? 0.0 : double(n) / double(a.size());
}

TEST(AnimationCli, SimpleSkinMovesItsShadowOverTime) {
    if (!fs::exists(kSimpleSkin)) GTEST_SKIP() << kSimpleSkin << " (assimp-testmodels) missing";
    const Frame a = render(kSimpleSkin, "skin_t0", "--time 0");
    // Its one channel turns the upper joint 90 degrees about z at t = 1 (and back to 0 at 2.5).
    const Frame b = render(kSimpleSkin, "skin_t1", "--time 1");
    ASSERT_EQ(a.outcome.code, 0) << a.outcome.output;
    ASSERT_EQ(b.outcome.code, 0) << b.outcome.output;
    // The bar bends: its picture and its shadow change.
    EXPECT_GT(changed(a.red, b.red), 0.005);
    EXPECT_GT(changed(a.visibility, b.visibility), 0.002);
    // Without its animation the bar stands at rest at every time.
    const Frame still = render(kSimpleSkin, "skin_none", "--time 1 --animation none");
    ASSERT_EQ(still.outcome.code, 0) << still.outcome.output;
    const Frame rest = render(kSimpleSkin, "skin_none0", "--time 0 --animation none");
    EXPECT_EQ(changed(still.red, rest.red), 0.0);
}

TEST(AnimationCli, MorphCubeChangesShapeOverTime) {
    if (!fs::exists(kMorphCube)) GTEST_SKIP() << kMorphCube << " (assimp-testmodels) missing";
    const Frame a = render(kMorphCube, "morph_t0", "--time 0");
    const Frame b = render(kMorphCube, "morph_t1", "--time 1 --animation Square");
    ASSERT_EQ(a.outcome.code, 0) << a.outcome.output;
    ASSERT_EQ(b.outcome.code, 0) << b.outcome.output;
    EXPECT_GT(changed(a.red, b.red), 0.005);
}

TEST(AnimationCli, CompareAdvancesTheClipPerFrame) {
    if (!fs::exists(kSimpleSkin)) GTEST_SKIP() << kSimpleSkin << " (assimp-testmodels) missing";
    const fs::path dir = outputDir("animation_cli") / "compare";
    const Outcome o =
        runCommand(std::string(FLOODLIGHT_BINARY) + " compare --scene " + kSimpleSkin.string() +
                   " --method jfa-l --frames 3 --animation-fps 2 --width 64 "
                   "--height 64 --shadow-map-size 256 --out " +
                   dir.string());
    ASSERT_EQ(o.code, 0) << o.output;
    EXPECT_TRUE(fs::exists(dir / "frames.csv"));
    const Outcome bad =
        runCommand(std::string(FLOODLIGHT_BINARY) + " compare --scene " + kSimpleSkin.string() +
                   " --frames 2 --animation-fps -1 --out " + dir.string());
    EXPECT_EQ(bad.code, 2) << bad.output;
}

TEST(AnimationCli, BadTimeOrUnknownAnimationIsAUsageError) {
    if (!fs::exists(kSimpleSkin)) GTEST_SKIP() << kSimpleSkin << " (assimp-testmodels) missing";
    for (const char* time : {"-1", "nan", "inf", "2e6"}) {
        const Frame f = render(kSimpleSkin, "bad_time", std::string("--time ") + time);
        EXPECT_EQ(f.outcome.code, 2) << time << ": " << f.outcome.output;
        EXPECT_NE(f.outcome.output.find("--time"), std::string::npos) << f.outcome.output;
    }
    const Frame f = render(kSimpleSkin, "bad_animation", "--animation walk");
    EXPECT_EQ(f.outcome.code, 2) << f.outcome.output;
    EXPECT_NE(f.outcome.output.find("--animation walk: not all, none, or one of the scene's 1 "
                                    "animation(s)"),
              std::string::npos)
        << f.outcome.output;
    EXPECT_EQ(render(kSimpleSkin, "bad_index", "--animation 1").outcome.code, 2);
}

} // namespace
} // namespace fl::test
