// The floodlight binary: exit codes and messages for bad input, and what `render` writes.

#include "CliRun.h"
#include "TestPaths.h"

#include <io/ImageIO.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>

namespace fl::test {
namespace {

Outcome run(const std::string& args) {
    return runCommand(std::string(FLOODLIGHT_BINARY) + " " + args);
}

TEST(Cli, HelpExitsZero) {
    for (const char* cmd : {"--help", "render --help", "view --help", "make-scene --help"}) {
        const Outcome r = run(cmd);
        EXPECT_EQ(r.code, 0) << cmd << "\n" << r.output;
        EXPECT_NE(r.output.find("Usage"), std::string::npos) << cmd;
    }
}

TEST(Cli, MissingSceneFileIsOneClearError) {
    const Outcome r =
        run("render --scene /nonexistent/scene.gltf --out " + outputDir("cli").string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("/nonexistent/scene.gltf"), std::string::npos) << r.output;
}

TEST(Cli, UnsupportedExtensionIsRejected) {
    const auto p = outputDir("cli") / "model.obj";
    std::ofstream(p) << "v 0 0 0\n";
    const Outcome r = run("render --scene " + p.string() + " --out " + outputDir("cli").string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("model.obj"), std::string::npos) << r.output;
}

TEST(Cli, AbsurdSizesAreUsageErrors) {
    for (const char* size : {"--width 0", "--height -5", "--width 100000", "--width abc"}) {
        const Outcome r =
            run(std::string("render ") + size + " --out " + outputDir("cli").string());
        EXPECT_EQ(r.code, 2) << size << "\n" << r.output;
        EXPECT_NE(r.output.find("--"), std::string::npos) << size << "\n" << r.output;
    }
}

TEST(Cli, TsmStabilityStepsOutOfRangeAreOneUsageError) {
    const std::array<std::pair<const char*, const char*>, 6> cases{{
        {"--tsm-quantize 0.6", "--tsm-quantize: must be a finite number in [0, 0.5], got '0.6'"},
        {"--tsm-quantize -0.01", "--tsm-quantize: must be a finite number in [0, 0.5]"},
        {"--tsm-quantize nan", "--tsm-quantize: must be a finite number in [0, 0.5]"},
        {"--tsm-snap 65", "--tsm-snap: must be a finite number in [0, 64], got '65'"},
        {"--tsm-hysteresis 1", "--tsm-hysteresis: must be a finite number in [0, 0.5]"},
        {"--tsm-hysteresis abc", "--tsm-hysteresis: must be a finite number in [0, 0.5]"},
    }};
    for (const auto& [args, message] : cases) {
        const Outcome r = run(std::string("render --shadow-map tsm --width 32 --height 32 ") +
                              args + " --out " + outputDir("cli").string());
        EXPECT_EQ(r.code, 2) << args << "\n" << r.output;
        EXPECT_NE(r.output.find(message), std::string::npos) << args << "\n" << r.output;
    }
    // The ends of each range are accepted (0 turns the measure off).
    const Outcome ok = run("render --shadow-map tsm --width 32 --height 32 --shadow-map-size 64 "
                           "--tsm-quantize 0.5 --tsm-snap 0 --tsm-hysteresis 0.5 --out " +
                           outputDir("cli_tsm_ranges").string());
    EXPECT_EQ(ok.code, 0) << ok.output;
    // On the uniform map a stability step is a conflicting option: one message, exit 2.
    const Outcome uniform = run("render --width 32 --height 32 --tsm-hysteresis 0.1 --out " +
                                outputDir("cli").string());
    EXPECT_EQ(uniform.code, 2) << uniform.output;
    EXPECT_NE(uniform.output.find("--tsm-hysteresis: only with --shadow-map tsm"),
              std::string::npos)
        << uniform.output;
}

// --penumbra (jfa-l, flood-l: which halves of the penumbra) on a method without a penumbra map is
// one usage error naming the option and the methods that take it; a value other than outer or
// both is one too; jfa-l takes both values.
TEST(Cli, PenumbraSidesOnlyWithAPenumbraMap) {
    const std::string small = "render --width 16 --height 16 --shadow-map-size 64 ";
    for (const char* method : {"pcss", "jfa-e"})
        for (const char* value : {"both", "outer"}) {
            const Outcome r = run(small + "--method " + method + " --penumbra " + value +
                                  " --out " + outputDir("cli").string() + " --name sides");
            EXPECT_EQ(r.code, 2) << method << " " << value << "\n" << r.output;
            EXPECT_NE(r.output.find("--penumbra: method " + std::string(method) +
                                    " does not take it (only jfa-l, flood-l do)"),
                      std::string::npos)
                << r.output;
        }
    const Outcome bad = run(small + "--method jfa-l --penumbra inner --out " +
                            outputDir("cli").string() + " --name sides");
    EXPECT_EQ(bad.code, 2) << bad.output;
    EXPECT_NE(bad.output.find("--penumbra"), std::string::npos) << bad.output;
    EXPECT_NE(bad.output.find("must be one of outer,both"), std::string::npos) << bad.output;
    for (const char* value : {"both", "outer"}) {
        const Outcome ok = run(small + "--method jfa-l --penumbra " + std::string(value) +
                               " --out " + outputDir("cli").string() + " --name sides");
        EXPECT_EQ(ok.code, 0) << value << "\n" << ok.output;
    }
}

TEST(Cli, BadCameraIsAnInputError) {
    const Outcome r =
        run("render --camera 7 --width 32 --height 32 --out " + outputDir("cli").string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("camera"), std::string::npos) << r.output;
}

TEST(Cli, RenderWritesPngAndExrAndNoTemporaries) {
    const auto dir = outputDir("cli_render");
    for (const auto& e : std::filesystem::directory_iterator(dir)) std::filesystem::remove(e);
    const Outcome r = run("render --width 96 --height 64 --shadow-map-size 256 --out " +
                          dir.string() + " --name small");
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("shadow map:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("frame total:"), std::string::npos) << r.output;
    const ByteImage png = readPng(dir / "small.png");
    EXPECT_EQ(png.width, 96);
    EXPECT_EQ(png.height, 64);
    int w = 0, h = 0;
    const std::vector<ExrChannel> exr = readExr(dir / "small.exr", w, h);
    EXPECT_EQ(w, 96);
    EXPECT_EQ(h, 64);
    std::vector<std::string> names;
    for (const ExrChannel& c : exr) {
        names.push_back(c.name);
        for (float v : c.values) ASSERT_TRUE(std::isfinite(v)) << c.name;
    }
    EXPECT_EQ(names, (std::vector<std::string>{"A", "B", "G", "R", "receiver", "visibility"}));
    int files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        ++files;
        EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
    }
    EXPECT_EQ(files, 3); // NAME.png, NAME.visibility.png, NAME.exr
}

TEST(Cli, RenderSideBySideWritesBothProvidersAndAliasingMaps) {
    const auto dir = outputDir("cli_tsm");
    for (const auto& e : std::filesystem::directory_iterator(dir)) std::filesystem::remove(e);
    const Outcome r = run("render --width 64 --height 48 --shadow-map-size 256 --side-by-side "
                          "--aliasing-map " +
                          (dir / "alias.exr").string() + " --out " + dir.string() + " --name f");
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("near the viewer"), std::string::npos) << r.output;
    for (const char* name : {"f.uniform.png", "f.tsm.png", "f.uniform.exr", "f.tsm.exr",
                             "alias.uniform.exr", "alias.tsm.exr", "f.uniform-vs-tsm.png",
                             "f.uniform-vs-tsm.visibility.png", "f.uniform-vs-tsm.footprint.png"})
        EXPECT_TRUE(std::filesystem::exists(dir / name)) << name << "\n" << r.output;
    const ByteImage pair = readPng(dir / "f.uniform-vs-tsm.png");
    EXPECT_EQ(pair.width, 2 * 64 + 4); // two frames and a 4-pixel gutter
    EXPECT_EQ(pair.height, 48);
    int w = 0, h = 0;
    const std::vector<ExrChannel> exr = readExr(dir / "alias.tsm.exr", w, h);
    std::vector<std::string> names;
    for (const ExrChannel& c : exr) names.push_back(c.name);
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"footprint", "previousVisibility", "viewDepth",
                                               "visibility"}));
}

