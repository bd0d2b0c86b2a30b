// `floodlight capture`: a short run of examples/capture/short.json on the default scene (3
// frames, 64x64, every kind of method, a 16-sample ground truth) writes every frame, the CSV, the
// summary and a report that headless Chromium loads with every chart drawn, every legend entry
// inside its chart and no error (and screenshots, as report.png); bad input is one clear
// message, exit code 1 and no summary or report left behind.

#include "CliRun.h"
#include "TestPaths.h"

#include <io/ImageIO.h>
#include <renderer/methods/ShadowMethod.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <sys/wait.h>

namespace fl::test {
namespace {

namespace fs = std::filesystem;

Outcome shell(const std::string& cmd) {
    return runCommand(cmd);
}

Outcome capture(const fs::path& script, const fs::path& out) {
    return shell(std::string(FLOODLIGHT_BINARY) + " capture " + script.string() + " --out " +
                 out.string());
}

fs::path example(const char* name) {
    return dataDir().parent_path() / "examples" / "capture" / name;
}

const char* kMethods[] = {"hard", "pcf_3", "pcss_16-24", "jfa-l", "flood-l", "jfa-e", "flood-e"};
constexpr int kFrames = 3;

void checkFiles(const fs::path& dir) {
    for (const char* f : {"frames.csv", "summary.json", "report.html"})
        EXPECT_TRUE(fs::is_regular_file(dir / f)) << f;
    std::vector<std::string> who(std::begin(kMethods), std::end(kMethods));
    who.push_back("reference");
    for (const std::string& m : who)
        for (int i = 0; i < kFrames; ++i) {
            const fs::path stem = dir / "frames" / "64x64" / m / ("frame_0000" + std::to_string(i));
            for (const char* ext : {".png", ".visibility.png", ".exr"})
                EXPECT_TRUE(fs::is_regular_file(stem.string() + ext)) << stem << ext;
        }
    for (const char* m : kMethods)
        EXPECT_TRUE(fs::is_regular_file(dir / "report" / ("worst_" + std::string(m) + ".png")))
            << m;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
}

void checkCsv(const fs::path& dir) {
    std::istringstream csv(fileContents(dir / "frames.csv"));
    std::string header, line;
    std::getline(csv, header);
    EXPECT_EQ(header.rfind("frame,method,width,height,rmse,rmse_penumbra,", 0), 0u) << header;
    auto split = [](const std::string& text) {
        std::vector<std::string> cells;
        std::stringstream in(text);
        for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
        if (!text.empty() && text.back() == ',') cells.emplace_back();
        return cells;
    };
    const std::vector<std::string> columns = split(header);
    const auto column = [&](const char* name) {
        return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) -
                                        columns.begin());
    };
    const std::size_t method = column("method"), passes = column("jfa_passes"),
                      share = column("active_share");
    ASSERT_LT(passes, columns.size()) << header;
    ASSERT_LT(share, columns.size()) << header;
    int rows = 0, floodRows = 0;
    while (std::getline(csv, line)) {
        ++rows;
        const std::vector<std::string> cells = split(line);
        ASSERT_EQ(cells.size(), columns.size()) << line;
        const MethodDescriptor* m = findMethod(cells[method]); // null for labels like pcf_3
        if (m && m->floods) {
            ++floodRows; // the flood's passes (auto: chosen per frame) and band share
            EXPECT_GE(std::stoi(cells[passes]), 1) << line;
            EXPECT_GT(std::stod(cells[share]), 0.0) << line;
            EXPECT_LE(std::stod(cells[share]), 1.0) << line;
        } else {
            EXPECT_TRUE(cells[passes].empty() && cells[share].empty()) << line;
        }
    }
    EXPECT_EQ(rows, kFrames * static_cast<int>(std::size(kMethods)));
    const auto floodMethods =
        std::count_if(std::begin(kMethods), std::end(kMethods), [](const char* name) {
            const MethodDescriptor* d = findMethod(name);
            return d && d->floods;
        });
    ASSERT_EQ(floodMethods, 4) << "jfa-l, flood-l, jfa-e, flood-e";
    EXPECT_EQ(floodRows, kFrames * floodMethods);
}

