#pragma once
// Linked programs kept for reuse (private to floodlight_gpu). Every ShaderLibrary (and every copy
// of it: renderers and kernels hold copies) shares one pool. A Program built from sources the pool
// has seen takes an idle program of those sources instead of compiling and linking again: on a
// software rasteriser (llvmpipe) compiling is most of a renderer's start-up, and a capture at two
// resolutions, a viewer switching methods back and forth or a test rendering with several
// settings builds the same programs over and over.
//
// A program is lent to one Program at a time, never shared: two live passes never see each
// other's uniforms. When it is lent again its uniforms are first put back to the values they had
// right after linking (GLSL initialisers included), so a reused program starts exactly as a new
// one would.

#include <epoxy/gl.h>

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace fl::gl {

class ProgramPool {
  public:
    ProgramPool() = default;
    ProgramPool(const ProgramPool&) = delete;
    ProgramPool& operator=(const ProgramPool&) = delete;
    /// Deletes the idle programs (the context they were made in must be current, as for any GL
    /// object's owner).
    ~ProgramPool();

    /// An idle program linked from `key`'s sources, its uniforms as just linked; 0 if none.
    GLuint take(const std::string& key);
    /// Records the uniforms of `program`, just linked, to put back before each later loan.
    void remember(GLuint program);
    /// Takes back a program a Program no longer needs.
    void giveBack(const std::string& key, GLuint program);

  private:
    // One default-block uniform element (arrays element by element) and its just-linked value.
    struct UniformValue {
        GLint location;
        GLenum type;
        std::array<std::uint32_t, 16> bits; // floats, ints or uints, by type
    };
    static std::vector<UniformValue> snapshot(GLuint program);
    static void restore(GLuint program, const std::vector<UniformValue>& values);

    std::unordered_map<std::string, std::vector<GLuint>> idle_;
    std::unordered_map<GLuint, std::vector<UniformValue>> linked_;
};

} // namespace fl::gl
