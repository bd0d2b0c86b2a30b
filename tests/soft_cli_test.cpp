// The floodlight binary's soft-shadow options and `compare` (issue 5): what they write, and one
// clear message with a non-zero exit for each bad input.

#include "CliRun.h"
#include "TestPaths.h"

#include <io/ImageIO.h>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace fl::test {
namespace {

Outcome run(const std::string& args) {
    return runCommand(std::string(FLOODLIGHT_BINARY) + " " + args);
}

std::filesystem::path freshDir(const std::string& name) {
    const auto dir = outputDir(name);
    for (const auto& e : std::filesystem::directory_iterator(dir)) std::filesystem::remove_all(e);
    return dir;
}

std::vector<float> exrChannel(const std::filesystem::path& file, const std::string& name) {
    int w = 0, h = 0;
    for (ExrChannel& c : readExr(file, w, h))
        if (c.name == name) return std::move(c.values);
    return {};
}

// Radius 0 is a point light: every soft method must reproduce the hard shadows exactly.
TEST(SoftCli, ZeroLightRadiusRendersTheHardShadows) {
    const auto dir = freshDir("soft_cli_zero");
    const std::string common = "render --width 64 --height 48 --shadow-map-size 256 --out " +
                               dir.string() + " --light-radius 0 ";
    ASSERT_EQ(run(common + "--method hard --name hard").code, 0);
    const std::vector<float> hard = exrChannel(dir / "hard.exr", "visibility");
    ASSERT_EQ(hard.size(), 64u * 48u);
    for (const char* m : {"jfa-l", "flood-l", "jfa-e", "flood-e"}) {
        const Outcome r = run(common + "--method " + m + " --name " + m);
        ASSERT_EQ(r.code, 0) << m << "\n" << r.output;
        EXPECT_EQ(exrChannel(dir / (std::string(m) + ".exr"), "visibility"), hard) << m;
    }
}

TEST(SoftCli, BadLightRadiusIsAUsageError) {
    for (const char* v : {"-1", "nan", "inf", "wide"}) {
        const Outcome r = run(std::string("render --method jfa-l --light-radius ") + v + " --out " +
                              outputDir("soft_cli").string());
        EXPECT_EQ(r.code, 2) << v << "\n" << r.output;
        EXPECT_NE(r.output.find("--light-radius: must be a finite number in [0, 1e+15]"),
                  std::string::npos)
            << r.output;
    }
}

// Pass counts: 0 or more than the flag's range are usage errors; within the flag's range but
// beyond log2 of the grid (the shadow map for -l, the frame for -e) an input error naming the
// valid range. --full-jfa takes the largest count.
TEST(SoftCli, PassCountsOutsideTheGridAreRejected) {
    const std::string out =
        " --width 32 --height 32 --shadow-map-size 256 --out " + outputDir("soft_cli").string();
    EXPECT_EQ(run("render --method jfa-l --jfa-passes 0" + out).code, 2);
    Outcome r = run("render --jfa-passes 9 --method jfa-l" + out);
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("outside [1, 8] for a 256^2 shadow map"), std::string::npos)
        << r.output;
    r = run("render --jfa-passes 6 --method jfa-e" + out);
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("outside [1, 5] for a 32x32 frame"), std::string::npos) << r.output;
    for (const char* m : {"jfa-l", "jfa-e"}) {
        r = run(std::string("render --full-jfa --light-radius 1 --method ") + m + out);
        EXPECT_EQ(r.code, 0) << m << "\n" << r.output;
    }
}

// --auto-passes (issue 30 item 2): both rules render; another word is a usage error naming the
// choices.
TEST(SoftCli, AutoPassRuleIsAChoice) {
    const std::string out =
        " --width 48 --height 48 --shadow-map-size 256 --light-radius 1 --out " +
        outputDir("soft_cli").string();
    for (const char* rule : {"measured", "geometric"}) {
        const Outcome r = run(std::string("render --method jfa-e --auto-passes ") + rule + out);
        EXPECT_EQ(r.code, 0) << rule << "\n" << r.output;
    }
    const Outcome r = run("render --method jfa-e --auto-passes sometimes" + out);
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("must be one of measured,geometric"), std::string::npos) << r.output;
}

TEST(SoftCli, CompareWritesCsvSummaryAndTheWorstFrame) {
    const auto dir = freshDir("soft_cli_compare");
    const Outcome r = run("compare --method jfa-l --frames 3 --width 64 --height 64 "
                          "--shadow-map-size 256 --light-radius 1.5 --out " +
                          dir.string());
    ASSERT_EQ(r.code, 0) << r.output;
    std::ifstream csv(dir / "frames.csv");
    std::string header, line;
    ASSERT_TRUE(std::getline(csv, header));
    // Each lane's flood: passes chosen (auto by default) and the band's share of the texels.
    for (const char* column : {"method_jfa_passes", "method_active_share", "reference_jfa_passes",
                               "reference_active_share"})
        EXPECT_NE(header.find(column), std::string::npos) << column << " in " << header;
    int rows = 0;
    while (std::getline(csv, line)) ++rows;
    EXPECT_EQ(rows, 3) << "one row per frame";
    std::ifstream js(dir / "summary.json");
    const nlohmann::json j = nlohmann::json::parse(js);
    EXPECT_EQ(j["passes"], "auto");
    for (const char* lane : {"method", "reference"}) {
        ASSERT_TRUE(j["flood"].contains(lane)) << j.dump();
        EXPECT_GE(j["flood"][lane]["medianPasses"].get<int>(), 1) << lane;
        const double share = j["flood"][lane]["medianActiveShare"].get<double>();
        EXPECT_GT(share, 0.0) << lane;
        EXPECT_LT(share, 1.0) << lane << ": banded by default";
    }
    EXPECT_EQ(j["method"], "jfa-l");
    EXPECT_EQ(j["reference"], "flood-l");
    EXPECT_EQ(j["frames"], 3);
    const int worst = j["worstFrame"];
    ASSERT_GE(worst, 0);
    ASSERT_LT(worst, 3);
    const std::string stem = "worst_frame_" + std::to_string(worst);
    const ByteImage pair = readPng(dir / (stem + ".png"));
    EXPECT_GE(pair.width, 3 * 64) << "JFA, standard flooding and the difference side by side";
    for (const char* ch : {"method", "reference", "difference"}) {
        const std::vector<float> v = exrChannel(dir / (stem + ".exr"), ch);
        ASSERT_EQ(v.size(), 64u * 64u) << ch;
        for (float x : v) ASSERT_TRUE(std::isfinite(x)) << ch;
    }
    for (const auto& e : std::filesystem::directory_iterator(dir))
        EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
}

TEST(SoftCli, CompareNeedsAJumpFloodingMethod) {
    const auto dir = freshDir("soft_cli_compare_bad");
    const Outcome r =
        run("compare --method hard --frames 2 --width 32 --height 32 --out " + dir.string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("no standard-flooding reference"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "summary.json"));
}

TEST(SoftCli, CompareWithAMissingPathFileWritesNothing) {
    const auto dir = freshDir("soft_cli_compare_path");
    const Outcome r = run("compare --method jfa-e --frames 2 --width 32 --height 32 --path " +
                          (dir / "nope.json").string() + " --out " + dir.string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("nope.json"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "summary.json"));
    EXPECT_FALSE(std::filesystem::exists(dir / "frames.csv"));
}

} // namespace
} // namespace fl::test