void checkSummary(const fs::path& dir) {
    const auto j = nlohmann::json::parse(fileContents(dir / "summary.json"));
    EXPECT_EQ(j["frames"], kFrames);
    EXPECT_EQ(j["reference"]["samples"], 16);
    EXPECT_TRUE(j["complete"].get<bool>());
    ASSERT_EQ(j["methods"].size(), std::size(kMethods));
    for (const auto& m : j["methods"]) {
        for (const char* f : {"rmse", "rmsePenumbra", "misclassifiedPercent", "meanAbsWidthErrorPx",
                              "addedFlicker", "addedFlickerScreen", "medianFrameMs",
                              "frameTimeOverHard", "medianPhaseMs", "worstFrame"})
            EXPECT_TRUE(m.contains(f)) << m["label"] << " lacks " << f;
        // With a 1.5 light radius every method differs somewhat from a 16-sample ground truth,
        // and none is wildly off.
        EXPECT_GT(m["rmse"].get<double>(), 0.0) << m["label"];
        EXPECT_LT(m["rmse"].get<double>(), 0.5) << m["label"];
    }
    // JFA methods carry the thesis' |dI| buckets against their standard-flooding counterpart.
    for (const auto& m : j["methods"]) {
        if (m["method"] == "jfa-l" || m["method"] == "jfa-e") {
            EXPECT_TRUE(m.contains("meanShareDelta")) << m["label"];
        }
    }
}

// The largest per-frame added flicker any method has in frames.csv (0 when none has any).
double maxFrameFlicker(const fs::path& dir) {
    std::istringstream csv(fileContents(dir / "frames.csv"));
    std::string line;
    std::getline(csv, line);
    std::size_t column = 0;
    for (std::size_t at = 0; line.compare(at, 14, "added_flicker,") != 0; ++column) {
        at = line.find(',', at);
        if (at == std::string::npos) return 0.0;
        ++at;
    }
    double most = 0.0;
    while (std::getline(csv, line)) {
        std::stringstream row(line);
        std::string cell;
        for (std::size_t c = 0; c <= column; ++c) std::getline(row, cell, ',');
        if (!cell.empty()) most = std::max(most, std::stod(cell));
    }
    return most;
}

