#pragma once
// Linked GLSL programs built from ShaderLibrary files; compile and link errors throw GlError with
// file, line and the driver's info log.

#include <gpu/Gl.h>
#include <gpu/ShaderLibrary.h>

#include <glm/glm.hpp>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace fl::gl {

/// One shader stage: GL stage enum and the shader file name (e.g. "forward.frag.glsl").
struct StageSource {
    GLenum stage;
    std::string file;
};

/// A linked program. Uniforms are set with DSA (glProgramUniform*), so no program is bound.
class Program {
  public:
    Program() = default;
    Program(Program&&) noexcept = default;
    Program& operator=(Program&& o) noexcept;
    /// Returns the GL program to the library's pool (deletes it if the pool is gone).
    ~Program();
    /// Compiles every stage (with `defines` lines inserted after #version) and links them; or,
    /// when the library's pool holds an idle program of the same sources and defines, takes that
    /// one, its uniforms as just linked.
    static Program build(const ShaderLibrary& library, const std::vector<StageSource>& stages,
                         const std::vector<std::string>& defines = {});

    [[nodiscard]] GLuint id() const { return handle_.id(); }
    /// Uniform location, or -1 if the linker removed it.
    [[nodiscard]] GLint location(const char* name) const;
    void set(const char* name, int v) const;
    void set(const char* name, float v) const;
    void set(const char* name, const glm::ivec2& v) const;
    void set(const char* name, const glm::vec2& v) const;
    void set(const char* name, const glm::vec3& v) const;
    void set(const char* name, const glm::vec4& v) const;
    void set(const char* name, const glm::mat3& v) const;
    void set(const char* name, const glm::mat4& v) const;

  private:
    void giveBack();
    ProgramHandle handle_;
    std::weak_ptr<ProgramPool> pool_; // where the program goes when this one is done with it
    std::string key_;                 // its stages' expanded sources
};

/// Draws one triangle covering the viewport with `program` (fullscreen.vert.glsl makes its
/// positions from gl_VertexID, so `emptyVao` has no attributes); unbinds both afterwards.
void drawFullscreenTriangle(const Program& program, const VertexArray& emptyVao);

/// Two fullscreen passes into the bound framebuffer, which has a depth target: `mark` runs on
/// every pixel and writes gl_FragDepth 0 where `refine` must run, 1 elsewhere; `refine` (none:
/// skipped) then runs only there, behind an early depth test (its fragments lie at depth 0.5,
/// tested GL_GREATER), so that a costly branch costs only where it is taken: a software
/// rasteriser runs every fragment of a block through both sides of a branch. `draw` binds a
/// program's inputs and draws it. Leaves the depth test off, GL_LESS, depth writes on.
void drawMarkedThenRefined(const std::function<void(const Program&)>& draw, const Program& mark,
                           const Program* refine);

/// Rewrites a driver info log so that "0:12(5): error" style references name the file and line;
/// `files` maps #line source-string numbers to file names. Exposed for tests.
std::string mapInfoLog(const std::string& log, const std::vector<std::string>& files);

} // namespace fl::gl
