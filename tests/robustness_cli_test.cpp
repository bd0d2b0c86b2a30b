// Issue 16, "fix every class at its root", through the real binary: every reader of a user file
// refuses a FIFO, a directory and a missing file with one line naming the option or role, the
// path and the problem (exit 1); an all-site mask writes a finite signed distance; points of a
// subnormal extent triangulate; --out and --name are checked once for every command (exit 2).
// Every command runs under `timeout`, so a reader that blocks again fails here instead of hanging.

#include "CliRun.h"
#include "PngBytes.h"
#include "TestPaths.h"

#include <io/ImageIO.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/stat.h>

namespace fl::test {
namespace {

namespace fs = std::filesystem;

Outcome run(const std::string& args) {
    return runCommand("timeout 120 " + std::string(FLOODLIGHT_BINARY) + " " + args);
}

// One folder per test: ctest runs the tests of this file as parallel processes, and a FIFO
// named mask.png in one test was replaced by another test's mask.png.
fs::path dir() {
    const fs::path d = outputDir("robustness_cli") /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::create_directories(d);
    return d;
}

// A FIFO at dir()/name (replacing whatever was there): reading it would block forever.
fs::path fifo(const std::string& name) {
    const fs::path p = dir() / name;
    std::error_code ec;
    fs::remove_all(p, ec);
    EXPECT_EQ(::mkfifo(p.c_str(), 0600), 0) << p;
    return p;
}

// A directory at dir()/name.
fs::path folder(const std::string& name) {
    const fs::path p = dir() / name;
    std::error_code ec;
    fs::remove_all(p, ec);
    fs::create_directories(p);
    return p;
}

void expectRefused(const Outcome& r, const std::string& message, int code = 1) {
    EXPECT_EQ(r.code, code) << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << "expected: " << message << "\n"
                                                         << r.output;
}

TEST(RobustnessCli, EveryReaderRefusesAFifo) {
    const std::string out = " --out " + dir().string();
    const fs::path script = fifo("script.json");
    expectRefused(run("capture " + script.string() + out),
                  "capture script " + script.string() + ": not a regular file (a FIFO)");
    const fs::path points = fifo("points.txt");
    expectRefused(run("voronoi --backend cpu --points " + points.string() + out),
                  "--points " + points.string() + ": not a regular file (a FIFO)");
    const fs::path mask = fifo("mask.png");
    expectRefused(run("voronoi --backend cpu --mask " + mask.string() + out),
                  "--mask " + mask.string() + ": not a regular file (a FIFO)");
    for (const char* name : {"points.node", "points.xy", "points.f64"}) {
        const fs::path p = fifo(name);
        expectRefused(run("delaunay " + p.string()), p.string() + ": not a regular file (a FIFO)");
    }
    const fs::path scene = fifo("scene.glb");
    expectRefused(run("render --scene " + scene.string() + out),
                  "scene.glb: not a regular file (a FIFO)");
    const fs::path path = fifo("path.json");
    expectRefused(
        run("compare --method jfa-l --width 32 --height 32 --path " + path.string() + out),
        "--path " + path.string() + ": not a regular file (a FIFO)");
}

TEST(RobustnessCli, DirectoriesAndMissingFilesAreNamedAsSuch) {
    const std::string out = " --out " + dir().string();
    // A directory given as a camera file gave "basic_filebuf::underflow".
    const fs::path cameras = folder("cameras.json");
    const fs::path script = dir() / "dir_camera.json";
    std::ofstream(script) << R"({"camera": {"frames": 2, "file": ")" << cameras.string()
                          << R"("}, "methods": ["hard"]})";
    expectRefused(run("capture " + script.string() + out),
                  "camera.file: " + cameras.string() + ": not a regular file (a directory)");
    expectRefused(
        run("compare --method jfa-l --width 32 --height 32 --path " + cameras.string() + out),
        "--path " + cameras.string() + ": not a regular file (a directory)");
    const fs::path labels = folder("labels.png");
    const fs::path mask = dir() / "mask.png";
    writePng(mask, ByteImage{4, 4, 4, std::vector<std::uint8_t>(4 * 4 * 4, 255)});
    expectRefused(
        run("voronoi --backend cpu --mask " + mask.string() + " --labels " + labels.string() + out),
        "--labels " + labels.string() + ": not a regular file (a directory)");
    // The loader said "file not found" for files that exist but are not regular.
    const fs::path scene = folder("folder.gltf");
    const Outcome r = run("render --scene " + scene.string() + out);
    expectRefused(r, "folder.gltf: not a regular file (a directory)");
    EXPECT_EQ(r.output.find("not found"), std::string::npos) << r.output;
    const fs::path missing = dir() / "missing.xy";
    fs::remove(missing);
    expectRefused(run("delaunay " + missing.string()), missing.string() + ": does not exist");
}

