#pragma once
// Shader sources by file name: embedded at build time, or read from --shader-dir at run time.

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fl::gl {

class ProgramPool;

/// The shaders/*.glsl files compiled into the binary, by file name.
const std::map<std::string, std::string_view>& embeddedShaders();

/// Resolves shader file names to source text, expanding `#include "name.glsl"` lines and
/// inserting `#line` directives so compile errors map back to the right file and line.
class ShaderLibrary {
  public:
    /// Embedded sources, or the files in `dir` when given (the --shader-dir override).
    explicit ShaderLibrary(std::optional<std::filesystem::path> dir = std::nullopt);

    /// The expanded source of `name`; `fileNames` receives the name of every file it pulled in,
    /// indexed by the source-string number used in its #line directives.
    [[nodiscard]] std::string expand(const std::string& name,
                                     std::vector<std::string>& fileNames) const;

    /// Raw text of one file; throws std::runtime_error naming the file if it does not exist.
    [[nodiscard]] std::string read(const std::string& name) const;

    [[nodiscard]] const std::optional<std::filesystem::path>& directory() const { return dir_; }

    /// The linked programs this library and its copies keep for reuse (see Program::build).
    [[nodiscard]] const std::shared_ptr<ProgramPool>& programPool() const { return pool_; }

  private:
    void expandInto(const std::string& name, std::string& out, std::vector<std::string>& files,
                    int depth) const;
    std::optional<std::filesystem::path> dir_;
    std::shared_ptr<ProgramPool> pool_;
};

} // namespace fl::gl
