// `floodlight voronoi3d` (issue 31 item 2): the error voxels it prints are the library's count
// for the same sites, GL and CPU agree, the pictures and the stacked EXR agree with the count,
// and bad input gets one message naming file, line and problem (exit 1) or the limit it broke
// (usage, exit 2), with no output written.

#include "CliRun.h"
#include "TestPaths.h"

#include <io/ImageIO.h>
#include <jfa/Jfa3d.h>

#include <gtest/gtest.h>

#include <fstream>
#include <map>

namespace fl::test {
namespace {

Outcome run(const std::string& args) {
    return runCommand(std::string(FLOODLIGHT_BINARY) + " voronoi3d " + args);
}

std::filesystem::path writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path) << text;
    return path;
}

bool contains(const Outcome& r, const std::string& text) {
    return r.output.find(text) != std::string::npos;
}

// Files in `dir` whose name starts with `stem` (temporaries included: they start with '.').
int filesNamed(const std::filesystem::path& dir, const std::string& stem) {
    int n = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        n += name.rfind(stem, 0) == 0 || name.find(".tmp") != std::string::npos;
    }
    return n;
}

TEST(Voronoi3dCli, PrintsTheLibrarysErrorCountAndGlEqualsCpu) {
    const auto dir = outputDir("cli_voronoi3d");
    std::filesystem::remove_all(dir / "v.exr");
    // The slice-by-slice variant misses voxels here (Fig. 4.17), so the count is not 0 by luck.
    const jfa::Extent3 e{32, 32, 32};
    const std::vector<jfa::Site3> sites = jfa::randomSites3d(300, e, 3);
    const auto exact = jfa::exactSquaredDistances3d(sites, e);
    const jfa::SiteGrid3 grid = jfa::floodVariant3d(*jfa::findFlood3dVariant("slices"), sites, e);
    const std::int64_t errors = jfa::countErrors3d(grid, sites, exact, "x").erroneous;
    ASSERT_GT(errors, 0);

    const Outcome r = run("--size 32 --sites 300 --seed 3 --backend both --variant slices --out " +
                          dir.string() + " --name v");
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_TRUE(contains(r, "GL == CPU: identical, voxel for voxel")) << r.output;
    EXPECT_TRUE(contains(r, "slice JFA on 32x32x32, 300 sites: " + std::to_string(errors) +
                                " error voxels of 32768"))
        << r.output;
    for (const char* file : {"v.z4.png", "v.z12.png", "v.z20.png", "v.z28.png", "v.montage.png"})
        EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;

    // The EXR: 32 x 32*32, its error channel counts the same voxels, and a distance equals the
    // exact one exactly where no error is marked (and exceeds it where one is).
    int w = 0, h = 0;
    std::map<std::string, std::vector<float>> ch;
    for (auto& c : readExr(dir / "v.exr", w, h)) ch[c.name] = std::move(c.values);
    ASSERT_EQ(w, 32);
    ASSERT_EQ(h, 32 * 32);
    std::int64_t marked = 0;
    for (std::size_t i = 0; i < ch["error"].size(); ++i) {
        const bool error = ch["error"][i] != 0.0f;
        marked += error;
        if (error)
            ASSERT_GT(ch["distance"][i], ch["exact_distance"][i]) << i;
        else
            ASSERT_EQ(ch["distance"][i], ch["exact_distance"][i]) << i;
    }
    EXPECT_EQ(marked, errors);
    EXPECT_EQ(filesNamed(dir, "."), 0) << "a temporary was left";
}

TEST(Voronoi3dCli, OneSiteFromAFileHasNoErrorVoxels) {
    const auto dir = outputDir("cli_voronoi3d");
    const auto points = writeText(dir / "one.txt", "# one site\n\n3 14 9\n");
    const Outcome r =
        run("--size 16 --points " + points.string() +
            " --backend gl --variant jfa+1 --slices 9,0 --out " + dir.string() + " --name one");
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_TRUE(contains(r, "3D JFA+1 on 16x16x16, 1 site: 0 error voxels of 4096")) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "one.z9.png"));
    EXPECT_TRUE(std::filesystem::exists(dir / "one.z0.png"));
}

TEST(Voronoi3dCli, BadPointFilesNameFileLineAndProblem) {
    const auto dir = outputDir("cli_voronoi3d_bad");
    const std::pair<std::string, std::string> cases[] = {
        {"1 2 3\n4 5\n", ":2: expected three integers 'x y z'"},
        {"1 2 3\n5 40 1\n", ":2: y must be an integer in [0, 15], got '40' (the grid is 16^3)"},
        {"nan 2 3\n", ":1: x must be an integer in [0, 15], got 'nan'"},
        {"1.5 2 3\n", ":1: x must be an integer in [0, 15]"},
        {"# nothing\n", ": no sites"},
        {"1 2 3\n\n1 2 3\n", ":3: duplicate of the site on line 1"},
    };
    int k = 0;
    for (const auto& [text, message] : cases) {
        SCOPED_TRACE(text);
        const auto file = writeText(dir / ("bad" + std::to_string(k++) + ".txt"), text);
        const Outcome r = run("--size 16 --backend cpu --points " + file.string() + " --out " +
                              dir.string() + " --name out");
        EXPECT_EQ(r.code, 1) << r.output;
        EXPECT_TRUE(contains(r, "--points " + file.string() + message)) << r.output;
    }
    EXPECT_EQ(filesNamed(dir, "out"), 0);
}

TEST(Voronoi3dCli, UsageErrorsNameTheLimit) {
    const auto dir = outputDir("cli_voronoi3d_bad");
    const std::pair<std::string, std::string> cases[] = {
        {"--size 600", "--size: must be an integer in [1, 512], got '600'"},
        {"--size 4 --sites 65", "--sites: 65 distinct sites do not fit a 4^3 grid of 64 voxels"},
        {"--size 16 --slices 3,16", "--slices: slice 16 is outside the 16^3 grid (0..15)"},
        {"--size 16 --variant jfa3", "--variant: jfa3 not in {"},
        {"--size 16 --runs 0", "--runs: must be an integer in [1, 100], got '0'"},
    };
    for (const auto& [args, message] : cases) {
        SCOPED_TRACE(args);
        const Outcome r = run(args + " --backend cpu --out " + dir.string() + " --name usage");
        EXPECT_EQ(r.code, 2) << r.output;
        EXPECT_TRUE(contains(r, message)) << r.output;
    }
    EXPECT_EQ(filesNamed(dir, "usage"), 0);
}

} // namespace
} // namespace fl::test
