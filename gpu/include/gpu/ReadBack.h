#pragma once
// Reading a texture back without stalling the GL thread: the copy goes into a buffer object
// bound as GL_PIXEL_PACK_BUFFER, a fence follows it, and the bytes are mapped later (a frame
// behind, in a capture), when the copy has long finished. glGetTextureImage into client memory
// waits for every command before it and for the copy itself.

#include <gpu/Gl.h>

#include <cstddef>
#include <vector>

namespace fl::gl {

/// Level 0 of `texture` read back now, one T a texel (`format`, `type`: one channel, e.g.
/// GL_RED / GL_FLOAT, GL_DEPTH_COMPONENT / GL_FLOAT, GL_RED_INTEGER / GL_UNSIGNED_INT), GL's row
/// order (row 0 at the bottom). It waits for the GPU: for CPU twins and tests, not in a frame.
template <typename T>
std::vector<T> readTexels(const Texture& texture, GLenum format, GLenum type) {
    std::vector<T> v(static_cast<std::size_t>(texture.width()) *
                     static_cast<std::size_t>(texture.height()));
    glGetTextureImage(texture.id(), 0, format, type, static_cast<GLsizei>(v.size() * sizeof(T)),
                      v.data());
    return v;
}

/// A fence (glFenceSync) after the commands issued so far; move-only, deleted with the object.
class Fence {
  public:
    Fence() = default;
    /// Inserts a fence after every command issued so far.
    static Fence insert();
    Fence(const Fence&) = delete;
    Fence& operator=(const Fence&) = delete;
    Fence(Fence&& o) noexcept : sync_(o.sync_) { o.sync_ = nullptr; }
    Fence& operator=(Fence&& o) noexcept;
    ~Fence() { reset(); }
    void reset();
    explicit operator bool() const { return sync_ != nullptr; }
    /// Blocks until the GPU has passed the fence (flushing the commands before it); throws
    /// GlError if the wait fails.
    void wait() const;

  private:
    GLsync sync_ = nullptr;
};

/// Level 0 of a texture copied into a read-mapped buffer (GL_PIXEL_PACK_BUFFER) as floats.
class TextureReadBack {
  public:
    /// Queues the copy of `texture`'s level 0 as `channels` floats a texel (1: red, 4: RGBA) and
    /// a fence after it; returns without waiting. The buffer is kept and reused while the
    /// texture's size stays. Throws std::invalid_argument for another channel count.
    void start(const Texture& texture, int channels);
    /// Whether a copy was started and not yet mapped.
    [[nodiscard]] bool pending() const { return static_cast<bool>(fence_); }

    /// The copied floats, mapped for reading, GL's row order (row 0 at the bottom); unmapped
    /// when it goes.
    class Mapped {
      public:
        Mapped(const Buffer& buffer, int width, int height, int channels);
        Mapped(const Mapped&) = delete;
        Mapped& operator=(const Mapped&) = delete;
        ~Mapped();
        [[nodiscard]] const float* data() const { return data_; }
        [[nodiscard]] int width() const { return width_; }
        [[nodiscard]] int height() const { return height_; }
        [[nodiscard]] int channels() const { return channels_; }

      private:
        GLuint buffer_ = 0;
        const float* data_ = nullptr;
        int width_ = 0, height_ = 0, channels_ = 0;
    };
    /// Waits for the copy started last and maps it; throws std::logic_error if none is pending
    /// and GlError if mapping fails.
    [[nodiscard]] Mapped finish();

  private:
    Buffer buffer_;
    Fence fence_;
    int width_ = 0, height_ = 0, channels_ = 0;
};

} // namespace fl::gl
