// `floodlight capture --resume`: a run stopped (--stop-after) or killed (SIGKILL) and resumed
// gives the same CSV rows (every column but the times), summary and worst-frame pictures as a
// run without a break, and renders only the frames it lacked; a changed script, a damaged journal
// and a missing frame file are refused with one message naming what is wrong.
//
// The three tests that compare with a run without a break take 30-50 s in release: each starts
// `floodlight` three to five times (the unbroken run, the stopped runs, the resumes), and each
// process compiles every method's shaders (about 10 s on llvmpipe; frames are a small part).
// The script below is already the smallest with what they check: two resolutions, a reference
// lane and both flooding methods with their counterparts, at 32 x 32 and 48 x 32 pixels.

#include "CaptureOutputs.h"
#include "CliRun.h"
#include "TestPaths.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <unistd.h>

namespace fl::test {
namespace {

namespace fs = std::filesystem;

// Two resolutions (the journal crosses from one to the next), a `reference` entry (it reads the
// ground truth's lane) and both flooding methods with their counterparts (their |dI| buckets).
constexpr const char* kScript = R"({
  "scene": "default",
  "camera": {"frames": 3, "path": "default"},
  "light": {"radius": 1.5},
  "resolutions": [[32, 32], [48, 32]],
  "shadowMap": {"provider": "uniform", "size": 256},
  "reference": {"samples": 16, "mapSize": 256},
  "methods": ["hard", "jfa-e", "flood-e", "reference"]
})";
constexpr int kTotal = 6; // 3 frames x 2 resolutions

// ctest runs each test in its own process, several at once: every process writes its own
// folders (the script too, so that none reads a file another is writing).
const fs::path& root() {
    static const fs::path r = [] {
        const fs::path d = outputDir("capture_resume") / std::to_string(::getpid());
        fs::remove_all(d);
        fs::create_directories(d);
        std::ofstream(d / "script.json") << kScript;
        return d;
    }();
    return r;
}

// The runs stopped, killed and resumed go through the pipeline (workers, frames read back a
// frame behind); the run without a break they are compared with is the synchronous one.
Outcome capture(const fs::path& out, const std::string& flags = {},
                const fs::path& script = root() / "script.json",
                const std::string& threads = "--capture-threads 2") {
    return runCommand(std::string(FLOODLIGHT_BINARY) + " capture " + script.string() + " --out " +
                      out.string() + " " + threads + " " + flags);
}

// The run without a break every other run is compared with (once per test program).
const fs::path& unbroken() {
    static const fs::path d = [] {
        const fs::path out = root() / "unbroken";
        const Outcome o = capture(out, {}, root() / "script.json", "--capture-threads 0");
        EXPECT_EQ(o.code, 0) << o.output;
        return out;
    }();
    return d;
}

