#include <gpu/Gl.h>
#include <gpu/LiveObjects.h>

#include <mutex>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace fl::gl {

namespace {

GLuint newBuffer() {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    noteCreated(ObjectKind::Buffer, id);
    return id;
}

GLuint newTexture2D() {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    noteCreated(ObjectKind::Texture, id);
    return id;
}

GLuint newTexture3D() {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &id);
    noteCreated(ObjectKind::Texture, id);
    return id;
}

} // namespace

Buffer::Buffer(GLsizeiptr bytes, const void* data, GLbitfield flags)
    : Handle(newBuffer()), size_(bytes) {
    glNamedBufferStorage(id(), bytes, data, flags);
}

Texture::Texture(GLenum internalFormat, int width, int height, int levels)
    : Handle(newTexture2D()), width_(width), height_(height), format_(internalFormat) {
    glTextureStorage2D(id(), levels, internalFormat, width, height);
    setSampling(levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST,
                levels > 1 ? GL_LINEAR : GL_NEAREST);
}

void Texture::setSampling(GLenum minFilter, GLenum magFilter, GLenum wrap) {
    glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
    glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
    glTextureParameteri(id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
    glTextureParameteri(id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
}

Texture3D::Texture3D(GLenum internalFormat, int width, int height, int depth)
    : Handle(newTexture3D()), width_(width), height_(height), depth_(depth),
      format_(internalFormat) {
    glTextureStorage3D(id(), 1, internalFormat, width, height, depth);
    glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

Framebuffer Framebuffer::create() {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    noteCreated(ObjectKind::Framebuffer, id);
    return Framebuffer(id);
}

Framebuffer Framebuffer::forColor(const Texture& color, const char* what) {
    Framebuffer fbo = create();
    fbo.attach(GL_COLOR_ATTACHMENT0, color);
    fbo.setDrawBuffers(1);
    fbo.check(what);
    return fbo;
}

Framebuffer Framebuffer::withTargets(std::initializer_list<const Texture*> colors,
                                     const Texture* depth, const char* what) {
    Framebuffer fbo = create();
    GLenum attachment = GL_COLOR_ATTACHMENT0;
    for (const Texture* c : colors) fbo.attach(attachment++, *c);
    if (depth) fbo.attach(GL_DEPTH_ATTACHMENT, *depth);
    fbo.setDrawBuffers(static_cast<int>(colors.size()));
    fbo.check(what);
    return fbo;
}

Handle<detail::SamplerDeleter> makeRawTexelSampler() {
    GLuint id = 0;
    glCreateSamplers(1, &id);
    noteCreated(ObjectKind::Sampler, id);
    glSamplerParameteri(id, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return Handle<detail::SamplerDeleter>(id);
}

void Framebuffer::attach(GLenum attachment, const Texture& tex) {
    glNamedFramebufferTexture(id(), attachment, tex.id(), 0);
}

void Framebuffer::setDrawBuffers(int count) {
    std::vector<GLenum> bufs;
    for (int i = 0; i < count; ++i) bufs.push_back(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i));
    if (bufs.empty())
        glNamedFramebufferDrawBuffer(id(), GL_NONE);
    else
        glNamedFramebufferDrawBuffers(id(), static_cast<GLsizei>(bufs.size()), bufs.data());
}

void Framebuffer::check(const char* what) const {
    const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        std::ostringstream s;
        s << what << ": framebuffer incomplete (status 0x" << std::hex << status << ")";
        throw GlError(s.str());
    }
}

VertexArray VertexArray::create() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    noteCreated(ObjectKind::VertexArray, id);
    return VertexArray(id);
}

Query Query::create(GLenum target) {
    GLuint id = 0;
    glCreateQueries(target, 1, &id);
    noteCreated(ObjectKind::Query, id);
    return Query(id);
}

namespace {

std::mutex g_mutex;
std::vector<std::string> g_errors;

const char* typeName(GLenum type) {
    switch (type) {
    case GL_DEBUG_TYPE_ERROR:
        return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR:
        return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR:
        return "undefined behaviour";
    default:
        return "message";
    }
}

void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity,
                               GLsizei length, const GLchar* message, const void* /*user*/) {
    // Errors and undefined behaviour are collected and turned into exceptions at the next
    // throwIfErrors() (throwing through the driver's stack frames is not allowed); performance
    // and other notes are ignored.
    const bool fatal = type == GL_DEBUG_TYPE_ERROR || type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR ||
                       severity == GL_DEBUG_SEVERITY_HIGH;
    // Shader compiler messages repeat the info log, which Program reports with file names.
    if (!fatal || source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
    std::string text =
        length > 0 ? std::string(message, static_cast<size_t>(length)) : std::string(message);
    std::lock_guard lock(g_mutex);
    g_errors.push_back(std::string("GL ") + typeName(type) + " " + std::to_string(id) + ": " +
                       text);
}

} // namespace

void installDebugOutput() {
    if (!epoxy_has_gl_extension("GL_KHR_debug") && epoxy_gl_version() < 43) return;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

void throwIfErrors(const char* where) {
    std::vector<std::string> errors;
    {
        std::lock_guard lock(g_mutex);
        errors.swap(g_errors);
    }
    for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
        std::ostringstream s;
        s << "glGetError 0x" << std::hex << e;
        errors.push_back(s.str());
        if (errors.size() > 32) break; // a lost context can report errors forever
    }
    if (errors.empty()) return;
    std::string msg = std::string(where) + ": " + std::to_string(errors.size()) + " GL error(s)";
    for (const std::string& e : errors) msg += "\n  " + e;
    throw GlError(msg);
}

std::string rendererName() {
    const auto* s = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return s ? s : "unknown";
}

std::int64_t texelBytes(GLenum internalFormat) {
    switch (internalFormat) {
    case GL_R8:
        return 1;
    case GL_DEPTH_COMPONENT16:
        return 2;
    case GL_RGBA8:
    case GL_SRGB8_ALPHA8:
    case GL_R32F:
    case GL_R32UI:
    case GL_R32I:
    case GL_DEPTH_COMPONENT32F:
        return 4;
    case GL_RGBA16F:
    case GL_RGBA16_SNORM:
    case GL_RG32F:
    case GL_RG32I:
    case GL_RG32UI:
        return 8;
    case GL_RGBA32F:
    case GL_RGBA32UI:
    case GL_RGBA32I:
        return 16;
    default:
        break;
    }
    std::ostringstream s;
    s << "texelBytes: internal format 0x" << std::hex << internalFormat << " is not in the table";
    throw std::invalid_argument(s.str());
}

std::int64_t textureBytes(const Texture& texture) {
    return texelBytes(texture.format()) * texture.width() * texture.height();
}

int maxTextureSize() {
    GLint size = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
    return size;
}

int max3dTextureSize() {
    GLint size = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &size);
    return size;
}

void checkTextureSize(const std::string& what, int width, int height) {
    const int limit = maxTextureSize();
    if (width > limit || height > limit)
        throw std::invalid_argument(
            what + " " + std::to_string(width) + "x" + std::to_string(height) +
            " is larger than this driver's largest texture, " + std::to_string(limit) + "x" +
            std::to_string(limit) + " (GL_MAX_TEXTURE_SIZE, " + rendererName() + ")");
}

bool isSoftwareRenderer() {
    const std::string r = rendererName();
    return r.find("llvmpipe") != std::string::npos || r.find("softpipe") != std::string::npos;
}

} // namespace fl::gl