TEST(Cli, UnknownShadowMapProviderIsAUsageError) {
    const Outcome r = run("render --shadow-map cascaded --out " + outputDir("cli").string());
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("--shadow-map"), std::string::npos) << r.output;
}

TEST(Cli, UnwritableOutputIsAnErrorWithoutPartialFiles) {
    const auto blocker = outputDir("cli") / "not_a_folder";
    std::ofstream(blocker) << "x";
    const Outcome r = run("render --width 16 --height 16 --out " + (blocker / "sub").string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("not_a_folder"), std::string::npos) << r.output;
}

TEST(Cli, VoronoiWritesDiagramAndReportsErrors) {
    const auto dir = outputDir("cli_voronoi");
    const Outcome r = run("voronoi --sites 50 --width 64 --height 48 --plan 1+jfa --out " +
                          dir.string() + " --name v");
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("1+JFA on 64x48"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("error pixels"), std::string::npos) << r.output;
    EXPECT_EQ(readPng(dir / "v.png").width, 64);
    int w = 0, h = 0;
    EXPECT_EQ(readExr(dir / "v.exr", w, h).size(), 6u);
}

// A plan of limited reach floods only the band around the sites, with the full grid's result;
// a plan that reaches every texel runs full and says so once. Both backends, both GL kernels.
TEST(Cli, VoronoiBandEqualsFullAndSaysWhenItRunsFull) {
    const auto dir = outputDir("cli_voronoi_band");
    const std::string common =
        "voronoi --sites 6 --width 96 --height 80 --plan flood:5 --out " + dir.string() + " ";
    for (const char* backend :
         {"--backend cpu", "--backend gl --kernel fragment", "--backend gl --kernel compute"}) {
        SCOPED_TRACE(backend);
        const Outcome band = run(common + backend + " --name band");
        ASSERT_EQ(band.code, 0) << band.output;
        EXPECT_NE(band.output.find("flood region: band, "), std::string::npos) << band.output;
        const Outcome full = run(common + backend + " --flood-region full --name full");
        ASSERT_EQ(full.code, 0) << full.output;
        EXPECT_EQ(full.output.find("flood region"), std::string::npos) << full.output;
        int w = 0, h = 0;
        const auto a = readExr(dir / "band.exr", w, h), b = readExr(dir / "full.exr", w, h);
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t c = 0; c < a.size(); ++c) EXPECT_EQ(a[c].values, b[c].values) << c;
    }
    const Outcome jfa = run("voronoi --sites 6 --width 96 --height 80 --plan jfa --out " +
                            dir.string() + " --name jfa");
    ASSERT_EQ(jfa.code, 0) << jfa.output;
    EXPECT_NE(jfa.output.find("flood region: full (every tile lies within the plan's reach"),
              std::string::npos)
        << jfa.output;
    EXPECT_EQ(run("voronoi --flood-region half --out " + dir.string()).code, 2);
}