TEST(RobustnessCli, OversizedInputsAreRefusedAndTheLimitsAreInTheHelp) {
    const fs::path big = dir() / "big.xy";
    { std::ofstream(big) << "0 0\n"; }
    fs::resize_file(big, (std::uintmax_t{64} << 20) + 1); // sparse
    expectRefused(run("delaunay " + big.string()),
                  big.string() + ": larger than the limit of 64 MiB");
    expectRefused(
        run("voronoi --backend cpu --points " + big.string() + " --out " + dir().string()),
        "--points " + big.string() + ": larger than the limit of 64 MiB");
    fs::remove(big);
    const std::pair<const char*, const char*> helps[] = {
        {"capture --help", "64 MiB"},  {"view --help", "64 MiB"},
        {"compare --help", "64 MiB"},  {"delaunay --help", "256 MiB"},
        {"voronoi --help", "256 MiB"}, {"render --help", "1024 MiB"}};
    for (const auto& [cmd, limit] : helps) {
        const Outcome r = run(cmd);
        EXPECT_EQ(r.code, 0) << cmd;
        EXPECT_NE(r.output.find(limit), std::string::npos) << cmd << "\n" << r.output;
    }
}

// Bug: an all-site mask (every pixel inside) wrote -inf into NAME.sdf.exr and exited 0. The
// field now holds -hypot(W, H) there (jfa/DistanceTransform.h), on both flood backends.
TEST(RobustnessCli, AllSiteMaskWritesAFiniteSignedDistance) {
    const fs::path mask = dir() / "all_sites.png";
    writePng(mask, ByteImage{12, 5, 4, std::vector<std::uint8_t>(12 * 5 * 4, 255)});
    for (const char* backend : {"cpu", "gl"}) {
        const std::string name = std::string("all_") + backend;
        const Outcome r = run("voronoi --backend " + std::string(backend) + " --mask " +
                              mask.string() + " --out " + dir().string() + " --name " + name);
        ASSERT_EQ(r.code, 0) << r.output;
        EXPECT_NE(r.output.find("the mask has no outside pixel"), std::string::npos) << r.output;
        int w = 0, h = 0;
        const auto channels = readExr(dir() / (name + ".sdf.exr"), w, h);
        ASSERT_EQ(channels.size(), 1u);
        ASSERT_EQ(w * h, 60);
        for (const float v : channels[0].values) ASSERT_EQ(v, -13.0f) << backend; // hypot(12, 5)
    }
}

