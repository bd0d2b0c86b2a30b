#include <base/OutputFiles.h>

#include <base/Text.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <regex>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace fl {

namespace {

thread_local OutputSet* current = nullptr;

// Whether process `pid` still runs. A killed process its parent has not reaped yet is a zombie:
// kill(pid, 0) still finds it, but it writes nothing any more (Linux: state Z or X in
// /proc/PID/stat, the field after the command name's closing parenthesis).
bool processRuns(pid_t pid) {
    if (pid == ::getpid()) return true;
    if (::kill(pid, 0) != 0 && errno != EPERM) return false;
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    if (!stat || !std::getline(stat, line)) return true; // no /proc: trust kill()
    const std::size_t close = line.rfind(')');
    if (close == std::string::npos || close + 2 >= line.size()) return true;
    const char state = line[close + 2];
    return state != 'Z' && state != 'X';
}

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& problem) {
    throw OutputFileError(path.string() + ": " + problem);
}

// An open descriptor that removes its file unless released.
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

// Creates the hidden sibling exclusively and returns it open; pid and counter keep concurrent
// writers (threads or processes) apart, and the same folder keeps the rename atomic.
TempFile createSibling(const std::filesystem::path& path) {
    if (!path.has_filename()) fail(path, "cannot write: not a file name");
    const std::filesystem::path dir = path.parent_path();
    static std::atomic<unsigned> counter{0};
    for (int attempt = 0;; ++attempt) {
        // Appends, not operator+ chains: GCC 12 at -O3 warns falsely (-Wrestrict) about those.
        std::string leaf = ".";
        leaf += path.filename().string();
        leaf += ".tmp";
        leaf += std::to_string(::getpid());
        leaf += '.';
        leaf += std::to_string(counter.fetch_add(1));
        std::filesystem::path tmp = dir / leaf;
        const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) return TempFile(std::move(tmp), fd);
        if (errno != EEXIST || attempt > 100)
            fail(path, "cannot create a temporary file beside it: " + systemMessage(errno));
    }
}

void renameInto(const std::filesystem::path& tmp, const std::filesystem::path& path) {
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        const int err = errno;
        ::unlink(tmp.c_str());
        fail(path, "cannot move the finished file into place: " + systemMessage(err));
    }
}

} // namespace

void makeOutputFolder(const std::filesystem::path& dir, std::string_view role) {
    if (dir.empty()) return;
    std::error_code ec;
    // The folders this call makes, outermost first: an uncommitted set removes them again.
    std::vector<std::filesystem::path> missing;
    for (std::filesystem::path p = dir; !p.empty() && !std::filesystem::exists(p, ec);
         p = p.parent_path()) {
        missing.insert(missing.begin(), p);
        if (p == p.parent_path()) break;
    }
    std::filesystem::create_directories(dir, ec);
    if (current && !ec)
        current->folders_.insert(current->folders_.end(), missing.begin(), missing.end());
    if (ec || !std::filesystem::is_directory(dir))
        throw OutputFileError((role.empty() ? std::string() : std::string(role) + " ") +
                              dir.string() + ": cannot create the folder (" +
                              (ec ? ec.message() : std::string("a file is in the way")) + ")");
}

void checkOutputFolder(const std::filesystem::path& dir, std::string_view role) {
    const std::string who = (role.empty() ? std::string() : std::string(role) + " ") +
                            (dir.empty() ? std::string(".") : dir.string()) + ": ";
    std::error_code ec;
    // The nearest part of the path that exists must be a writable folder.
    std::filesystem::path p = dir.empty() ? std::filesystem::path(".") : dir;
    while (!std::filesystem::exists(p, ec)) {
        const std::filesystem::path up = p.parent_path();
        if (up.empty() || up == p) {
            p = std::filesystem::current_path(ec);
            break;
        }
        p = up;
    }
    if (!std::filesystem::is_directory(p, ec))
        throw OutputFileError(who + (p == dir ? std::string("is a file, not a folder")
                                              : p.string() + " is a file, not a folder"));
    if (::access(p.c_str(), W_OK | X_OK) != 0)
        throw OutputFileError(who + "cannot write in " + p.string() + " (" + systemMessage(errno) +
                              ")");
}