TEST(Cli, VoronoiBadInput) {
    const auto bad = outputDir("cli") / "bad_points.txt";
    std::ofstream(bad) << "1 2\n3 oops\n";
    Outcome r = run("voronoi --backend cpu --points " + bad.string() + " --out " +
                    outputDir("cli").string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("bad_points.txt:2"), std::string::npos) << r.output;
    r = run("voronoi --backend cpu --plan jfa+x --out " + outputDir("cli").string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("--plan"), std::string::npos) << r.output;
    const auto outside = outputDir("cli") / "outside.txt";
    std::ofstream(outside) << "10 10\n600 3\n";
    r = run("voronoi --backend cpu --width 64 --height 64 --points " + outside.string() +
            " --out " + outputDir("cli").string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("site 1"), std::string::npos) << r.output;
    const auto dup = outputDir("cli") / "dup.txt";
    std::ofstream(dup) << "3 4\n5 6\n3 4\n";
    r = run("voronoi --backend cpu --points " + dup.string() + " --out " +
            outputDir("cli").string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("dup.txt:3: duplicate of the site on line 1"), std::string::npos)
        << r.output;
    const auto empty = outputDir("cli") / "empty.txt";
    std::ofstream(empty) << "# nothing\n";
    r = run("voronoi --backend cpu --points " + empty.string() + " --out " +
            outputDir("cli").string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("no sites"), std::string::npos) << r.output;
    // Usage errors like render's (exit 2; they exited 1 before the one numeric rule).
    for (const char* size : {"--width 0", "--height 20000"}) {
        r = run(std::string("voronoi ") + size + " --out " + outputDir("cli").string());
        EXPECT_EQ(r.code, 2) << size << "\n" << r.output;
        EXPECT_NE(r.output.find("must be an integer in [1, 16384]"), std::string::npos) << r.output;
    }
    const auto blank = outputDir("cli") / "blank.png";
    writePng(blank, ByteImage{8, 8, 4, std::vector<std::uint8_t>(8 * 8 * 4, 0)});
    r = run("voronoi --backend cpu --mask " + blank.string() + " --out " +
            outputDir("cli").string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("no sites"), std::string::npos) << r.output;
    const auto notPng = outputDir("cli") / "not_a.png";
    std::ofstream(notPng) << "garbage";
    r = run("voronoi --backend cpu --mask " + notPng.string() + " --out " +
            outputDir("cli").string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("not_a.png"), std::string::npos) << r.output;
}

