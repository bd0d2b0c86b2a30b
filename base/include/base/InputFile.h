#pragma once
// Reading the files a user names (scenes, scripts, camera paths, point sets, images), in one
// place: only regular files (after following links), never more than a limit, and one message
// naming the option or role, the path and the problem. A FIFO, a device or a directory would
// otherwise block forever or be read without end.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fl {

// Default size limits per kind of input, in MiB; the --help texts of the readers quote them.
inline constexpr std::uintmax_t kTextInputLimitMiB = 64;    // scripts, camera paths, point text
inline constexpr std::uintmax_t kBinaryInputLimitMiB = 256; // .f64/.bin point sets (16M points)
inline constexpr std::uintmax_t kImageInputLimitMiB = 256;  // PNG masks and label images
inline constexpr std::uintmax_t kSceneInputLimitMiB = 1024; // glTF/GLB scenes and their buffers

/// A user file that cannot be used. what() is "ROLE PATH: PROBLEM" ("PATH: PROBLEM" without a
/// role), e.g. "--points /tmp/f: not a regular file (a FIFO)".
class InputFileError : public std::runtime_error {
  public:
    InputFileError(std::string role, std::string path, std::string problem);
    [[nodiscard]] const std::string& role() const { return role_; }
    [[nodiscard]] const std::string& path() const { return path_; }
    /// "does not exist", "not a regular file (a directory)", "larger than the limit of 64 MiB".
    [[nodiscard]] const std::string& problem() const { return problem_; }

  private:
    std::string role_, path_, problem_;
};

/// The whole of `path` as bytes, with `padding` zero bytes after them (parsers that read past
/// the end); throws InputFileError unless it is a regular file of at most `limitMiB` MiB.
std::vector<unsigned char> readInputBytes(const std::filesystem::path& path, std::string_view role,
                                          std::uintmax_t limitMiB, std::size_t padding = 0);

/// The whole of `path` as text; the same checks as readInputBytes.
std::string readInputFile(const std::filesystem::path& path, std::string_view role,
                          std::uintmax_t limitMiB);

/// The problem readInputBytes would report before reading (empty when the file can be read):
/// for callers that must test a path first (tinygltf's "file exists" callback).
std::string inputFileProblem(const std::filesystem::path& path, std::uintmax_t limitMiB);

} // namespace fl
