#pragma once
// Linked GLSL programs built from ShaderLibrary files; compile and link errors throw GlError with
// file, line and the driver's info log.

#include <gpu/Gl.h>
#include <gpu/ShaderLibrary.h>
#include <gpu/Uniform.h>

#include <glm/glm.hpp>

#include <functional>
#include <initializer_list>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
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
    /// one, its uniforms as just linked. Either way the new Program has no uniforms bound: the
    /// caller binds its tables (bindUniforms), which asks the GL program itself, so a reused
    /// program's locations are its own, never a previous owner's cache.
    static Program build(const ShaderLibrary& library, const std::vector<StageSource>& stages,
                         const std::vector<std::string>& defines = {});

    [[nodiscard]] GLuint id() const { return handle_.id(); }
    /// Uniform location by name, or -1 if the linker removed it (unchecked: for tests and for
    /// uniforms no table declares).
    [[nodiscard]] GLint location(const char* name) const;

    /// Checks `uniforms` against this program and caches their locations for set(). Throws
    /// GlError, naming the program's files and the uniform, for one that is active with another
    /// type (or arrayness), or inactive and not declared as `uniform <type> <name>` in any stage:
    /// a shader variant may leave a declared uniform unused, a misspelt one is declared nowhere.
    /// May be called more than once (a pass's own table, then shared ones).
    void bindUniforms(std::initializer_list<const UniformBase*> uniforms);
    /// The location bindUniforms() cached for `u`, -1 when inactive; throws GlError if `u` was not
    /// bound.
    [[nodiscard]] GLint location(const UniformBase& u) const;
    /// Sets a bound uniform; does nothing when it is inactive. T is deduced from both arguments,
    /// so a value of another type does not compile rather than convert.
    template <class T>
    void set(const Uniform<T>& u, const T& v) const {
        upload(location(u), v);
    }
    /// Sets the first v.size() elements of a bound uniform array.
    template <class T>
    void set(const UniformArray<T>& u, std::span<const std::type_identity_t<T>> v) const {
        upload(location(u), v);
    }

  private:
    void giveBack();
    void upload(GLint at, int v) const;
    void upload(GLint at, float v) const;
    void upload(GLint at, const glm::ivec2& v) const;
    void upload(GLint at, const glm::ivec3& v) const;
    void upload(GLint at, const glm::ivec4& v) const;
    void upload(GLint at, const glm::vec2& v) const;
    void upload(GLint at, const glm::vec3& v) const;
    void upload(GLint at, const glm::vec4& v) const;
    void upload(GLint at, const glm::mat3& v) const;
    void upload(GLint at, const glm::mat4& v) const;
    void upload(GLint at, std::span<const glm::vec2> v) const;
    void upload(GLint at, std::span<const float> v) const;
    ProgramHandle handle_;
    std::weak_ptr<ProgramPool> pool_; // where the program goes when this one is done with it
    std::string key_;                 // its stages' expanded sources
    std::string files_;               // its stages' file names, for messages
    // bindUniforms()'s cache, a few entries per program: set() finds a location by the Uniform's
    // address.
    std::vector<std::pair<const UniformBase*, GLint>> bound_;
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