// --- first use (issue 42) -----------------------------------------------------------------
// Issue 42, as a new user meets the binary: the light size they can reason about and the line
// that says what a render used, ranges in --help, a typo's nearest flag, one line without a
// display, outputs checked before the work and nothing left by a failure, a file opening on the
// auto frame with its cameras by index, and capture scripts' light size, auto and orbit paths.
// Each case of the issue's "Why" is here with its exit code and message (the loader's messages
// are gltf_messages_test's).

namespace fs = std::filesystem;

const fs::path kSamples = "/usr/share/assimp/models/glTF2";

// One folder per test (ctest runs this file's tests as parallel processes), emptied first.
fs::path firstUseDir() {
    const fs::path d = outputDir("first_use_cli") /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::error_code ec;
    fs::remove_all(d, ec);
    fs::create_directories(d);
    return d;
}

void expectOutcome(const Outcome& r, int code, const std::string& message) {
    EXPECT_EQ(r.code, code) << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << "expected: " << message << "\n"
                                                         << r.output;
}

std::string small(const fs::path& out) {
    return " --width 32 --height 32 --shadow-map-size 256 --out " + out.string();
}

TEST(FirstUseCli, LightSizeAndRadiusHaveRanges) {
    const fs::path d = firstUseDir();
    for (const char* bad : {"-1", "nan", "1e30"})
        expectOutcome(run(std::string("render --light-size ") + bad + small(d)), 2,
                      std::string("--light-size: must be a finite number in [0, 1], got '") + bad +
                          "'");
    expectOutcome(run("render --light-radius 1e30" + small(d)), 2,
                  "--light-radius: must be a finite number in [0, 1e+15], got '1e30'");
    // In range for the option, out of range for the scene: a disk wider than its distance.
    expectOutcome(run("render --light-radius 1e6" + small(d)), 1,
                  "--light-radius 1e+06: wider than the light's distance to the scene's centre");
    // 0: a point light, allowed as for --light-radius.
    expectOutcome(run("render --light-size 0" + small(d)), 0, "disk radius 0 = 0 of the model's");
}

TEST(FirstUseCli, RenderSaysWhatLightMapAndPassesItUsed) {
    const Outcome r = run("render --method jfa-e --light-size 0.1" + small(firstUseDir()));
    expectOutcome(r, 0,
                  "= 0.1 of the model's radius (--light-size); shadow map: 256^2 uniform; "
                  "flood: ");
    EXPECT_NE(r.output.find(" passes (auto chose)"), std::string::npos) << r.output;
    // The default scene's light keeps its own radius (extras.radius 0.3).
    expectOutcome(run("render" + small(firstUseDir())), 0, "light: sun, centre (");
}

TEST(FirstUseCli, HelpShowsRangesAndDefaults) {
    const Outcome r = run("render --help");
    EXPECT_EQ(r.code, 0);
    for (const char* shown :
         {"--width INT:in [1, 8192]=512", "--shadow-map-size INT:in [16, 8192]=1024",
          "--fov FLOAT:in [1, 170]", "Default: the glTF camera's, else 50",
          "--light-size FLOAT:in [0, 1]", "Default 0.08", "--jfa-passes TEXT:in [1, 13] or auto",
          "Missing folders are created"})
        EXPECT_NE(r.output.find(shown), std::string::npos) << shown << "\n" << r.output;
}

TEST(FirstUseCli, ATypoNamesTheNearestFlag) {
    expectOutcome(run("render --lightradius 2"), 2,
                  "--lightradius: not an option of `render`; did you mean --light-radius?");
    expectOutcome(run("render --shadowmap-size=512"), 2, "did you mean --shadow-map-size?");
    // compare has no --overlay: the message names it, not the arguments after it.
    const Outcome r = run("compare --overlay voronoi --frames 1");
    expectOutcome(r, 2, "--overlay: not an option of `compare`");
    EXPECT_EQ(r.output.find("1 --frames"), std::string::npos) << r.output;
}

