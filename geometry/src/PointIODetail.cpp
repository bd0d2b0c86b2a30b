#include "PointIODetail.h"

#include <geometry/PointIO.h>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace fl::geom::detail {

void appendDouble(std::string& out, double v) {
    char buffer[32]; // the longest shortest-round-trip double is 24 characters
    const auto [p, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    if (ec != std::errc{}) throw std::logic_error("appendDouble: buffer too small");
    out.append(buffer, p);
}

void appendRounded(std::string& out, double v, int digits) {
    char buffer[48];
    const auto [p, ec] =
        std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::general, digits);
    if (ec != std::errc{}) throw std::logic_error("appendRounded: buffer too small");
    out.append(buffer, p);
}

void appendUint(std::string& out, std::uint64_t v) {
    char buffer[24];
    const auto [p, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    if (ec != std::errc{}) throw std::logic_error("appendUint: buffer too small");
    out.append(buffer, p);
}

namespace {

std::string systemMessage(int err) {
    return std::error_code(err, std::generic_category()).message();
}

// Closes a descriptor and removes the temporary file unless released (the success path).
class TempFile {
  public:
    TempFile(std::filesystem::path path, int fd) : path_(std::move(path)), fd_(fd) {}
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;
    ~TempFile() {
        if (fd_ >= 0) ::close(fd_);
        if (!released_) ::unlink(path_.c_str());
    }
    [[nodiscard]] int fd() const { return fd_; }
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }
    /// Closes the descriptor; returns errno of a failed close (delayed write errors), else 0.
    int close() {
        const int rc = ::close(fd_);
        fd_ = -1;
        return rc == 0 ? 0 : errno;
    }
    void release() { released_ = true; }

  private:
    std::filesystem::path path_;
    int fd_ = -1;
    bool released_ = false;
};

} // namespace

void writeFileAtomically(const std::filesystem::path& path, std::string_view contents) {
    const std::string name = path.string();
    if (!path.has_filename()) throw PointFileError(name, "cannot write: not a file name");

    // A hidden name in the same folder, so the final rename stays within one file system (and is
    // atomic); pid and counter keep concurrent writers, threads or processes, apart.
    static std::atomic<unsigned> counter{0};
    int fd = -1;
    std::filesystem::path tmp;
    for (int attempt = 0; fd < 0; ++attempt) {
        // Appends, not operator+ chains: GCC 12 at -O3 warns falsely (-Wrestrict) about those.
        std::string leaf = ".";
        leaf += path.filename().string();
        leaf += ".tmp";
        leaf += std::to_string(::getpid());
        leaf += '.';
        leaf += std::to_string(counter.fetch_add(1));
        tmp = path.parent_path() / leaf;
        fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0 && (errno != EEXIST || attempt > 100)) {
            throw PointFileError(name, "cannot create temporary file " + tmp.string() + ": " +
                                           systemMessage(errno));
        }
    }
    TempFile file(tmp, fd);

    const char* p = contents.data();
    std::size_t left = contents.size();
    while (left > 0) {
        const ssize_t n = ::write(file.fd(), p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw PointFileError(name, "cannot write: " + systemMessage(errno));
        }
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    if (const int err = file.close(); err != 0)
        throw PointFileError(name, "cannot write: " + systemMessage(err));
    if (::rename(tmp.c_str(), path.c_str()) != 0)
        throw PointFileError(name, "cannot replace: " + systemMessage(errno));
    file.release();
}

void requireFinite(const std::vector<glm::dvec2>& points, const char* what) {
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y)) {
            throw std::invalid_argument(std::string(what) + ": point " + std::to_string(i) +
                                        " is not finite");
        }
    }
}

void requireTriangles(const std::vector<glm::dvec2>& points,
                      const std::vector<std::uint32_t>& triangles, const char* what) {
    if (triangles.size() % 3 != 0) {
        throw std::invalid_argument(std::string(what) + ": " + std::to_string(triangles.size()) +
                                    " triangle indices is not a multiple of 3");
    }
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        if (triangles[i] >= points.size()) {
            throw std::invalid_argument(std::string(what) + ": triangle " + std::to_string(i / 3) +
                                        " refers to vertex " + std::to_string(triangles[i]) +
                                        " but there are " + std::to_string(points.size()) +
                                        " points");
        }
    }
}

} // namespace fl::geom::detail
