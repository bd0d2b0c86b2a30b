#pragma once
// Every file Floodlight writes goes through here: it is written under a hidden temporary name
// beside its final one and renamed into place when complete, so no reader ever sees half a
// file. A command that writes several files opens an OutputSet first: then the renames wait
// for its commit(), and if the command fails before that (an exception unwinds the set), every
// temporary is removed and none of its outputs appears. Before the set, `render` with an
// unwritable --aliasing-map left its PNG and EXR behind, and `delaunay` left .node/.ele/.obj
// when the SVG failed.

#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

namespace fl {

/// "PATH: problem" for a file that could not be written.
class OutputFileError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Creates the folder `dir` and its parents (nothing for an empty path); throws OutputFileError
/// "ROLE DIR: cannot create the folder (reason)" (just "DIR: ..." without a role), never a raw
/// filesystem_error. ROLE is the option that named it, e.g. "--steps". Missing folders are
/// created for every output alike; under an open OutputSet, the folders it created are removed
/// again (when empty) if the set is never committed, so a failed command leaves nothing new.
void makeOutputFolder(const std::filesystem::path& dir, std::string_view role = {});

/// Checks, before any work, that `dir` can be an output folder: it is a folder or can be made
/// one (no file in the way, here or above), and an existing one is writable. Throws
/// OutputFileError "ROLE DIR: problem".
void checkOutputFolder(const std::filesystem::path& dir, std::string_view role = {});
/// Checks, before any work, that a file can be written at `path`: not a folder, and its folder
/// passes checkOutputFolder. Throws OutputFileError "ROLE PATH: problem".
void checkOutputFile(const std::filesystem::path& path, std::string_view role = {});

/// A new, empty, uniquely named hidden file beside `path` (".NAME.tmpPID.N"), for writers
/// that need a path to write to (stb, OpenEXR). The folder must exist (callers that make
/// folders, such as the image writers, make them first).
std::filesystem::path temporarySibling(const std::filesystem::path& path);

/// Removes, under `dir` and its subfolders, the temporaries that writers killed mid-write left
/// (temporarySibling's names); returns how many. For a folder a killed run is continued in.
std::size_t removeKilledTemporaries(const std::filesystem::path& dir);

/// Moves the finished temporary `tmp` to `path`: now, or at the commit of the thread's open
/// OutputSet. Throws OutputFileError (and removes `tmp`) if the rename fails.
void finishOutputFile(const std::filesystem::path& tmp, const std::filesystem::path& path);

/// Writes `bytes` to `path` through a temporary sibling (temporarySibling, finishOutputFile).
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

/// The outputs of one command: all of them appear at commit(), or none does. One per thread is
/// current (a nested set hands its files to the outer one at its commit). Tied to its scope:
/// neither copyable nor movable.
class OutputSet {
  public:
    OutputSet();
    ~OutputSet(); // without commit(): removes every temporary written under it
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;

    /// Renames every file into place, in the order written; throws OutputFileError if one
    /// fails (the rest are then removed).
    void commit();
    /// The final paths waiting for commit().
    [[nodiscard]] std::vector<std::filesystem::path> pending() const;

  private:
    friend void finishOutputFile(const std::filesystem::path&, const std::filesystem::path&);
    friend void makeOutputFolder(const std::filesystem::path&, std::string_view);
    std::vector<std::pair<std::filesystem::path, std::filesystem::path>> files_; // tmp, final
    std::vector<std::filesystem::path> folders_; // created under the set, outermost first
    OutputSet* outer_ = nullptr;
    bool done_ = false;
};

} // namespace fl