TEST(FirstUseCli, NoDisplayIsOneLineSayingWhatToDo) {
    const Outcome r = runCommand("env -u DISPLAY -u WAYLAND_DISPLAY timeout 60 " +
                                 std::string(FLOODLIGHT_BINARY) + " view --frames 1");
    expectOutcome(r, 1, "use `floodlight render` (headless)");
    EXPECT_NE(r.output.find("xvfb-run -a floodlight view"), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_EQ(r.output.find("GLFW"), std::string::npos) << r.output;
}

TEST(FirstUseCli, OutputsAreCheckedBeforeTheWork) {
    const fs::path d = firstUseDir();
    // A folder where the aliasing map goes: refused before rendering, no file in --out.
    fs::create_directories(d / "map.exr");
    const Outcome folderMap =
        run("render --aliasing-map " + (d / "map.exr").string() + small(d / "out"));
    expectOutcome(folderMap, 1, "--aliasing-map " + (d / "map.exr").string() + ": is a folder");
    EXPECT_EQ(folderMap.output.find("context:"), std::string::npos) << "rendered first";
    EXPECT_FALSE(fs::exists(d / "out"));
    // A file where the output folder goes: refused before rendering.
    std::ofstream(d / "file") << "x";
    const Outcome fileOut = run("render" + small(d / "file"));
    expectOutcome(fileOut, 1, "--out " + (d / "file").string() + ": is a file, not a folder");
    EXPECT_EQ(fileOut.output.find("context:"), std::string::npos) << "rendered first";
    // Missing folders are created, for --out and --aliasing-map alike.
    const fs::path map = d / "new" / "deeper" / "a.exr";
    expectOutcome(run("render --aliasing-map " + map.string() + small(d / "made" / "here")), 0,
                  "wrote");
    EXPECT_TRUE(fs::is_regular_file(map));
    EXPECT_TRUE(fs::is_regular_file(d / "made" / "here" / "frame.png"));
    // Side by side, the map is written once per provider, as --help says.
    const fs::path pair = d / "pair.exr";
    expectOutcome(run("render --side-by-side --aliasing-map " + pair.string() + small(d)), 0,
                  "pair.tsm.exr");
    EXPECT_TRUE(fs::is_regular_file(d / "pair.uniform.exr"));
    EXPECT_TRUE(fs::is_regular_file(d / "pair.tsm.exr"));
    // Options that cannot combine: exit 2.
    expectOutcome(run("render --side-by-side --shadow-map tsm" + small(d)), 2,
                  "--shadow-map excludes --side-by-side");
}

TEST(FirstUseCli, ABadSceneIsNamedInWords) {
    const fs::path d = firstUseDir();
    std::ofstream(d / "photo.glb", std::ios::binary) << "\x89PNG\r\n\x1a\n....";
    const Outcome r = run("render --scene " + (d / "photo.glb").string() + small(d));
    expectOutcome(r, 1, "error: photo.glb: not a glTF file (it starts like a PNG image)");
    EXPECT_EQ(r.output.find('\x89'), std::string::npos);
    std::ofstream(d / "zero.glb", std::ios::binary) << "";
    expectOutcome(run("render --scene " + (d / "zero.glb").string() + small(d)), 1,
                  "zero.glb: empty file (0 bytes)");
}

// A file opens on the auto frame (its model and shadow), its own cameras by index; the built-in
// scene keeps its camera (the goldens' view).
TEST(FirstUseCli, AFileOpensFramedAndItsCamerasStaySelectable) {
    const fs::path file = kSamples / "cameras" / "Cameras.gltf";
    ASSERT_TRUE(fs::exists(file)) << "assimp-testmodels (scripts/setup.sh)";
    const fs::path d = firstUseDir();
    for (const char* camera : {"default", "auto", "0"})
        ASSERT_EQ(run("render --scene " + file.string() + " --camera " + camera + " --name " +
                      camera + small(d))
                      .code,
                  0)
            << camera;
    const auto bytes = [&](const char* name) {
        std::ifstream in(d / (std::string(name) + ".png"), std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), {});
    };
    EXPECT_EQ(bytes("default"), bytes("auto"));
    EXPECT_NE(bytes("0"), bytes("auto"));
}

TEST(FirstUseCli, CaptureScriptsTakeALightSizeAndTheAutoAndOrbitPaths) {
    const fs::path d = firstUseDir();
    for (const char* path : {"auto", "orbit"}) {
        const fs::path script = d / (std::string(path) + ".json");
        std::ofstream(script) << R"({"scene": ")"
                              << (kSamples / "BoxTextured-glTF" / "BoxTextured.gltf").string()
                              << R"(", "camera": {"frames": 2, "path": ")" << path
                              << R"("}, "light": {"size": 0.1}, "resolutions": [[32, 32]],
                  "shadowMap": {"size": 256}, "reference": {"kind": "maps", "samples": 4,
                  "mapSize": 64}, "methods": ["hard"]})";
        expectOutcome(run("capture " + script.string() + " --out " + (d / path).string()), 0,
                      "= 0.1 of the model's radius");
    }
    const fs::path both = d / "both.json";
    std::ofstream(both) << R"({"camera": {"frames": 1, "path": "auto"},
                               "light": {"radius": 1, "size": 0.1}, "methods": ["hard"]})";
    expectOutcome(run("capture " + both.string() + " --out " + (d / "both").string()), 1,
                  "light.size: give radius (scene units) or size");
}

} // namespace
} // namespace fl::test
