#include <gpu/BindScope.h>

#include <stdexcept>

namespace fl::gl {

BindScope& BindScope::texture(TextureUnit unit, GLuint texture) {
    glBindTextureUnit(unit.index, texture);
    note(Kind::Texture, unit.index);
    return *this;
}

BindScope& BindScope::sampler(TextureUnit unit, GLuint sampler) {
    glBindSampler(unit.index, sampler);
    note(Kind::Sampler, unit.index);
    return *this;
}

BindScope& BindScope::image(ImageUnit unit, GLuint texture, GLenum access, GLenum format,
                            GLint level, GLboolean layered) {
    glBindImageTexture(unit.index, texture, level, layered, 0, access, format);
    note(Kind::Image, unit.index, format);
    return *this;
}

BindScope& BindScope::storage(StorageBinding binding, GLuint buffer) {
    return bindBuffer(Kind::Storage, binding.index, buffer, true, 0, 0);
}

BindScope& BindScope::storage(StorageBinding binding, GLuint buffer, GLintptr offset,
                              GLsizeiptr size) {
    return bindBuffer(Kind::Storage, binding.index, buffer, false, offset, size);
}

BindScope& BindScope::counter(CounterBinding binding, GLuint buffer) {
    return bindBuffer(Kind::Counter, binding.index, buffer, true, 0, 0);
}

BindScope& BindScope::counter(CounterBinding binding, GLuint buffer, GLintptr offset,
                              GLsizeiptr size) {
    return bindBuffer(Kind::Counter, binding.index, buffer, false, offset, size);
}

BindScope& BindScope::bindBuffer(Kind kind, GLuint index, GLuint buffer, bool whole,
                                 GLintptr offset, GLsizeiptr size) {
    const GLenum target =
        kind == Kind::Storage ? GL_SHADER_STORAGE_BUFFER : GL_ATOMIC_COUNTER_BUFFER;
    if (whole)
        glBindBufferBase(target, index, buffer);
    else
        glBindBufferRange(target, index, buffer, offset, size);
    note(kind, index);
    return *this;
}

void BindScope::note(Kind kind, GLuint index, GLenum format) {
    // A point bound again (a ping-pong loop) is unbound once.
    for (std::size_t i = 0; i < count_; ++i) {
        if (entries_[i].kind == kind && entries_[i].index == index) {
            entries_[i].format = format;
            return;
        }
    }
    if (count_ == entries_.size()) throw std::logic_error("BindScope: more than 16 bindings");
    entries_[count_++] = Entry{kind, index, format};
}

void BindScope::release() {
    while (count_ > 0) {
        const Entry& e = entries_[--count_];
        switch (e.kind) {
        case Kind::Texture:
            glBindTextureUnit(e.index, 0);
            break;
        case Kind::Sampler:
            glBindSampler(e.index, 0);
            break;
        case Kind::Image:
            glBindImageTexture(e.index, 0, 0, GL_FALSE, 0, GL_READ_ONLY, e.format);
            break;
        case Kind::Storage:
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, e.index, 0);
            break;
        case Kind::Counter:
            glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, e.index, 0);
            break;
        }
    }
}

} // namespace fl::gl