// Headless Chromium loads the report once: it dumps the DOM after the report's own self-check
// ran on load, and screenshots the page (kept as report.png beside the report, to look at).
void checkReportInChromium(const fs::path& dir, const std::string& chromium) {
    const fs::path profile = outputDir("capture_chromium_profile");
    const fs::path screenshot = dir / "report.png";
    constexpr int kShotW = 1280, kShotH = 4800; // the whole report of this run
    const Outcome r =
        shell("timeout 120 " + chromium +
              " --headless --no-sandbox --disable-gpu --user-data-dir=" + profile.string() +
              " --window-size=" + std::to_string(kShotW) + "," + std::to_string(kShotH) +
              " --screenshot=" + screenshot.string() + " --dump-dom file://" +
              fs::absolute(dir / "report.html").string());
    ASSERT_EQ(r.code, 0) << r.output.substr(0, 2000);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.output, m, std::regex("data-charts-ok=\"(\\d+)/(\\d+)\"")))
        << "the report's check script did not run:\n"
        << r.output.substr(0, 2000);
    // 3 error curves (the flicker one left out, with a sentence why, when every method's is 0 in
    // every frame), 2 |dI| charts (jfa-l, jfa-e), time per phase, cost against error.
    const bool flickerShown = maxFrameFlicker(dir) > 0.0;
    EXPECT_EQ(m[1], m[2]) << "charts drawn / charts";
    EXPECT_EQ(std::stoi(m[2]), flickerShown ? 7 : 6);
    EXPECT_EQ(r.output.find("id=\"no-flicker-chart\"") == std::string::npos, flickerShown);
    ASSERT_TRUE(std::regex_search(r.output, m, std::regex("data-images-ok=\"(\\d+)/(\\d+)\"")));
    EXPECT_EQ(m[1], m[2]) << "images shown / images";
    EXPECT_EQ(std::stoi(m[2]), static_cast<int>(std::size(kMethods)));
    // The self-check: every legend entry inside its chart, off the plot and off the others, in
    // a colour of its own, a legend entry for every series, no error and no console.error.
    ASSERT_TRUE(std::regex_search(r.output, m, std::regex("<pre id=\"selfcheck\">([^<]*)</pre>")))
        << r.output.substr(0, 2000);
    EXPECT_EQ(m[1], "self-check: 0 problem(s)");
    // A summary column that reads 0 for every method says why (here: added flicker when no
    // method's shadow moves on the surface more than the reference's).
    const auto summary = nlohmann::json::parse(fileContents(dir / "summary.json"));
    const bool flickerAllZero =
        std::all_of(summary["methods"].begin(), summary["methods"].end(),
                    [](const auto& e) { return e["addedFlicker"].template get<double>() == 0.0; });
    EXPECT_EQ(r.output.find("0 for every method: no method's visibility changed") !=
                  std::string::npos,
              flickerAllZero);
    // The screenshot is the page as asked, with the charts' colours in it.
    const ByteImage shot = readPng(screenshot);
    ASSERT_EQ(shot.width, kShotW);
    ASSERT_EQ(shot.height, kShotH);
    std::size_t blue = 0, orange = 0; // the first two series' colours, #1f77b4 and #ff7f0e
    for (std::size_t i = 0; i + 3 < shot.data.size(); i += 4) {
        const std::uint8_t* p = &shot.data[i];
        blue += p[0] == 0x1f && p[1] == 0x77 && p[2] == 0xb4;
        orange += p[0] == 0xff && p[1] == 0x7f && p[2] == 0x0e;
    }
    EXPECT_GT(blue, 1000u) << screenshot;
    EXPECT_GT(orange, 50u) << screenshot;
}

// One run (about 20 s on llvmpipe), every check on its outputs; the report check needs Chromium.
TEST(CaptureRun, ShortScriptWritesEverythingAndTheReportShowsEveryChart) {
    const fs::path dir = outputDir("capture_short");
    fs::remove_all(dir);
    const Outcome r = capture(example("short.json"), dir);
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("wrote"), std::string::npos) << r.output;
    checkFiles(dir);
    checkCsv(dir);
    checkSummary(dir);
    const std::string chromium = FLOODLIGHT_CHROMIUM;
    if (chromium.empty())
        GTEST_SKIP() << "the files are checked; chromium not found for the report (scripts/"
                        "setup.sh installs it)";
    checkReportInChromium(dir, chromium);
}

// Writes a script into the test's folder.
fs::path scriptFile(const std::string& name, const std::string& text) {
    const fs::path p = outputDir("capture_bad") / name;
    std::ofstream(p) << text;
    return p;
}

// Runs a 2-frame, 32² capture of the default walkthrough with `fields` (the script's
// "reference" and "methods") into the test output folder `name`; returns the run.
Outcome tinyCapture(const std::string& name, const std::string& fields) {
    const fs::path dir = outputDir(name);
    fs::remove_all(dir);
    return capture(scriptFile(name + ".json", R"({"camera": {"frames": 2, "path": "default"}, )"
                                              R"("resolutions": [[32, 32]], )" +
                                                  fields + "}"),
                   dir);
}