void checkOutputFile(const std::filesystem::path& path, std::string_view role) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw OutputFileError((role.empty() ? std::string() : std::string(role) + " ") +
                              path.string() + ": is a folder, not a file");
    checkOutputFolder(path.parent_path(), role);
}

std::filesystem::path temporarySibling(const std::filesystem::path& path) {
    TempFile f = createSibling(path);
    if (const int err = f.close(); err != 0) fail(path, "cannot write: " + systemMessage(err));
    f.release();
    return f.path();
}

std::size_t removeKilledTemporaries(const std::filesystem::path& dir) {
    // ".NAME.tmpPID.N" (createSibling); only dead processes' files, so a run writing in the
    // same folder keeps its own.
    static const std::regex name(R"(\..+\.tmp([0-9]{1,9})\.[0-9]+)");
    std::size_t removed = 0;
    std::error_code ec;
    for (auto it = std::filesystem::recursive_directory_iterator(dir, ec);
         !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
        std::smatch m;
        const std::string leaf = it->path().filename().string();
        if (!it->is_regular_file(ec) || !std::regex_match(leaf, m, name)) continue;
        const auto pid = static_cast<pid_t>(std::stol(m[1].str()));
        if (processRuns(pid)) continue; // a live writer's
        std::error_code gone;
        if (std::filesystem::remove(it->path(), gone)) ++removed;
    }
    return removed;
}

void finishOutputFile(const std::filesystem::path& tmp, const std::filesystem::path& path) {
    if (current) {
        current->files_.emplace_back(tmp, path);
        return;
    }
    renameInto(tmp, path);
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
    TempFile file = createSibling(path);
    const char* p = bytes.data();
    std::size_t left = bytes.size();
    while (left > 0) {
        const ssize_t n = ::write(file.fd(), p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail(path, "cannot write: " + systemMessage(errno));
        }
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    if (const int err = file.close(); err != 0) fail(path, "cannot write: " + systemMessage(err));
    file.release();
    finishOutputFile(file.path(), path);
}

OutputSet::OutputSet() : outer_(current) {
    current = this;
}

OutputSet::~OutputSet() {
    if (current == this) current = outer_;
    if (done_) return;
    for (const auto& [tmp, path] : files_) ::unlink(tmp.c_str());
    // Innermost first; ::rmdir leaves a folder that something else has put a file in.
    for (auto it = folders_.rbegin(); it != folders_.rend(); ++it) ::rmdir(it->c_str());
}

void OutputSet::commit() {
    if (done_) return;
    done_ = true;
    if (current == this) current = outer_;
    if (outer_) { // the outer set decides
        for (auto& f : files_) outer_->files_.push_back(std::move(f));
        files_.clear();
        outer_->folders_.insert(outer_->folders_.end(), folders_.begin(), folders_.end());
        return;
    }
    // Every final place is checked before the first rename, so that a folder standing where a
    // file goes fails the set before any of its files has appeared.
    for (const auto& [tmp, path] : files_) {
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec)) {
            for (const auto& f : files_) ::unlink(f.first.c_str());
            for (auto it = folders_.rbegin(); it != folders_.rend(); ++it) ::rmdir(it->c_str());
            throw OutputFileError(path.string() +
                                  ": is a folder; the finished file cannot take its place");
        }
    }
    for (std::size_t i = 0; i < files_.size(); ++i) {
        try {
            renameInto(files_[i].first, files_[i].second);
        } catch (...) {
            for (std::size_t k = i + 1; k < files_.size(); ++k) ::unlink(files_[k].first.c_str());
            throw;
        }
    }
    files_.clear();
}

std::vector<std::filesystem::path> OutputSet::pending() const {
    std::vector<std::filesystem::path> out;
    for (const auto& f : files_) out.push_back(f.second);
    return out;
}

} // namespace fl