void expectSameAsUnbroken(const fs::path& dir) {
    ASSERT_TRUE(fs::is_regular_file(dir / "summary.json"));
    EXPECT_EQ(untimedCsv(dir), untimedCsv(unbroken()));
    EXPECT_EQ(untimedSummary(dir), untimedSummary(unbroken()));
    for (const auto& e : fs::directory_iterator(unbroken() / "report"))
        EXPECT_EQ(fileContents(dir / "report" / e.path().filename()), fileContents(e.path()))
            << e.path().filename() << ": the worst frame's picture differs";
    std::size_t frames = 0, unbrokenFrames = 0;
    for (const auto& e : fs::recursive_directory_iterator(dir / "frames"))
        frames += e.is_regular_file();
    for (const auto& e : fs::recursive_directory_iterator(unbroken() / "frames"))
        unbrokenFrames += e.is_regular_file();
    EXPECT_EQ(frames, unbrokenFrames);
    // The progress goes with the finished run, and no temporary is left anywhere.
    EXPECT_FALSE(fs::exists(dir / "progress.jsonl"));
    EXPECT_FALSE(fs::exists(dir / "resume"));
    for (const auto& e : fs::recursive_directory_iterator(dir))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

int finishedFrames(const fs::path& dir) {
    std::ifstream in(dir / "progress.jsonl");
    int lines = 0;
    for (std::string line; std::getline(in, line);) ++lines;
    return lines - 1; // the header
}

TEST(CaptureResume, StoppedTwiceAndResumedGivesTheRunWithoutABreak) {
    const fs::path d = root() / "stopped";
    Outcome o = capture(d, "--stop-after 2");
    ASSERT_EQ(o.code, 3) << o.output;
    EXPECT_NE(o.output.find("2 of 6 finished"), std::string::npos) << o.output;
    EXPECT_FALSE(fs::exists(d / "summary.json")); // nothing claims a finished run
    EXPECT_EQ(finishedFrames(d), 2);
    // Across the boundary between the two resolutions.
    o = capture(d, "--resume --stop-after 2");
    ASSERT_EQ(o.code, 3) << o.output;
    EXPECT_NE(o.output.find("resuming: 2 of 6"), std::string::npos) << o.output;
    EXPECT_EQ(finishedFrames(d), 4);
    o = capture(d, "--resume");
    ASSERT_EQ(o.code, 0) << o.output;
    EXPECT_NE(o.output.find("resuming: 4 of 6"), std::string::npos) << o.output;
    expectSameAsUnbroken(d);

    // Resuming a finished capture does nothing, and says so.
    const std::string summary = fileContents(d / "summary.json");
    o = capture(d, "--resume");
    EXPECT_EQ(o.code, 0) << o.output;
    EXPECT_NE(o.output.find("nothing to resume"), std::string::npos) << o.output;
    EXPECT_EQ(fileContents(d / "summary.json"), summary);
}

TEST(CaptureResume, AKilledRunLosesAtMostTheFrameInFlight) {
    const fs::path d = root() / "killed";
    fs::remove_all(d);
    // SIGKILL once two frames are in the journal; the loop gives up if the run ends first. The
    // shell then waits for (reaps) it: until then the killed process still "exists" for
    // kill(pid, 0), and the resumed run would keep its temporary as a live run's.
    const Outcome killed = runCommand(
        std::string(FLOODLIGHT_BINARY) + " capture " + (root() / "script.json").string() +
        " --out " + d.string() +
        " --capture-threads 2 >/dev/null 2>&1 & pid=$!; while kill -0 $pid 2>/dev/null && " +
        "[ $(($(wc -l 2>/dev/null < " + (d / "progress.jsonl").string() +
        " || echo 0))) -lt 3 ]; do sleep 0.01; done; kill -9 $pid && { wait $pid; echo killed; }");
    ASSERT_NE(killed.output.find("killed"), std::string::npos)
        << "the run finished before it could be killed: " << killed.output;
    const int before = finishedFrames(d);
    ASSERT_GE(before, 2);
    ASSERT_LT(before, kTotal);
    const Outcome o = capture(d, "--resume");
    ASSERT_EQ(o.code, 0) << o.output;
    EXPECT_NE(o.output.find("resuming: " + std::to_string(before) + " of 6"), std::string::npos)
        << o.output;
    expectSameAsUnbroken(d);
}

TEST(CaptureResume, ATornLastLineIsTheFrameInFlight) {
    const fs::path d = root() / "torn";
    ASSERT_EQ(capture(d, "--stop-after 2").code, 3);
    std::ofstream(d / "progress.jsonl", std::ios::app) << R"({"size":0,"frame":2,"refer)";
    const Outcome o = capture(d, "--resume");
    ASSERT_EQ(o.code, 0) << o.output;
    EXPECT_NE(o.output.find("resuming: 2 of 6"), std::string::npos) << o.output;
    expectSameAsUnbroken(d);
}

TEST(CaptureResume, AChangedScriptIsRefusedAndAFreshRunStartsOver) {
    const fs::path d = root() / "changed";
    ASSERT_EQ(capture(d, "--stop-after 1").code, 3);
    const fs::path other = root() / "other.json";
    std::string text = kScript;
    text.replace(text.find("1.5"), 3, "1.25");
    std::ofstream(other) << text;
    Outcome o = capture(d, "--resume", other);
    EXPECT_EQ(o.code, 1) << o.output;
    EXPECT_NE(o.output.find("progress.jsonl: the unfinished run there is of another script"),
              std::string::npos)
        << o.output;
    EXPECT_EQ(finishedFrames(d), 1); // refused: its progress is untouched
    o = capture(d, "--stop-after 1", other);
    EXPECT_EQ(o.code, 3) << o.output;
    EXPECT_NE(o.output.find("discarding the unfinished capture"), std::string::npos) << o.output;
}

TEST(CaptureResume, MissingPicturesAndFramesAreNamed) {
    const fs::path d = root() / "missing";
    ASSERT_EQ(capture(d, "--stop-after 2").code, 3);
    const fs::path frame = d / "frames" / "32x32" / "jfa-e" / "frame_00001.exr";
    fs::remove(frame);
    Outcome o = capture(d, "--resume");
    EXPECT_EQ(o.code, 1) << o.output;
    EXPECT_NE(o.output.find(frame.string() + ": missing"), std::string::npos) << o.output;
    ASSERT_EQ(capture(d, "--stop-after 2").code, 3); // a fresh start
    const fs::path state = d / "resume" / "state_0_1.exr";
    ASSERT_TRUE(fs::exists(state));
    fs::remove(state);
    o = capture(d, "--resume");
    EXPECT_EQ(o.code, 1) << o.output;
    EXPECT_NE(o.output.find(state.string() + ": missing"), std::string::npos) << o.output;
}

TEST(CaptureResume, ResumeWithNothingToResumeStartsFromFrameZero) {
    const fs::path d = root() / "empty";
    fs::remove_all(d);
    const Outcome o = capture(d, "--resume --stop-after 1");
    EXPECT_EQ(o.code, 3) << o.output;
    EXPECT_NE(o.output.find("starting from frame 0"), std::string::npos) << o.output;
}

} // namespace
} // namespace fl::test
