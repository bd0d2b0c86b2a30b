// `floodlight render --overlay NAME`: writes the overlay picture beside the frame, rejects an
// unknown name with one clear message.

#include "CliRun.h"
#include "TestPaths.h"

#include <io/ImageIO.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <sys/wait.h>

namespace fl::test {
namespace {

Outcome run(const std::string& args) {
    return runCommand(std::string(FLOODLIGHT_BINARY) + " " + args);
}

TEST(OverlayCli, RenderWritesTheOverlayPicture) {
    const auto dir = outputDir("overlay_cli");
    const auto png = dir / "f.overlay-voronoi.png";
    std::filesystem::remove(png);
    const Outcome r = run("render --width 64 --height 48 --shadow-map-size 128 --method jfa-l "
                          "--overlay voronoi --variant 1 --name f --out " +
                          dir.string());
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("Voronoi diagram of the"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("JFA+1"), std::string::npos) << r.output;
    const ByteImage img = readPng(png);
    EXPECT_EQ(img.width, 64);
    EXPECT_EQ(img.height, 48);
}

TEST(OverlayCli, UnknownOverlayIsOneClearError) {
    const auto dir = outputDir("overlay_cli");
    const Outcome r = run("render --width 32 --height 32 --overlay bogus --out " + dir.string());
    EXPECT_NE(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("unknown overlay 'bogus'"), std::string::npos) << r.output;
}

TEST(OverlayCli, HardFrameSaysWhatTheOverlayNeeds) {
    const auto dir = outputDir("overlay_cli");
    const Outcome r = run("render --width 32 --height 32 --shadow-map-size 64 --overlay seeds "
                          "--name h --out " +
                          dir.string());
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("needs a soft method"), std::string::npos) << r.output;
}

} // namespace
} // namespace fl::test
