#include "base/InputFile.h"

#include <base/Text.h>

#include <cerrno>
#include <cstring>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fl {

namespace {

constexpr std::uintmax_t kMiB = std::uintmax_t{1} << 20;

/// What a non-regular file is, for the message.
std::string kindOf(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a file";
}

std::string tooLarge(std::uintmax_t limitMiB) {
    return "larger than the limit of " + std::to_string(limitMiB) + " MiB";
}

/// The problem with a stat() result; empty when it is a regular file within the limit.
std::string statProblem(const struct stat& st, std::uintmax_t limitMiB) {
    if (!S_ISREG(st.st_mode)) return "not a regular file (" + kindOf(st.st_mode) + ")";
    if (static_cast<std::uintmax_t>(st.st_size) > limitMiB * kMiB) return tooLarge(limitMiB);
    return {};
}

std::string openProblem(int err) {
    if (err == ENOENT || err == ENOTDIR) return "does not exist";
    return "cannot open: " + systemMessage(err);
}

/// Owns a descriptor.
struct Fd {
    int fd = -1;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

/// Appends the file's bytes to `out` (a std::string or byte vector).
template <class Buffer>
void readInto(const std::filesystem::path& path, std::string_view role, std::uintmax_t limitMiB,
              Buffer& out) {
    const auto fail = [&](std::string problem) {
        throw InputFileError(std::string(role), path.string(), std::move(problem));
    };
    // stat() first so that opening never touches a device or blocks on a FIFO; then fstat() the
    // open descriptor, in case the path was replaced in between. O_NONBLOCK keeps even that
    // open from waiting for a FIFO's writer.
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) fail(openProblem(errno));
    if (std::string p = statProblem(st, limitMiB); !p.empty()) fail(p);
    Fd file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
    if (file.fd < 0) fail(openProblem(errno));
    if (::fstat(file.fd, &st) != 0) fail("cannot read: " + systemMessage(errno));
    if (std::string p = statProblem(st, limitMiB); !p.empty()) fail(p);

    // Read to the end rather than st_size bytes (the file may change), but never past the limit.
    // A small probe past the expected end finds growth without reallocating a large buffer.
    const std::uintmax_t limit = limitMiB * kMiB;
    const std::size_t start = out.size();
    std::size_t have = 0;
    out.resize(start + static_cast<std::size_t>(st.st_size));
    char probe[4096];
    for (;;) {
        const bool full = have == out.size() - start;
        const ssize_t n = full ? ::read(file.fd, probe, sizeof probe)
                               : ::read(file.fd, &out[start + have], out.size() - start - have);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail("cannot read: " + systemMessage(errno));
        }
        if (n == 0) break;
        if (full) out.insert(out.end(), probe, probe + n);
        have += static_cast<std::size_t>(n);
        if (have > limit) fail(tooLarge(limitMiB));
    }
    out.resize(start + have);
}

std::string withRole(const std::string& role, const std::string& path, const std::string& problem) {
    return (role.empty() ? path : role + " " + path) + ": " + problem;
}

} // namespace

InputFileError::InputFileError(std::string role, std::string path, std::string problem)
    : std::runtime_error(withRole(role, path, problem)), role_(std::move(role)),
      path_(std::move(path)), problem_(std::move(problem)) {}

std::vector<unsigned char> readInputBytes(const std::filesystem::path& path, std::string_view role,
                                          std::uintmax_t limitMiB, std::size_t padding) {
    std::vector<unsigned char> out;
    readInto(path, role, limitMiB, out);
    out.resize(out.size() + padding, 0);
    return out;
}

std::string readInputFile(const std::filesystem::path& path, std::string_view role,
                          std::uintmax_t limitMiB) {
    std::string out;
    readInto(path, role, limitMiB, out);
    return out;
}

std::string inputFileProblem(const std::filesystem::path& path, std::uintmax_t limitMiB) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return openProblem(errno);
    return statProblem(st, limitMiB);
}

} // namespace fl
