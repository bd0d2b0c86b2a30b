#include <gpu/ReadBack.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>

namespace fl::gl {

Fence Fence::insert() {
    Fence f;
    f.sync_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    if (!f.sync_) throw GlError("glFenceSync failed");
    return f;
}

Fence& Fence::operator=(Fence&& o) noexcept {
    if (this != &o) {
        reset();
        sync_ = std::exchange(o.sync_, nullptr);
    }
    return *this;
}

void Fence::reset() {
    if (sync_) glDeleteSync(sync_);
    sync_ = nullptr;
}

void Fence::wait() const {
    // The first wait flushes the commands before the fence (else it might never be reached);
    // waits after it only need to poll again.
    GLbitfield flags = GL_SYNC_FLUSH_COMMANDS_BIT;
    for (;;) {
        const GLenum r = glClientWaitSync(sync_, flags, std::numeric_limits<GLuint64>::max());
        if (r == GL_ALREADY_SIGNALED || r == GL_CONDITION_SATISFIED) return;
        if (r == GL_WAIT_FAILED) throw GlError("glClientWaitSync failed");
        flags = 0; // GL_TIMEOUT_EXPIRED: wait again
    }
}

void TextureReadBack::start(const Texture& texture, int channels) {
    if (channels != 1 && channels != 4)
        throw std::invalid_argument("TextureReadBack: 1 or 4 channels");
    const GLsizeiptr bytes = static_cast<GLsizeiptr>(texture.width()) * texture.height() *
                             channels * static_cast<GLsizeiptr>(sizeof(float));
    // Client storage: the driver keeps it where the CPU reads it fastest.
    if (!buffer_ || buffer_.size() != bytes)
        buffer_ = Buffer(bytes, nullptr, GL_MAP_READ_BIT | GL_CLIENT_STORAGE_BIT);
    width_ = texture.width();
    height_ = texture.height();
    channels_ = channels;
    // A pack buffer turns the pointer argument into an offset into it; the binding is undone at
    // once, so nothing outlives the call.
    glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer_.id());
    glGetTextureImage(texture.id(), 0, channels == 1 ? GL_RED : GL_RGBA, GL_FLOAT,
                      static_cast<GLsizei>(bytes), nullptr);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    throwIfErrors("texture read-back into a pixel buffer");
    fence_ = Fence::insert();
}

TextureReadBack::Mapped TextureReadBack::finish() {
    if (!fence_) throw std::logic_error("TextureReadBack::finish without start");
    fence_.wait();
    fence_.reset();
    return Mapped(buffer_, width_, height_, channels_);
}

TextureReadBack::Mapped::Mapped(const Buffer& buffer, int width, int height, int channels)
    : buffer_(buffer.id()), width_(width), height_(height), channels_(channels) {
    data_ = static_cast<const float*>(
        glMapNamedBufferRange(buffer_, 0, buffer.size(), GL_MAP_READ_BIT));
    if (!data_) {
        throwIfErrors("mapping a read-back buffer");
        throw GlError("mapping a read-back buffer failed");
    }
}

TextureReadBack::Mapped::~Mapped() {
    glUnmapNamedBuffer(buffer_);
}

} // namespace fl::gl
