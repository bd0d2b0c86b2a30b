// `floodlight delaunay` as a user runs it: the sample inputs triangulate and pass --check, the
// printed counts match the files written, --steps writes every picture, and bad input or flags
// give one clear message and exit code 1 (input) or 2 (usage).

#include "CliRun.h"
#include "TestPaths.h"

#include <geometry/PointIO.h>
#include <geometry/Triangulation.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <sys/wait.h>

namespace fl::test {
namespace {

Outcome run(const std::string& args, const std::string& env = {}) {
    return runCommand(env + " " + std::string(FLOODLIGHT_BINARY) + " " + args);
}

std::string sample(const char* name) {
    return (dataDir().parent_path() / "examples" / "points" / name).string();
}

// The number after "label: " in the command's output, or -1.
long printed(const std::string& output, const std::string& label) {
    std::smatch m;
    if (!std::regex_search(output, m, std::regex("\n  " + label + ": ([0-9]+)"))) return -1;
    return std::stol(m[1]);
}

// Triangles in a Triangle .ele file: the header's count, checked against the lines that follow.
long eleTriangles(const std::filesystem::path& path) {
    std::ifstream in(path);
    long count = -1, lines = 0;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (count < 0)
            std::istringstream(line) >> count;
        else
            ++lines;
    }
    return lines == count ? count : -2;
}

std::filesystem::path freshDir(const std::string& name) {
    const auto dir = outputDir(name);
    for (const auto& e : std::filesystem::directory_iterator(dir)) std::filesystem::remove_all(e);
    return dir;
}

std::filesystem::path writeText(const std::string& name, const std::string& text) {
    const auto p = outputDir("delaunay_cli") / name;
    std::ofstream(p) << text;
    return p;
}

TEST(DelaunayCli, HelpExitsZero) {
    const Outcome r = run("delaunay --help");
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("--texture"), std::string::npos) << r.output;
}

TEST(DelaunayCli, SampleTriangulatesChecksAndWritesEveryFormat) {
    const auto dir = freshDir("delaunay_cli_out");
    const Outcome r =
        run("delaunay " + sample("uniform200.node") + " --check --out " + (dir / "u").string());
    ASSERT_EQ(r.code, 0) << r.output;
    for (const char* step : {"G1", "G2", "G3", "G4", "G5", "G6", "C1", "C2", "C3", "C4", "total"})
        EXPECT_NE(r.output.find("  " + std::string(step)), std::string::npos) << step;
    EXPECT_NE(r.output.find("check: ok"), std::string::npos) << r.output;
    EXPECT_EQ(printed(r.output, "points"), 200) << r.output;
    EXPECT_EQ(printed(r.output, "duplicates"), 0) << r.output;

    // Every Delaunay triangulation of a point set has the same number of triangles.
    const auto points = geom::readPoints(sample("uniform200.node"));
    const long expected = long(geom::delaunayReference(points).triangleCount());
    EXPECT_EQ(printed(r.output, "triangles"), expected) << r.output;
    EXPECT_EQ(eleTriangles(dir / "u.ele"), expected);
    EXPECT_EQ(geom::readPoints(dir / "u.node"), points);
    for (const char* ext : {".node", ".ele", ".obj", ".svg"})
        EXPECT_TRUE(std::filesystem::exists(dir / (std::string("u") + ext))) << ext;
}

TEST(DelaunayCli, DegenerateSamplesPassTheCheck) {
    // A grid (co-circular squares), a dense Gaussian (missing sites) and a circle with its centre.
    for (const char* name : {"grid10x10.txt", "gaussian1000.xy", "circle64.txt"}) {
        const Outcome r = run("delaunay " + sample(name) + " --check --texture 64");
        EXPECT_EQ(r.code, 0) << name << "\n" << r.output;
        EXPECT_NE(r.output.find("check: ok"), std::string::npos) << name << "\n" << r.output;
    }
}