// Bug (fuzz_png_mask): stb_image sizes its buffers from a PNG's chunk lengths and header before
// it reads the data, so a 116-byte mask whose IDAT chunk claimed 1.1 GB allocated 2 GiB, and a
// tiny 16384^2 16-bit header as much again. readPng refuses both before decoding.
TEST(RobustnessCli, PngClaimingMoreThanItHoldsIsRefusedBeforeDecoding) {
    const fs::path longChunk = dir() / "long_chunk.png";
    std::ofstream(longChunk, std::ios::binary)
        << pngStart(8, 8, 8, 2) + pngChunk("IDAT", "x\xda", 1'192'036'890);
    expectRefused(
        run("voronoi --backend cpu --mask " + longChunk.string() + " --out " + dir().string()),
        "--mask " + longChunk.string() + ": the chunk at byte 33 claims 1192036890 " +
            "bytes, past the end of the");
    const fs::path huge = dir() / "huge_header.png";
    std::ofstream(huge, std::ios::binary) << pngStart(16384, 16384, 16, 6) +
                                                 pngChunk("IDAT", std::string(20, 'x'), 20) +
                                                 pngChunk("IEND", "", 0);
    expectRefused(run("voronoi --backend cpu --mask " + huge.string() + " --out " + dir().string()),
                  "--mask " + huge.string() +
                      ": 20 bytes of image data cannot hold the 16384x16384 image");
}

// Bug: `delaunay` crashed (SIGSEGV in snapSites) on coordinates around 1e-307 .. 1e-309.
TEST(RobustnessCli, DelaunayOfSubnormalExtentDoesNotCrash) {
    for (const char* unit : {"1e-305", "1e-307", "1e-308", "1e-309", "1e-320"}) {
        const fs::path p = dir() / (std::string("tiny_") + unit + ".xy");
        {
            std::ofstream f(p);
            for (const char* xy : {"0 0", "3 1", "1 4", "5 5", "2 2", "7 3"}) {
                const std::string s(xy);
                const auto space = s.find(' ');
                f << s.substr(0, space) << unit << " " << s.substr(space + 1) << unit << "\n";
            }
        }
        for (const char* backend : {"cpu", "gl"}) {
            const Outcome r = run("delaunay " + p.string() + " --check --backend " + backend);
            EXPECT_EQ(r.code, 0) << unit << " " << backend << "\n" << r.output;
            EXPECT_NE(r.output.find("check: ok"), std::string::npos) << r.output;
        }
    }
}

TEST(RobustnessCli, OutputNamesStayInsideOut) {
    const std::string out = dir().string();
    const std::pair<std::string, std::string> cases[] = {
        {"render --out " + out + " --name ../../x", "--name"},
        {"render --out " + out + " --name sub/x", "--name"},
        {"render --out " + out + " --name ''", "--name"},
        {"render --out '' --name x", "--out"},
        {"render --out " + out + " --name .hidden", "--name"},
        {"voronoi --out " + out + " --name ../x", "--name"},
        {"voronoi --out '' --name x", "--out"},
        {"capture examples/capture/short.json --out ''", "--out"},
        {"compare --method jfa-l --out ''", "--out"},
        {"make-scene --out ''", "--out"},
        {"delaunay x.xy --out " + out + "/", "--out"},
        {"delaunay x.xy --steps ''", "--steps"},
    };
    for (const auto& [args, option] : cases) {
        const Outcome r = run(args);
        EXPECT_EQ(r.code, 2) << args << "\n" << r.output;
        EXPECT_NE(r.output.find(option), std::string::npos) << args << "\n" << r.output;
    }
    EXPECT_FALSE(fs::exists(fs::path(out).parent_path().parent_path() / "x.png"));
}

// One numeric rule for every option (base/Numbers.h): NaN and inf were accepted and rendered a
// background-only frame, "abc" was called "not in range", and voronoi --width 0 exited 1 where
// render --width 0 exited 2.
TEST(RobustnessCli, NumbersAreFiniteAndInRangeEverywhere) {
    const std::string out = " --out " + dir().string();
    const std::pair<std::string, std::string> cases[] = {
        {"render --eye nan,1,1 --target 0,0,0" + out, "--eye: must be a finite number, got 'nan'"},
        {"render --eye 1,inf,1 --target 0,0,0" + out, "--eye: must be a finite number, got 'inf'"},
        {"render --target 0,0,1e400 --eye 1,1,1" + out, "--target: must be a finite number"},
        {"render --bias-slope nan" + out, "--bias-slope: must be a finite number in [0, 64]"},
        {"render --fov inf" + out, "--fov: must be a finite number in [1, 170]"},
        {"render --light-radius -1" + out, "--light-radius: must be a finite number in [0, 1e+15]"},
        {"render --width abc" + out, "--width: must be an integer in [1, 8192], got 'abc'"},
        {"render --width 2.5" + out, "--width: must be an integer in [1, 8192], got '2.5'"},
        {"render --pcss-preset 16/24 --vsm-blur nan" + out, "--vsm-blur: must be a finite number"},
        {"voronoi --width 0" + out, "--width: must be an integer in [1, 16384], got '0'"},
        {"view --frames -1", "--frames: must be an integer in [0, 10000000]"},
    };
    for (const auto& [args, message] : cases) {
        SCOPED_TRACE(args);
        expectRefused(run(args), message, 2);
    }
}

// Named after the bug: flood:1048576 on a 64 x 64 grid ran for minutes. A step-1 flood crosses
// the largest grid (16384 per side) in fewer passes, so more are refused at once, and the limit
// is in --help.
TEST(RobustnessCli, FloodPassesBeyondAnyGridAreRefused) {
    const std::string out = " --out " + dir().string();
    expectRefused(run("voronoi --width 64 --height 64 --plan flood:1048576" + out),
                  "N in flood:N must be 1..16384");
    expectRefused(run("voronoi --width 64 --height 64 --plan flood:16385" + out),
                  "N in flood:N must be 1..16384");
    const Outcome ok = run("voronoi --width 64 --height 64 --sites 3 --plan flood:64" + out);
    EXPECT_EQ(ok.code, 0) << ok.output;
    EXPECT_NE(run("voronoi --help").output.find("flood:N (N <= 16384)"), std::string::npos);
    EXPECT_NE(run("capture --help").output.find("at most 100000 frames"), std::string::npos);
}

// A number beyond a double in a capture script printed nlohmann's raw out_of_range exception.
TEST(RobustnessCli, ScriptNumbersGetTheFileAndTheField) {
    const fs::path script = dir() / "huge.json";
    std::ofstream(script)
        << R"({"camera": {"frames": 1e400, "path": "default"}, "methods": ["hard"]})";
    const Outcome r = run("capture " + script.string() + " --out " + dir().string());
    expectRefused(r, script.string() + ": not valid JSON: number overflow parsing '1e400'");
    EXPECT_EQ(r.output.find("json.exception"), std::string::npos) << r.output;
    const fs::path nan = dir() / "fractional.json";
    std::ofstream(nan) << R"({"camera": {"frames": 2.5, "path": "default"}, "methods": ["hard"]})";
    expectRefused(run("capture " + nan.string() + " --out " + dir().string()),
                  "camera.frames: must be an integer in [1, 100000], got 2.5");
}

// A command's outputs appear together or not at all (base/OutputFiles.h). Named after the bugs:
// render with an unwritable --aliasing-map left its PNG and EXR; delaunay left .node/.ele/.obj
// when its --steps folder could not be made.
TEST(RobustnessCli, AFailedCommandLeavesNoOutputs) {
    const fs::path d = folder("all-or-nothing");
    std::ofstream(d / "blocker") << "a file where a folder is needed";
    const Outcome render =
        run("render --width 32 --height 32 --out " + d.string() + " --name frame --aliasing-map " +
            (d / "blocker" / "a.png").string());
    EXPECT_EQ(render.code, 1) << render.output;
    EXPECT_FALSE(fs::exists(d / "frame.png")) << render.output;
    EXPECT_FALSE(fs::exists(d / "frame.exr")) << render.output;

    std::ofstream(d / "pts.xy") << "0 0\n1 0\n0 1\n1 1\n0.5 0.3\n";
    const Outcome delaunay =
        run("delaunay " + (d / "pts.xy").string() + " --backend cpu --out " +
            (d / "mesh").string() + " --steps " + (d / "blocker" / "steps").string());
    EXPECT_EQ(delaunay.code, 1) << delaunay.output;
    for (const char* ext : {".node", ".ele", ".obj", ".svg"})
        EXPECT_FALSE(fs::exists(d / (std::string("mesh") + ext))) << ext << delaunay.output;
    EXPECT_EQ(delaunay.output.find("wrote"), std::string::npos) << delaunay.output;

    // Nothing hidden is left either: every temporary was removed.
    for (const auto& e : fs::directory_iterator(d))
        EXPECT_NE(e.path().filename().string().front(), '.') << e.path();
    // And the same commands succeed where they can write.
    const Outcome ok = run("delaunay " + (d / "pts.xy").string() + " --backend cpu --out " +
                           (d / "mesh").string() + " --steps " + (d / "steps").string());
    EXPECT_EQ(ok.code, 0) << ok.output;
    EXPECT_TRUE(fs::exists(d / "mesh.node"));
    EXPECT_TRUE(fs::exists(d / "steps"));
}

// FLOODLIGHT_EGL_DEVICE (issue 28): a device that does not exist, or a value that is not an
// index, is a usage error (exit 2) whose message lists the devices found with their renderers;
// a device that exists is used and named on the context line.
Outcome renderOnDevice(const std::string& device, const fs::path& out) {
    return runCommand("FLOODLIGHT_EGL_DEVICE=" + device + " timeout 120 " +
                      std::string(FLOODLIGHT_BINARY) + " render --width 16 --height 16 --out " +
                      out.string());
}

TEST(RobustnessCli, AnEglDeviceThatDoesNotExistListsTheDevicesFound) {
    const Outcome r = renderOnDevice("99", dir());
    EXPECT_EQ(r.code, 2) << r.output;
    const std::string head = "FLOODLIGHT_EGL_DEVICE=99: no such EGL device; ";
    const std::size_t at = r.output.find(head);
    ASSERT_NE(at, std::string::npos) << r.output;
    const int found = std::stoi(r.output.substr(at + head.size()));
    EXPECT_GE(found, 1) << "this machine renders headless, so EGL enumerates a device\n"
                        << r.output;
    for (int i = 0; i < found; ++i) // one line a device, with a renderer (or why none opens)
        EXPECT_NE(r.output.find("\n  " + std::to_string(i) + ": "), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("GL error"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir() / "frame.png"));
}

TEST(RobustnessCli, AnEglDeviceThatIsNotAnIndexIsAUsageError) {
    for (const char* bad : {"abc", "-1", "1x", "99999999999999999999"}) {
        const Outcome r = renderOnDevice(bad, dir());
        EXPECT_EQ(r.code, 2) << bad << "\n" << r.output;
        EXPECT_NE(
            r.output.find("FLOODLIGHT_EGL_DEVICE=" + std::string(bad) + ": not a device index"),
            std::string::npos)
            << r.output;
    }
}

TEST(RobustnessCli, TheFirstEglDeviceIsUsedWhenNamed) {
    const Outcome r = renderOnDevice("0", dir());
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("context: EGL device 0, OpenGL"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(dir() / "frame.png")) << r.output;
}

// Messages name the input and the problem, not our functions (SvgPicture::render:,
// randomIntegerSites:) or raw "filesystem error" text.
TEST(RobustnessCli, MessagesNameTheInputNotTheFunction) {
    const fs::path d = folder("messages");
    std::ofstream(d / "huge.xy") << "1e308 0\n-1e308 0\n0 1e308\n5 7\n";
    const Outcome svg =
        run("delaunay " + (d / "huge.xy").string() + " --backend cpu --out " + (d / "m").string());
    expectRefused(svg, (d / "huge.xy").string() + ": cannot draw " + (d / "m.svg").string());
    EXPECT_EQ(svg.output.find("SvgPicture"), std::string::npos) << svg.output;
    EXPECT_FALSE(fs::exists(d / "m.node")) << "all or nothing";

    const Outcome sites = run("voronoi --width 8 --height 8 --sites 100 --out " + d.string());
    expectRefused(sites, "--sites: 100 distinct sites do not fit a 8x8 grid");
    EXPECT_EQ(sites.output.find("randomIntegerSites"), std::string::npos) << sites.output;

    std::ofstream(d / "file") << "x";
    const Outcome steps = run("delaunay " + (d / "huge.xy").string() + " --backend cpu --steps " +
                              (d / "file" / "steps").string());
    expectRefused(steps,
                  "--steps " + (d / "file" / "steps").string() + ": cannot create the folder");
    EXPECT_EQ(steps.output.find("filesystem error"), std::string::npos) << steps.output;
}

} // namespace
} // namespace fl::test
