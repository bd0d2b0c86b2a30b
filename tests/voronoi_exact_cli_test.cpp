// `floodlight voronoi --exact` (issue 31 item 3): 0 error pixels on the CPU and both GL kernels
// with --sites, --points (clustered, collinear, co-circular) and --mask, the same diagram on
// every backend, and bad input: the messages point files get without --exact, and exit 2 for
// what the repair cannot take.

#include "CliRun.h"
#include "TestPaths.h"

#include <io/ImageIO.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>

namespace fl::test {
namespace {

Outcome run(const std::string& args) {
    return runCommand(std::string(FLOODLIGHT_BINARY) + " " + args);
}

// The EXR's channels by name.
std::map<std::string, std::vector<float>> channels(const std::filesystem::path& exr) {
    int w = 0, h = 0;
    std::map<std::string, std::vector<float>> out;
    for (auto& c : readExr(exr, w, h)) out[c.name] = std::move(c.values);
    return out;
}

// The run printed 0 error pixels for the repair, and its EXR agrees: no error texel, and every
// distance equal to the exact one.
void expectExactOutput(const Outcome& r, const std::filesystem::path& exr,
                       const std::string& exactLine) {
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find(exactLine), std::string::npos) << r.output;
    auto ch = channels(exr);
    ASSERT_EQ(ch.count("error"), 1u);
    for (float e : ch["error"]) ASSERT_EQ(e, 0.0f);
    EXPECT_EQ(ch["distance"], ch["exact_distance"]);
}

TEST(VoronoiExactCli, ZeroErrorsOnEveryBackendAndTheSameDiagram) {
    const auto dir = outputDir("cli_voronoi_exact");
    const std::string input = " --sites 2000 --width 128 --height 96 --out " + dir.string() + " ";
    const std::string common = "voronoi --exact" + input;
    const Outcome jfa = run("voronoi" + input + "--backend cpu --name plain");
    ASSERT_EQ(jfa.code, 0) << jfa.output;
    // JFA alone misses here, or the test would prove little.
    EXPECT_NE(jfa.output.find("2000 sites: 15 error pixels"), std::string::npos) << jfa.output;
    std::map<std::string, std::vector<float>> first;
    for (const char* backend :
         {"--backend cpu", "--backend gl --kernel fragment", "--backend gl --kernel compute"}) {
        SCOPED_TRACE(backend);
        const Outcome r = run(common + backend + " --name exact");
        expectExactOutput(r, dir / "exact.exr", "exact 128x96, 2000 sites: 0 error pixels");
        EXPECT_NE(r.output.find("exact repair: site graph of "), std::string::npos) << r.output;
        auto ch = channels(dir / "exact.exr");
        if (first.empty()) first = ch;
        for (const char* name : {"site.x", "site.y", "site.id"}) EXPECT_EQ(ch[name], first[name]);
    }
}

TEST(VoronoiExactCli, PointsAndMasks) {
    const auto dir = outputDir("cli_voronoi_exact");
    const auto points = dir / "hard_points.txt";
    {
        std::ofstream f(points);
        f << "# a cluster, a collinear row and a co-circular ring (x^2 + y^2 = 325 around 60,40)\n";
        for (int i = 0; i < 40; ++i) f << 10 + (i * 7) % 9 << " " << 70 + (i * 5) % 8 << "\n";
        for (int x = 3; x < 120; x += 4) f << x << " 5\n";
        for (int dx = -18; dx <= 18; ++dx)
            for (int dy = -18; dy <= 18; ++dy)
                if (dx * dx + dy * dy == 325) f << 60 + dx << " " << 40 + dy << "\n";
    }
    for (const char* backend : {"--backend cpu", "--backend gl --kernel compute"}) {
        SCOPED_TRACE(backend);
        const Outcome r =
            run("voronoi --exact --width 128 --height 90 --points " + points.string() + " " +
                backend + " --out " + dir.string() + " --name points");
        expectExactOutput(r, dir / "points.exr", "exact 128x90,");
        EXPECT_NE(r.output.find(": 0 error pixels"), std::string::npos) << r.output;
    }
    ByteImage mask{80, 64, 4, std::vector<std::uint8_t>(80 * 64 * 4, 0)};
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 80; ++x) {
            const int dx = x - 30, dy = y - 30, d = dx * dx + dy * dy;
            if ((d < 400 && d > 150) || (x > 70 && y % 9 < 4))
                for (int k = 0; k < 4; ++k) mask.data[(std::size_t(y) * 80 + x) * 4 + k] = 255;
        }
    writePng(dir / "mask.png", mask);
    const Outcome r = run("voronoi --exact --backend gl --mask " + (dir / "mask.png").string() +
                          " --out " + dir.string() + " --name mask");
    expectExactOutput(r, dir / "mask.exr", ": 0 error pixels");
    EXPECT_NE(r.output.find("signed distance transform (JFA + exact repair, CPU): 0 pixels differ"),
              std::string::npos)
        << r.output;
}

TEST(VoronoiExactCli, BadInput) {
    const auto dir = outputDir("cli_voronoi_exact_bad");
    const std::string out = " --out " + dir.string();
    // Point files get the messages they get without --exact (exit 1).
    const auto dup = dir / "dup.txt", nan = dir / "nan.txt", outside = dir / "outside.txt";
    std::ofstream(dup) << "3 4\n5 6\n3 4\n";
    std::ofstream(nan) << "3 4\nnan 6\n";
    std::ofstream(outside) << "10 10\n600 3\n";
    const std::pair<std::filesystem::path, const char*> files[] = {
        {dup, "dup.txt:3: duplicate of the site on line 1"},
        {nan, "nan.txt:2: expected two finite numbers 'x y'"},
        {outside, "site 1"}};
    for (const auto& [file, message] : files) {
        for (const char* exact : {"", " --exact"}) {
            const Outcome r = run("voronoi --backend cpu --width 64 --height 64 --points " +
                                  file.string() + exact + out);
            EXPECT_EQ(r.code, 1) << exact << "\n" << r.output;
            EXPECT_NE(r.output.find(message), std::string::npos) << exact << "\n" << r.output;
        }
    }
    // What the repair cannot take: usage errors (exit 2), one line naming the problem.
    const std::pair<const char*, const char*> refused[] = {
        {"--float-sites", "--exact: sub-pixel sites (--float-sites) cannot be repaired exactly"},
        {"--compare", "--exact repairs one plan's flood and --compare runs every plan"},
        {"--plan flood:3", "--exact: plan flood:3 reaches 3 texels, fewer than the 63 of this "
                           "grid"}};
    for (const auto& [option, message] : refused) {
        const Outcome r = run(std::string("voronoi --backend cpu --width 64 --height 64 --exact ") +
                              option + out + " --name refused");
        EXPECT_EQ(r.code, 2) << option << "\n" << r.output;
        EXPECT_NE(r.output.find(message), std::string::npos) << option << "\n" << r.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "refused.png")) << option;
    }
}

} // namespace
} // namespace fl::test