TEST(DelaunayCli, DuplicatesAreCountedAndLeftOut) {
    const auto p = writeText("dups.txt", "0 0\n1 0\n0 1\n1 0\n1 1\n0 0\n");
    const auto dir = freshDir("delaunay_cli_dups");
    const Outcome r =
        run("delaunay " + p.string() + " --check --format node --out " + (dir / "d").string());
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_EQ(printed(r.output, "duplicates"), 2) << r.output;
    EXPECT_EQ(printed(r.output, "triangles"), 2) << r.output;
    EXPECT_EQ(eleTriangles(dir / "d.ele"), 2);
    EXPECT_FALSE(std::filesystem::exists(dir / "d.obj")); // --format node: .node + .ele only
}

TEST(DelaunayCli, StepsWritesOnePicturePerStage) {
    const auto dir = freshDir("delaunay_cli_steps");
    const Outcome r = run("delaunay " + sample("gaussian1000.xy") + " --steps " + dir.string());
    ASSERT_EQ(r.code, 0) << r.output;
    std::set<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        names.insert(e.path().filename().string());
        EXPECT_GT(std::filesystem::file_size(e.path()), 200u) << e.path();
    }
    EXPECT_EQ(names, (std::set<std::string>{"01_sites.svg", "02_voronoi.svg", "03_islands.svg",
                                            "04_vertices.svg", "05_mesh.svg", "06_hull.svg",
                                            "07_shifted.svg", "08_missing.svg", "09_flipped.svg"}));
}

TEST(DelaunayCli, BadInputNamesFileAndLine) {
    const std::string data = (dataDir() / "data" / "points").string() + "/";
    const std::pair<std::string, std::string> cases[] = {
        {data + "truncated_header_says_5.node", "truncated_header_says_5.node:"},
        {data + "nan_on_line_3.node", "nan_on_line_3.node:3:"},
        {data + "not_a_number_on_line_2.txt", "not_a_number_on_line_2.txt:2:"},
        {writeText("nan.txt", "0 0\n1 0\nnan 1\n").string(), "nan.txt:3:"},
    };
    for (const auto& [file, where] : cases) {
        const Outcome r = run("delaunay " + file);
        EXPECT_EQ(r.code, 1) << file << "\n" << r.output;
        EXPECT_TRUE(std::regex_search(
            r.output,
            std::regex(std::regex_replace(where, std::regex("\\."), "\\.") + "[0-9]*:? ")))
            << where << "\n"
            << r.output;
    }
}

TEST(DelaunayCli, InputsWithoutATriangulationAreInputErrors) {
    const std::pair<std::filesystem::path, std::string> cases[] = {
        {writeText("two.txt", "0 0\n1 1\n"), "at least 3 distinct points"},
        {writeText("two_distinct.txt", "0 0\n1 1\n0 0\n1 1\n"), "at least 3 distinct points"},
        {writeText("line.txt", "0 0\n1 1\n2 2\n3 3\n-5 -5\n"), "collinear"},
        {writeText("empty.txt", "# nothing\n"), "no points"},
        {outputDir("delaunay_cli") / "does_not_exist.node", "does_not_exist.node"},
        {writeText("points.csv", "0 0\n1 0\n0 1\n"), "points.csv"},
    };
    for (const auto& [file, message] : cases) {
        const Outcome r = run("delaunay " + file.string());
        EXPECT_EQ(r.code, 1) << file << "\n" << r.output;
        EXPECT_NE(r.output.find(message), std::string::npos) << file << "\n" << r.output;
        EXPECT_NE(r.output.find(file.filename().string()), std::string::npos) << r.output;
    }
}

