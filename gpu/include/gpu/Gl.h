#pragma once
// Move-only RAII owners for GL objects, created with DSA (glCreate*). Only a current GL 4.5 context
// and libepoxy are needed; nothing here binds global state that outlives a call.

#include <epoxy/gl.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

namespace fl::gl {

/// Thrown for any GL failure: debug-output errors, incomplete framebuffers, bad shaders.
class GlError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Owns one GL name; Deleter::destroy(GLuint) frees it. Move-only so a name is freed exactly once.
template <typename Deleter>
class Handle {
  public:
    Handle() = default;
    explicit Handle(GLuint id) : id_(id) {}
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
    Handle& operator=(Handle&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = std::exchange(o.id_, 0);
        }
        return *this;
    }
    ~Handle() { reset(); }
    void reset() {
        if (id_ != 0) Deleter::destroy(id_);
        id_ = 0;
    }
    [[nodiscard]] GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    /// Gives up ownership without deleting (a pooled program goes back to its pool).
    [[nodiscard]] GLuint release() { return std::exchange(id_, 0); }

  private:
    GLuint id_ = 0;
};

namespace detail {
struct BufferDeleter {
    static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct TextureDeleter {
    static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct FramebufferDeleter {
    static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct VertexArrayDeleter {
    static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct ProgramDeleter {
    static void destroy(GLuint id) { glDeleteProgram(id); }
};
struct ShaderDeleter {
    static void destroy(GLuint id) { glDeleteShader(id); }
};
struct QueryDeleter {
    static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};
struct SamplerDeleter {
    static void destroy(GLuint id) { glDeleteSamplers(1, &id); }
};
} // namespace detail

/// A buffer object with immutable storage.
class Buffer : public Handle<detail::BufferDeleter> {
  public:
    Buffer() = default;
    /// Allocates `bytes` of storage initialised from `data` (may be null).
    Buffer(GLsizeiptr bytes, const void* data, GLbitfield flags = 0);
    [[nodiscard]] GLsizeiptr size() const { return size_; }

  private:
    GLsizeiptr size_ = 0;
};

/// A 2D texture with immutable storage.
class Texture : public Handle<detail::TextureDeleter> {
  public:
    Texture() = default;
    /// Allocates width x height x levels of `internalFormat` (GL_TEXTURE_2D).
    Texture(GLenum internalFormat, int width, int height, int levels = 1);
    [[nodiscard]] int width() const { return width_; }
    [[nodiscard]] int height() const { return height_; }
    [[nodiscard]] GLenum format() const { return format_; }
    /// Sets min/mag filter and clamp-to-edge wrapping.
    void setSampling(GLenum minFilter, GLenum magFilter, GLenum wrap = GL_CLAMP_TO_EDGE);

  private:
    int width_ = 0;
    int height_ = 0;
    GLenum format_ = 0;
};

/// A 3D texture with immutable storage, one level (volumes written by compute passes, e.g. the
/// 3D jump flood's image3D ping-pong pair).
class Texture3D : public Handle<detail::TextureDeleter> {
  public:
    Texture3D() = default;
    /// Allocates width x height x depth texels of `internalFormat` (GL_TEXTURE_3D), NEAREST.
    Texture3D(GLenum internalFormat, int width, int height, int depth);
    [[nodiscard]] int width() const { return width_; }
    [[nodiscard]] int height() const { return height_; }
    [[nodiscard]] int depth() const { return depth_; }
    [[nodiscard]] GLenum format() const { return format_; }

  private:
    int width_ = 0;
    int height_ = 0;
    int depth_ = 0;
    GLenum format_ = 0;
};

/// A framebuffer object; attach textures, then check() it.
class Framebuffer : public Handle<detail::FramebufferDeleter> {
  public:
    /// Creates an empty framebuffer (no attachments yet).
    static Framebuffer create();
    /// A checked framebuffer drawing into `color` alone (attachment 0, no depth); throws GlError
    /// naming `what` if it is incomplete.
    static Framebuffer forColor(const Texture& color, const char* what);
    /// A checked framebuffer drawing into `colors` (attachments 0..n-1, all of them draw
    /// buffers) with an optional depth attachment; throws GlError naming `what` if incomplete.
    static Framebuffer withTargets(std::initializer_list<const Texture*> colors,
                                   const Texture* depth, const char* what);
    /// Attaches level 0 of `tex` at `attachment` (GL_COLOR_ATTACHMENTi / GL_DEPTH_ATTACHMENT).
    void attach(GLenum attachment, const Texture& tex);
    /// Sets the draw buffers to COLOR_ATTACHMENT0..count-1 (0 = none).
    void setDrawBuffers(int count);
    /// Throws GlError naming `what` if the framebuffer is not complete.
    void check(const char* what) const;

  private:
    using Handle::Handle;
};

/// A sampler object that reads stored texels: NEAREST, clamped to the edge, no depth comparison
/// (a depth texture read through it gives its depths, whatever its own compare mode).
Handle<detail::SamplerDeleter> makeRawTexelSampler();

/// A vertex array object.
class VertexArray : public Handle<detail::VertexArrayDeleter> {
  public:
    static VertexArray create();

  private:
    using Handle::Handle;
};

/// A query object of one target (e.g. GL_TIME_ELAPSED).
class Query : public Handle<detail::QueryDeleter> {
  public:
    static Query create(GLenum target);

  private:
    using Handle::Handle;
};

class Shader : public Handle<detail::ShaderDeleter> {
  public:
    using Handle::Handle;
};

class ProgramHandle : public Handle<detail::ProgramDeleter> {
  public:
    using Handle::Handle;
};

/// Installs the KHR_debug callback (synchronous) that records errors for throwIfErrors().
void installDebugOutput();
/// Throws GlError listing every GL error recorded since the last call (debug output and
/// glGetError), prefixed with `where`; returns normally if there were none.
void throwIfErrors(const char* where);
/// The GL_RENDERER string of the current context.
std::string rendererName();
/// Bytes one texel of `internalFormat` occupies (GL_RGBA32F: 16, GL_R8: 1, ...); throws
/// std::invalid_argument for a format not in its table, so a new format cannot go uncounted.
std::int64_t texelBytes(GLenum internalFormat);
/// Bytes of level 0 of `texture`: what a pass that writes every texel of it writes.
std::int64_t textureBytes(const Texture& texture);
/// GL_MAX_TEXTURE_SIZE of the current context: the largest side a frame or map can have here.
int maxTextureSize();
/// GL_MAX_3D_TEXTURE_SIZE of the current context: the largest side of a 3D texture here.
int max3dTextureSize();
/// Throws std::invalid_argument naming `what`, its size and this driver's largest texture side
/// when `width` or `height` exceeds maxTextureSize().
void checkTextureSize(const std::string& what, int width, int height);
/// True on Mesa's software rasterisers (timer queries unreliable for compute there).
bool isSoftwareRenderer();

} // namespace fl::gl
