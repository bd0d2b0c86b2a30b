// base/OutputFiles.h: files appear whole (temporary sibling, then rename), and a command's set
// of outputs appears together or not at all.

#include "TestPaths.h"

#include <base/OutputFiles.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

namespace fl {
namespace {

namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
    const fs::path d = test::outputDir("output_files") / name;
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

std::size_t entries(const fs::path& dir) {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
    return n;
}

TEST(OutputFiles, AFileAppearsWholeAndLeavesNoTemporary) {
    const fs::path d = freshDir("single");
    writeFileAtomically(d / "a.txt", "hello");
    EXPECT_EQ(test::fileContents(d / "a.txt"), "hello");
    writeFileAtomically(d / "a.txt", "again"); // replaces
    EXPECT_EQ(test::fileContents(d / "a.txt"), "again");
    EXPECT_THROW(writeFileAtomically(d / "sub" / "b.txt", "x"), OutputFileError)
        << "the folder must exist";
    EXPECT_EQ(entries(d), 1u) << "no temporaries left";
    EXPECT_THROW(writeFileAtomically(d / "a.txt" / "c.txt", "x"), OutputFileError);
}

TEST(OutputFiles, ASetAppearsAtCommitOnly) {
    const fs::path d = freshDir("commit");
    {
        OutputSet set;
        writeFileAtomically(d / "a.txt", "1");
        const fs::path tmp = temporarySibling(d / "b.bin");
        std::ofstream(tmp) << "2";
        finishOutputFile(tmp, d / "b.bin");
        EXPECT_FALSE(fs::exists(d / "a.txt"));
        EXPECT_FALSE(fs::exists(d / "b.bin"));
        EXPECT_EQ(set.pending().size(), 2u);
        set.commit();
    }
    EXPECT_EQ(test::fileContents(d / "a.txt"), "1");
    EXPECT_EQ(test::fileContents(d / "b.bin"), "2");
    EXPECT_EQ(entries(d), 2u);
}

// Named after the bug: render with an unwritable --aliasing-map left its PNG and EXR behind.
TEST(OutputFiles, AFailureBeforeCommitLeavesNothing) {
    const fs::path d = freshDir("rollback");
    std::ofstream(d / "old.txt") << "kept";
    try {
        OutputSet set;
        writeFileAtomically(d / "frame.png", "png");
        writeFileAtomically(d / "old.txt", "replaced?");
        writeFileAtomically(d / "old.txt" / "aliasing.png", "fails: a file is not a folder");
        set.commit();
        FAIL() << "the third file cannot be written";
    } catch (const OutputFileError& e) {
        EXPECT_NE(std::string(e.what()).find("aliasing.png"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(d / "frame.png"));
    EXPECT_EQ(test::fileContents(d / "old.txt"), "kept")
        << "an existing file is replaced only at commit";
    EXPECT_EQ(entries(d), 1u) << "no temporaries left";
}

TEST(OutputFiles, ANestedSetHandsItsFilesToTheOuterOne) {
    const fs::path d = freshDir("nested");
    {
        OutputSet outer;
        {
            OutputSet inner;
            writeFileAtomically(d / "inner.txt", "i");
            inner.commit();
        }
        EXPECT_FALSE(fs::exists(d / "inner.txt")) << "the outer set decides";
        writeFileAtomically(d / "outer.txt", "o");
        // No commit: both are dropped.
    }
    EXPECT_EQ(entries(d), 0u);
    writeFileAtomically(d / "after.txt", "a"); // no set open any more: written at once
    EXPECT_TRUE(fs::exists(d / "after.txt"));
}

// A run killed mid-write leaves its hidden temporary; the folder it is continued in (capture
// --resume) sheds those of dead processes, and keeps a live writer's and every other file.
TEST(OutputFiles, TemporariesOfKilledWritersAreRemovedAndNothingElse) {
    const fs::path d = freshDir("killed");
    fs::create_directories(d / "frames");
    const std::string mine = ".b.png.tmp" + std::to_string(::getpid()) + ".0";
    for (const fs::path& f : {d / "frames" / ".a.exr.tmp999999999.3", d / mine, d / "keep.png",
                              d / ".hidden", d / "x.tmp12.1"})
        std::ofstream(f) << "x";
    EXPECT_EQ(removeKilledTemporaries(d), 1u);
    EXPECT_FALSE(fs::exists(d / "frames" / ".a.exr.tmp999999999.3"));
    for (const fs::path& f : {d / mine, d / "keep.png", d / ".hidden", d / "x.tmp12.1"})
        EXPECT_TRUE(fs::exists(f)) << f;
}

// A killed writer its parent has not reaped yet (a zombie, which kill(pid, 0) still finds) is
// dead too: its temporary goes (seen in capture_resume_cli_test before it reaped its run).
TEST(OutputFiles, TemporariesOfAnUnreapedKilledWriterAreRemoved) {
    const fs::path d = freshDir("zombie");
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) ::_exit(0); // exits at once and stays a zombie until waited for
    // Wait until it is a zombie (state Z), without reaping it.
    for (int i = 0; i < 500; ++i) {
        std::ifstream stat("/proc/" + std::to_string(child) + "/stat");
        std::string line;
        std::getline(stat, line);
        const std::size_t close = line.rfind(')');
        if (close != std::string::npos && close + 2 < line.size() && line[close + 2] == 'Z') break;
        ::usleep(2000);
    }
    const fs::path tmp = d / (".c.png.tmp" + std::to_string(child) + ".0");
    std::ofstream(tmp) << "x";
    EXPECT_EQ(removeKilledTemporaries(d), 1u);
    EXPECT_FALSE(fs::exists(tmp));
    int status = 0;
    ::waitpid(child, &status, 0);
}

} // namespace
} // namespace fl