// The bad-input list of issue 8 through the CLI, case by case: exit code 1 with a message that
// names the file and the line (or the problem), or a documented exact result.
TEST(DelaunayCli, BadInputSweepOfTheIssue) {
    const std::string data = (dataDir() / "data" / "points").string() + "/";
    const std::pair<std::string, std::string> rejected[] = {
        {writeText("one.txt", "0 0\n").string(), "at least 3 distinct points"},
        {writeText("all_same.txt", "2 2\n2 2\n2 2\n2 2\n").string(), "at least 3 distinct"},
        {writeText("vertical.txt", "1 0\n1 5\n1 -2\n1 0\n1 7\n").string(), "collinear"},
        {writeText("inf.txt", "0 0\n1 0\n0 1\n-inf 2\n").string(), "inf.txt:4:"},
        {data + "inf_on_line_4.txt", "inf_on_line_4.txt:4:"},
        {data + "overflow_on_line_5.txt", "overflow_on_line_5.txt:5:"},
        {data + "too_few_values_on_line_5.node", "too_few_values_on_line_5.node:5:"},
        {data + "too_many_values_on_line_3.node", "too_many_values_on_line_3.node:3:"},
        {data + "dimension_3_on_line_2.node", "dimension_3_on_line_2.node:"},
        {data + "non_consecutive_index_on_line_4.node", "non_consecutive_index_on_line_4.node:4:"},
        {writeText("cut.node", "4 2 0 0\n0 0 0\n1 1 0\n2 0 1\n3 1").string(), "cut.node:"},
    };
    for (const auto& [file, message] : rejected) {
        const Outcome r = run("delaunay " + file);
        EXPECT_EQ(r.code, 1) << file << "\n" << r.output;
        EXPECT_NE(r.output.find(message), std::string::npos) << file << "\n" << r.output;
        EXPECT_EQ(r.output.find("terminate"), std::string::npos) << r.output; // no crash
    }
    // Documented exact results: duplicates are left out (DuplicatesAreCountedAndLeftOut), and
    // coordinates from 1e-300 to 1e300 triangulate exactly (--check runs the exact checker).
    const auto wide = writeText("wide.txt", "1e-300 0\n1e300 0\n0 1e300\n-1e300 -1e300\n"
                                            "1e-300 1e-300\n-1e-300 2e-300\n5e-301 -1e-300\n");
    const Outcome r = run("delaunay " + wide.string() + " --check --texture 64");
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("check: ok"), std::string::npos) << r.output;
    EXPECT_EQ(printed(r.output, "triangles"), 9) << r.output; // 2n - 2 - hull(3)
}

TEST(DelaunayCli, BadFlagsAreUsageErrors) {
    const std::string in = sample("grid10x10.txt");
    for (const char* flags : {"--texture 0", "--texture 100000", "--texture abc",
                              "--backend vulkan", "--format png", "--threads -1", "--bogus"}) {
        const Outcome r = run("delaunay " + in + " " + flags);
        EXPECT_EQ(r.code, 2) << flags << "\n" << r.output;
    }
    EXPECT_EQ(run("delaunay").code, 2); // IN is required
    const Outcome r = run("delaunay " + in + " --plan jfa+x");
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("--plan"), std::string::npos) << r.output;
}

TEST(DelaunayCli, GlBackendWritesTheSameMeshAsTheCpuBackend) {
    const auto dir = freshDir("delaunay_cli_gl");
    const std::string in = sample("uniform200.node");
    // Mesa's driver leaves a few bytes at exit that LeakSanitizer cannot attribute (see
    // tests/CMakeLists.txt): leak checks are off for the GL child only.
    const Outcome gl = run("delaunay " + in +
                               " --backend gl --texture 256 --check --format node "
                               "--out " +
                               (dir / "gl").string(),
                           "ASAN_OPTIONS=detect_leaks=0");
    if (gl.code != 0 && (gl.output.find("no headless OpenGL") != std::string::npos ||
                         gl.output.find("no GL Delaunay backend") != std::string::npos))
        GTEST_SKIP() << "no GL backend or context here:\n" << gl.output;
    ASSERT_EQ(gl.code, 0) << gl.output;
    const Outcome cpu =
        run("delaunay " + in + " --texture 256 --format node --out " + (dir / "cpu").string());
    ASSERT_EQ(cpu.code, 0) << cpu.output;
    auto slurp = [](const std::filesystem::path& p) {
        std::ifstream f(p);
        return std::string(std::istreambuf_iterator<char>(f), {});
    };
    EXPECT_EQ(slurp(dir / "gl.ele"), slurp(dir / "cpu.ele"));
    for (const char* count : {"missing sites", "flips", "triangles"})
        EXPECT_EQ(printed(gl.output, count), printed(cpu.output, count)) << count;
}

} // namespace
} // namespace fl::test
