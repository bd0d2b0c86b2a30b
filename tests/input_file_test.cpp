// base/InputFile.h, the one reader of user-named files (issue 16): regular files only, after
// following links, within a size limit, with one message naming the role, the path and the
// problem. Before it, a FIFO was read forever and a directory gave "basic_filebuf::underflow".

#include "TestPaths.h"

#include <base/InputFile.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <sys/stat.h>

namespace fl::test {
namespace {

namespace fs = std::filesystem;

fs::path fresh(const std::string& name) {
    const fs::path p = outputDir("input_file") / name;
    std::error_code ec;
    fs::remove_all(p, ec);
    return p;
}

/// The message of the InputFileError reading `path` throws ("" if it reads).
std::string errorOf(const fs::path& path, std::uintmax_t limitMiB = 1) {
    try {
        readInputFile(path, "--points", limitMiB);
    } catch (const InputFileError& e) {
        return e.what();
    }
    return {};
}

TEST(InputFile, ReadsARegularFileAndALinkToOne) {
    const fs::path file = fresh("points.xy");
    std::ofstream(file) << "1 2\n3 4\n";
    EXPECT_EQ(readInputFile(file, "--points", 1), "1 2\n3 4\n");
    const fs::path link = fresh("link.xy");
    fs::create_symlink(file, link);
    EXPECT_EQ(readInputFile(link, "", 1), "1 2\n3 4\n");
    const std::vector<unsigned char> padded = readInputBytes(file, "", 1, 3);
    ASSERT_EQ(padded.size(), 11u);
    EXPECT_EQ(padded[7], '\n');
    EXPECT_EQ(padded[10], 0);
    EXPECT_EQ(inputFileProblem(file, 1), "");
    const fs::path empty = fresh("empty.xy");
    std::ofstream{empty};
    EXPECT_EQ(readInputFile(empty, "", 1), "");
}

TEST(InputFile, AFifoIsRefusedWithoutBlocking) {
    const fs::path fifo = fresh("fifo.xy");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(errorOf(fifo), "--points " + fifo.string() + ": not a regular file (a FIFO)");
    // A link to it is the FIFO too (links are followed).
    const fs::path link = fresh("fifo_link.xy");
    fs::create_symlink(fifo, link);
    EXPECT_EQ(errorOf(link), "--points " + link.string() + ": not a regular file (a FIFO)");
    EXPECT_EQ(inputFileProblem(link, 1), "not a regular file (a FIFO)");
}

TEST(InputFile, DirectoriesDevicesAndMissingFilesAreRefused) {
    const fs::path dir = fresh("folder.json");
    fs::create_directories(dir);
    EXPECT_EQ(errorOf(dir), "--points " + dir.string() + ": not a regular file (a directory)");
    EXPECT_EQ(errorOf("/dev/zero"), "--points /dev/zero: not a regular file (a character device)");
    const fs::path missing = fresh("missing.xy");
    EXPECT_EQ(errorOf(missing), "--points " + missing.string() + ": does not exist");
    EXPECT_EQ(errorOf(missing / "below"),
              "--points " + (missing / "below").string() + ": does not exist");
    const fs::path dangling = fresh("dangling.xy");
    fs::create_symlink(missing, dangling);
    EXPECT_EQ(errorOf(dangling), "--points " + dangling.string() + ": does not exist");
    try {
        readInputBytes(dir, "", 1);
        ADD_FAILURE() << "no error";
    } catch (const InputFileError& e) {
        EXPECT_EQ(std::string(e.what()), dir.string() + ": not a regular file (a directory)");
        EXPECT_EQ(e.role(), "");
        EXPECT_EQ(e.path(), dir.string());
        EXPECT_EQ(e.problem(), "not a regular file (a directory)");
    }
}

TEST(InputFile, TheSizeLimitIsEnforced) {
    const fs::path file = fresh("big.xy");
    { std::ofstream(file) << "x"; }
    fs::resize_file(file, (std::uintmax_t{1} << 20) + 1); // sparse: no disk space used
    EXPECT_EQ(errorOf(file, 1), "--points " + file.string() + ": larger than the limit of 1 MiB");
    EXPECT_EQ(readInputFile(file, "", 2).size(), (std::size_t{1} << 20) + 1);
    fs::resize_file(file, std::uintmax_t{1} << 20); // exactly the limit: accepted
    EXPECT_EQ(errorOf(file, 1), "");
}

} // namespace
} // namespace fl::test
