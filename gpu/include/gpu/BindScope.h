#pragma once
// Binds a pass' textures, samplers, images and buffers and unbinds exactly those when the scope
// ends, so no pass leaves a binding behind (DESIGN: no global GL state outside a pass) and none
// lists its unbinding by hand. Every binding point is a typed constant of gpu/Bindings.h.

#include <gpu/Bindings.h>

#include <array>
#include <cstddef>

namespace fl::gl {

class BindScope {
  public:
    BindScope() = default;
    BindScope(const BindScope&) = delete;
    BindScope& operator=(const BindScope&) = delete;
    ~BindScope() { release(); }

    /// Binds `texture` (a GL name; 0 binds none) to `unit`.
    BindScope& texture(TextureUnit unit, GLuint texture);
    /// Binds `sampler` to `unit`, overriding the texture's own sampling state.
    BindScope& sampler(TextureUnit unit, GLuint sampler);
    /// Binds level `level` of `texture` to `unit` (all layers when `layered`).
    BindScope& image(ImageUnit unit, GLuint texture, GLenum access, GLenum format, GLint level = 0,
                     GLboolean layered = GL_FALSE);
    /// Binds the whole of `buffer` to a shader storage binding point.
    BindScope& storage(StorageBinding binding, GLuint buffer);
    /// Binds `size` bytes of `buffer` from `offset` to a shader storage binding point.
    BindScope& storage(StorageBinding binding, GLuint buffer, GLintptr offset, GLsizeiptr size);
    /// Binds the whole of `buffer` to an atomic counter binding point.
    BindScope& counter(CounterBinding binding, GLuint buffer);
    /// Binds `size` bytes of `buffer` from `offset` to an atomic counter binding point.
    BindScope& counter(CounterBinding binding, GLuint buffer, GLintptr offset, GLsizeiptr size);
    /// Unbinds everything this scope bound (last first), now rather than at the scope's end.
    void release();

  private:
    enum class Kind : unsigned char { Texture, Sampler, Image, Storage, Counter };
    struct Entry {
        Kind kind;
        GLuint index;
        GLenum format; // images: unbinding needs a valid format
    };
    void note(Kind kind, GLuint index, GLenum format = 0);
    // A storage or counter buffer: the whole of it, or `size` bytes from `offset`.
    BindScope& bindBuffer(Kind kind, GLuint index, GLuint buffer, bool whole, GLintptr offset,
                          GLsizeiptr size);

    std::array<Entry, 16> entries_{}; // a pass binds a handful: no allocation per pass
    std::size_t count_ = 0;
};

} // namespace fl::gl
