#pragma once
// The GL objects the current context holds, counted by asking GL itself (glIsBuffer, ...), not
// by our wrappers' bookkeeping: a leak through a path that bypasses the wrappers counts too.
// For soak runs: over thousands of frames with methods, overlays and map sizes switched, the
// counts at the same settings must come back to the same numbers.

#include <epoxy/gl.h>

#include <array>
#include <string>
#include <string_view>

namespace fl::gl {

/// Every kind of GL object Floodlight creates, in the order of kObjectKinds.
enum class ObjectKind {
    Buffer,
    Texture,
    Framebuffer,
    VertexArray,
    Program,
    Shader,
    Query,
    Sampler
};

/// A kind's name in reports and GL's test for a live name of that kind.
struct ObjectKindInfo {
    std::string_view name;
    GLboolean (*isLive)(GLuint name);
};
/// The one table of kinds, indexed by ObjectKind.
inline constexpr std::array<ObjectKindInfo, 8> kObjectKinds = {{
    {"buffers", [](GLuint n) { return glIsBuffer(n); }},
    {"textures", [](GLuint n) { return glIsTexture(n); }},
    {"framebuffers", [](GLuint n) { return glIsFramebuffer(n); }},
    {"vertex arrays", [](GLuint n) { return glIsVertexArray(n); }},
    {"programs", [](GLuint n) { return glIsProgram(n); }},
    {"shaders", [](GLuint n) { return glIsShader(n); }},
    {"queries", [](GLuint n) { return glIsQuery(n); }},
    {"samplers", [](GLuint n) { return glIsSampler(n); }},
}};
static_assert(static_cast<std::size_t>(ObjectKind::Sampler) + 1 == kObjectKinds.size());

/// Live objects per kind (indexed by ObjectKind) and their sum.
struct ObjectCounts {
    std::array<int, kObjectKinds.size()> live{};
    [[nodiscard]] int total() const;
    /// "buffers 12, textures 30, ..." (kinds with none left out).
    [[nodiscard]] std::string text() const;
};

/// Counts the current context's live objects: every name up to the highest one created so far
/// (noteCreated) is asked. Cost: one glIs* call per name ever issued.
ObjectCounts countLiveObjects();

/// Records a name just created (called by the wrappers' constructors), so that
/// countLiveObjects knows how far to ask.
void noteCreated(ObjectKind kind, GLuint name);

} // namespace fl::gl
