// `floodlight capture --capture-threads N`: the pipelined capture (frames read back a frame
// behind, files, metrics and progress on N workers) writes the same outputs as the synchronous
// one (N = 0) — every frame file and worst-frame picture byte for byte, the CSV and summary but
// their times — and records where its time went (summary.json's "phaseSplit"); `auto` takes
// no workers on a software rasterizer and 1 to 4 elsewhere; a thread count out of range is a
// usage error with one message.
//
// Two runs of a small script (each process compiles its methods' shaders: about 10 s each).

#include "CaptureOutputs.h"
#include "CliRun.h"
#include "TestPaths.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fl::test {
namespace {

namespace fs = std::filesystem;

// A reference entry (lane 0 read twice), a flooding method with its counterpart (its |dI|
// buckets) and frames written: every kind of task the pipeline runs.
constexpr const char* kScript = R"({
  "scene": "default",
  "camera": {"frames": 4, "path": "default"},
  "light": {"radius": 1.5},
  "resolutions": [[48, 32]],
  "shadowMap": {"provider": "uniform", "size": 256},
  "reference": {"samples": 16, "mapSize": 256},
  "methods": ["hard", "pcss:16/24", "jfa-e", "flood-e", "reference"],
  "saveFrames": true
})";

const fs::path& root() {
    static const fs::path r = [] {
        const fs::path d = outputDir("capture_threads") / std::to_string(::getpid());
        fs::remove_all(d);
        fs::create_directories(d);
        std::ofstream(d / "script.json") << kScript;
        return d;
    }();
    return r;
}

Outcome capture(const fs::path& out, const std::string& flags) {
    return runCommand(std::string(FLOODLIGHT_BINARY) + " capture " +
                      (root() / "script.json").string() + " --out " + out.string() + " " + flags);
}

TEST(CaptureThreads, PipelinedWritesWhatTheSynchronousRunWrites) {
    const fs::path sync = root() / "sync", piped = root() / "piped";
    const Outcome a = capture(sync, "--capture-threads 0");
    ASSERT_EQ(a.code, 0) << a.output;
    const Outcome b = capture(piped, "--capture-threads 3");
    ASSERT_EQ(b.code, 0) << b.output;
    EXPECT_NE(a.output.find("phase split, s (synchronous)"), std::string::npos) << a.output;
    EXPECT_NE(b.output.find("phase split, s (3 worker threads)"), std::string::npos) << b.output;

    // Every frame file and worst-frame picture, byte for byte, and no file more or less.
    std::size_t files = 0;
    for (const char* sub : {"frames", "report"})
        for (const auto& e : fs::recursive_directory_iterator(sync / sub)) {
            if (!e.is_regular_file()) continue;
            ++files;
            const fs::path other = piped / fs::relative(e.path(), sync);
            ASSERT_TRUE(fs::is_regular_file(other)) << other;
            EXPECT_TRUE(fileContents(other) == fileContents(e.path())) << other << " differs";
        }
    std::size_t pipedFiles = 0;
    for (const char* sub : {"frames", "report"})
        for (const auto& e : fs::recursive_directory_iterator(piped / sub))
            pipedFiles += e.is_regular_file();
    EXPECT_EQ(pipedFiles, files);
    // 4 frames x 5 lanes (hard, pcss, jfa-e, flood-e, reference) x 3 files, 5 worst pictures.
    EXPECT_EQ(files, 4u * 5u * 3u + 5u);
    EXPECT_EQ(untimedCsv(piped), untimedCsv(sync));
    EXPECT_EQ(untimedSummary(piped), untimedSummary(sync));
    for (const auto& e : fs::recursive_directory_iterator(piped))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

TEST(CaptureThreads, TheSummaryRecordsThePhaseSplit) {
    const fs::path out = root() / "split";
    const Outcome o = capture(out, "--capture-threads 2");
    ASSERT_EQ(o.code, 0) << o.output;
    const nlohmann::json j = nlohmann::json::parse(fileContents(out / "summary.json"));
    ASSERT_TRUE(j.contains("phaseSplit")) << j.dump(2);
    const nlohmann::json& s = j["phaseSplit"];
    EXPECT_EQ(s["threads"], 2);
    for (const char* key :
         {"wallSeconds", "renderSeconds", "readBackSeconds", "metricsSeconds", "filesSeconds",
          "progressSeconds", "waitingSeconds", "outsideRenderingShare", "progressMedianMs",
          "progressShareOfRendering"}) {
        ASSERT_TRUE(s.contains(key)) << key;
        EXPECT_GE(s[key].get<double>(), 0.0) << key;
    }
    // Every frame renders, writes files and keeps its progress: none of those can be 0.
    for (const char* key : {"renderSeconds", "filesSeconds", "progressSeconds"})
        EXPECT_GT(s[key].get<double>(), 0.0) << key;
    EXPECT_LT(s["renderSeconds"].get<double>(), s["wallSeconds"].get<double>());
    EXPECT_LE(s["outsideRenderingShare"].get<double>(), 1.0);
}

TEST(CaptureThreads, AutoTakesNoWorkersOnASoftwareRasterizer) {
    const fs::path out = root() / "auto";
    const Outcome o = capture(out, ""); // auto is the default
    ASSERT_EQ(o.code, 0) << o.output;
    const nlohmann::json j = nlohmann::json::parse(fileContents(out / "summary.json"));
    const std::string context = j["context"].get<std::string>();
    const int threads = j["phaseSplit"]["threads"].get<int>();
    // gl::isSoftwareRenderer's names: Mesa's CPU rasterizers.
    if (context.find("llvmpipe") != std::string::npos ||
        context.find("softpipe") != std::string::npos)
        EXPECT_EQ(threads, 0) << context;
    else {
        EXPECT_GE(threads, 1) << context;
        EXPECT_LE(threads, 4) << context;
    }
}

TEST(CaptureThreads, AThreadCountOutOfRangeIsAUsageError) {
    for (const char* bad : {"17", "-1", "two"}) {
        const fs::path out = root() / "bad";
        const Outcome o = capture(out, std::string("--capture-threads ") + bad);
        EXPECT_EQ(o.code, 2) << bad << ": " << o.output;
        EXPECT_NE(o.output.find("--capture-threads: must be auto or an integer in [0, 16], got '" +
                                std::string(bad) + "'"),
                  std::string::npos)
            << o.output;
        EXPECT_FALSE(fs::exists(out / "summary.json"));
    }
}

} // namespace
} // namespace fl::test