// The script's terminator offset reaches the ray tracer: the reference without it is the entry
// without it, and the default view's low-poly objects make the two differ at their terminator.
// (An entry is the reference itself when every option it gives has the reference's value, so
// the "on" entry says so.)
TEST(CaptureRun, TheRayTracedReferenceTakesTheTerminatorOffset) {
    const fs::path dir = outputDir("capture_terminator");
    fs::remove_all(dir);
    const Outcome r = capture(
        scriptFile("capture_terminator.json",
                   R"({"camera": {"frames": 1, "path": "default"}, "resolutions": [[64, 64]],
                       "reference": {"kind": "raytrace", "samples": 16, "terminatorOffset": "off"},
                       "methods": [{"method": "raytrace", "samples": 16,
                                    "terminatorOffset": "on", "label": "on"},
                                   {"method": "raytrace", "samples": 16,
                                    "terminatorOffset": "off", "label": "off"}]})"),
        dir);
    ASSERT_EQ(r.code, 0) << r.output;
    const nlohmann::json summary = nlohmann::json::parse(fileContents(dir / "summary.json"));
    EXPECT_EQ(summary["reference"]["terminatorOffset"], "off");
    std::map<std::string, double> rmse;
    for (const auto& m : summary["methods"]) rmse[m["label"]] = m["rmse"].get<double>();
    EXPECT_EQ(rmse.at("off"), 0.0);
    EXPECT_GT(rmse.at("on"), 0.0);
}

// The bug: an entry of the reference's method with other options ({"method": "reference",
// "mapSize": 512} beside a 256² reference) was taken for the reference itself and scored 0.
TEST(CaptureRun, AnEntryOfTheReferencesMethodWithOtherOptionsIsAMethodOfItsOwn) {
    const Outcome r = tinyCapture("capture_reference_entries",
                                  R"("reference": {"samples": 16, "mapSize": 256},
           "methods": [{"method": "reference", "mapSize": 512, "label": "maps 512"}, "reference",
                       {"method": "reference", "mapSize": 256, "label": "same"}])");
    ASSERT_EQ(r.code, 0) << r.output;
    const nlohmann::json summary = nlohmann::json::parse(
        fileContents(outputDir("capture_reference_entries") / "summary.json"));
    std::map<std::string, double> rmse;
    for (const auto& m : summary["methods"]) rmse[m["label"]] = m["rmse"].get<double>();
    EXPECT_GT(rmse.at("maps 512"), 0.0);
    EXPECT_EQ(rmse.at("reference"), 0.0);
    EXPECT_EQ(rmse.at("same"), 0.0); // the reference's own options: the reference itself
}

TEST(CaptureRun, TheRayTracedReferenceIsUsedAndNamed) {
    // Two tiny frames against the ray-traced ground truth: the metrics come from its lane, and
    // the summary and report say which reference it was.
    const Outcome r = tinyCapture("capture_raytrace",
                                  R"("reference": {"kind": "raytrace", "samples": 16},
                                     "methods": ["hard", "raytrace"])");
    const fs::path dir = outputDir("capture_raytrace");
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("reference: raytrace: 16 shadow rays per pixel"), std::string::npos)
        << r.output;
    const nlohmann::json summary = nlohmann::json::parse(fileContents(dir / "summary.json"));
    EXPECT_EQ(summary["reference"]["kind"], "raytrace");
    EXPECT_EQ(summary["reference"]["method"], "raytrace");
    EXPECT_FALSE(summary["reference"].contains("mapSize"));
    EXPECT_EQ(summary["reference"]["terminatorOffset"], "on");
    for (const auto& m : summary["methods"]) {
        // The raytrace entry is the reference against itself; hard is not.
        if (m["method"] == "raytrace")
            EXPECT_EQ(m["rmse"].get<double>(), 0.0);
        else
            EXPECT_GT(m["rmse"].get<double>(), 0.0);
        // Acne and peter-panning, shares in [0, 1]; none for the reference itself.
        for (const char* key : {"acne", "peterPanning"}) {
            ASSERT_TRUE(m.contains(key)) << key;
            EXPECT_GE(m[key].get<double>(), 0.0);
            EXPECT_LE(m[key].get<double>(), 1.0);
            if (m["method"] == "raytrace") {
                EXPECT_EQ(m[key].get<double>(), 0.0) << key;
            }
        }
    }
    EXPECT_TRUE(summary["definitions"].contains("acne"));
    EXPECT_TRUE(summary["definitions"].contains("peterPanning"));
    const std::string csv = fileContents(dir / "frames.csv");
    const std::string header = csv.substr(0, csv.find('\n'));
    for (const char* column :
         {"acne_percent", "acne_candidates", "peter_panning_percent", "peter_panning_candidates"})
        EXPECT_NE(header.find(column), std::string::npos) << column;
    const std::string report = fileContents(dir / "report.html");
    EXPECT_NE(report.find("raytrace: 16 shadow rays per pixel (Embree)"), std::string::npos);
    EXPECT_NE(report.find("<th>acne %</th><th>peter-panning %</th>"), std::string::npos);
    EXPECT_NE(r.output.find("acne%"), std::string::npos) << r.output;
}

