// The floodlight binary with the baseline methods (pcf, pcss, reference): they render, and their
// options reject bad values with a usage error naming the option.

#include "CliRun.h"
#include "TestPaths.h"

#include <io/ImageIO.h>
#include <renderer/methods/ShadowMethod.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <sys/wait.h>

namespace fl::test {
namespace {

Outcome run(const std::string& args) {
    return runCommand(std::string(FLOODLIGHT_BINARY) + " " + args);
}

TEST(BaselinesCli, EachBaselineRendersWithItsPhases) {
    const auto dir = outputDir("cli_baselines");
    struct Case {
        const char* args;
        const char* phase; // printed by the timer
    };
    for (const Case& c :
         {Case{"--method pcf --pcf-kernel 5", "pcf filter"},
          Case{"--method pcss --pcss-preset 32/64 --shadow-map tsm", "blocker search+filter"},
          Case{"--method reference --reference-samples 4 --reference-map-size 256",
               "reference maps"},
          Case{"--method raytrace --raytrace-samples 4", "raytrace rays"},
          Case{"--method raytrace --raytrace-samples 4 --terminator-offset off",
               "raytrace rays"}}) {
        const Outcome r =
            run(std::string("render --width 64 --height 48 --shadow-map-size 256 ") +
                "--light-radius 1.5 " + c.args + " --out " + dir.string() + " --name f");
        ASSERT_EQ(r.code, 0) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.phase), std::string::npos) << c.args << "\n" << r.output;
        int w = 0, h = 0;
        for (const ExrChannel& ch : readExr(dir / "f.exr", w, h))
            for (float v : ch.values) ASSERT_TRUE(std::isfinite(v)) << c.args << " " << ch.name;
        EXPECT_EQ(w, 64);
        EXPECT_EQ(h, 48);
    }
}

TEST(BaselinesCli, BadBaselineOptionsAreUsageErrors) {
    for (const char* args :
         {"--pcf-kernel 0", "--pcf-kernel 16", "--pcf-kernel x", "--pcss-preset 8/8",
          "--pcss-preset 16", "--reference-samples 0", "--reference-samples -3",
          "--reference-map-size 8", "--reference-map-size 100000", "--raytrace-samples 0",
          "--raytrace-samples 16385", "--raytrace-samples many", "--terminator-offset maybe",
          "--terminator-offset 1"}) {
        // Each with its own method (an option of another method is a usage error by itself).
        const std::string a(args);
        const std::string method =
            a.find("pcf") != std::string::npos    ? "pcf"
            : a.find("pcss") != std::string::npos ? "pcss"
            : a.find("raytrace") != std::string::npos || a.find("terminator") != std::string::npos
                ? "raytrace"
                : "reference";
        const Outcome r = run("render --method " + method + " " + a + " --out " +
                              outputDir("cli_baselines").string());
        EXPECT_EQ(r.code, 2) << args << "\n" << r.output;
        const std::string option = std::string(args).substr(0, std::string(args).find(' '));
        EXPECT_NE(r.output.find(option), std::string::npos) << args << "\n" << r.output;
    }
}

// A method option given to a method that does not take it is a usage error naming the option,
// for every method of the table but the one that takes it (--pcf-kernel: pcf).
TEST(BaselinesCli, AnOptionOfAnotherMethodIsAUsageError) {
    int checked = 0;
    for (const MethodDescriptor& m : methodTable()) {
        if (m.takesFlag("--pcf-kernel")) continue;
        const std::string args = "--method " + std::string(m.name) + " --pcf-kernel 5";
        // Small, so that a method that wrongly accepts it still ends quickly.
        const Outcome r = run("render --width 16 --height 16 --shadow-map-size 64 " + args +
                              " --out " + outputDir("cli_baselines").string() + " --name other");
        EXPECT_EQ(r.code, 2) << args << "\n" << r.output;
        EXPECT_NE(r.output.find("--pcf-kernel"), std::string::npos) << args << "\n" << r.output;
        ++checked;
    }
    EXPECT_GE(checked, 7) << "every method but pcf";
    // pcf itself takes it.
    const Outcome pcf = run("render --width 16 --height 16 --shadow-map-size 64 --method pcf "
                            "--pcf-kernel 5 --out " +
                            outputDir("cli_baselines").string() + " --name pcf5");
    EXPECT_EQ(pcf.code, 0) << pcf.output;
}

} // namespace
} // namespace fl::test
