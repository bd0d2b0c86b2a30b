#pragma once
// What every libFuzzer target here shares: the readers under test read files, so each input is
// written to one temporary file per process (removed at exit), and a broken promise of the reader
// aborts with its text, which libFuzzer reports as a crash with the input.

#include <fcntl.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <set>
#include <string>

namespace fl::fuzz {

/// "/tmp/fuzz_TARGET_PID.EXT", the same for every input of this process, removed at exit.
inline std::filesystem::path tempFile(const std::string& target, const std::string& ext) {
    static std::mutex m;
    static std::set<std::string> made;
    const std::string path = "/tmp/fuzz_" + target + "_" + std::to_string(::getpid()) + "." + ext;
    std::lock_guard lock(m);
    if (made.empty())
        std::atexit([] {
            for (const std::string& p : made) std::remove(p.c_str());
        });
    made.insert(path);
    return path;
}

/// Replaces the file's contents with the input. Overwritten in place and then cut to length:
/// opening with O_TRUNC makes ext4 flush the file on close (its replace-by-truncate heuristic),
/// about 2 ms an input instead of 30 us.
inline void writeInput(const std::filesystem::path& path, const std::uint8_t* data,
                       std::size_t size) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0600);
    bool ok = fd >= 0;
    for (std::size_t done = 0; ok && done < size;) {
        const ssize_t n = ::write(fd, data + done, size - done);
        ok = n > 0;
        done += ok ? static_cast<std::size_t>(n) : 0;
    }
    ok = ok && ::ftruncate(fd, static_cast<off_t>(size)) == 0;
    if (fd < 0 || ::close(fd) != 0 || !ok) std::abort(); // the fuzzer's problem, not the reader's
}

} // namespace fl::fuzz

/// Aborts, naming the broken promise, unless `ok`.
#define REQUIRE(ok)                                                                                \
    do {                                                                                           \
        if (!(ok)) {                                                                               \
            std::fprintf(stderr, "broken promise: %s (line %d)\n", #ok, __LINE__);                 \
            std::abort();                                                                          \
        }                                                                                          \
    } while (false)