void expectCleanFailure(const Outcome& r, const std::string& named, const fs::path& out) {
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find(named), std::string::npos) << "expected '" << named << "' in\n"
                                                       << r.output;
    EXPECT_FALSE(fs::exists(out / "report.html")) << out;
    EXPECT_FALSE(fs::exists(out / "summary.json")) << out;
}

TEST(CaptureBadInput, ScriptErrorsNameTheField) {
    const fs::path out = outputDir("capture_bad") / "out";
    const std::string camera = R"("camera": {"frames": 3, "path": "default"})";
    expectCleanFailure(
        capture(scriptFile("unknown.json",
                           "{" + camera + R"(, "methods": ["hard", "no-such-method"]})"),
                out),
        "methods[1]: unknown method \"no-such-method\"", out);
    expectCleanFailure(
        capture(scriptFile("zero.json",
                           R"({"camera": {"frames": 0, "path": "default"}, "methods": ["hard"]})"),
                out),
        "camera.frames", out);
    expectCleanFailure(capture(scriptFile("incomplete.json", "{" + camera + "}"), out),
                       "methods: missing", out);
    expectCleanFailure(capture(scriptFile("broken.json", "{" + camera), out), "not valid JSON",
                       out);
    expectCleanFailure(capture(outputDir("capture_bad") / "absent.json", out), "absent.json", out);
    // 6 JFA-E passes reach 63 pixels: more than an 8x8 frame holds ("auto", the default,
    // chooses what fits).
    expectCleanFailure(
        capture(scriptFile("eye.json", "{" + camera +
                                           R"(, "jfaPasses": 6, "resolutions": [[8, 8]], )"
                                           R"("methods": ["jfa-e"]})"),
                out),
        "jfaPasses at 8x8", out);
}

TEST(CaptureBadInput, UnwritableFolderIsOneClearError) {
    // A regular file where a folder is needed cannot be written into, even by root.
    const fs::path blocker = outputDir("capture_bad") / "a-file";
    std::ofstream(blocker) << "x";
    const Outcome r = capture(example("short.json"), blocker / "out");
    expectCleanFailure(r, "--out " + (blocker / "out").string(), blocker / "out");
}

TEST(CaptureBadInput, FailedRunLeavesNoOldReportBehind) {
    // An earlier run's report and summary in the folder; this run fails (its scene is missing)
    // after the folder was prepared: neither may be left looking like this run's results.
    const fs::path out = outputDir("capture_bad") / "stale";
    fs::create_directories(out);
    std::ofstream(out / "report.html") << "<html>old</html>";
    std::ofstream(out / "summary.json") << "{}";
    const Outcome r =
        capture(scriptFile("missing_scene.json",
                           R"({"scene": "nowhere.glb", "camera": {"frames": 2, "path": "default"},
                       "methods": ["hard"]})"),
                out);
    expectCleanFailure(r, "nowhere.glb", out);
}

} // namespace
} // namespace fl::test
