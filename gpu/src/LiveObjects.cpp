#include <gpu/LiveObjects.h>

#include <algorithm>
#include <atomic>
#include <numeric>

namespace fl::gl {

namespace {

// The highest name each kind has issued. A driver may reuse freed names or not (Mesa hands out
// the next unused number), so the range to ask is bounded by what was issued, not by a guess.
std::array<std::atomic<GLuint>, kObjectKinds.size()> g_highest{};

GLboolean isLive(ObjectKind kind, GLuint name) {
    switch (kind) {
    case ObjectKind::Buffer:
        return glIsBuffer(name);
    case ObjectKind::Texture:
        return glIsTexture(name);
    case ObjectKind::Framebuffer:
        return glIsFramebuffer(name);
    case ObjectKind::VertexArray:
        return glIsVertexArray(name);
    case ObjectKind::Program:
        return glIsProgram(name);
    case ObjectKind::Shader:
        return glIsShader(name);
    case ObjectKind::Query:
        return glIsQuery(name);
    case ObjectKind::Sampler:
        return glIsSampler(name);
    }
    return GL_FALSE;
}

} // namespace

int ObjectCounts::total() const {
    return std::accumulate(live.begin(), live.end(), 0);
}

std::string ObjectCounts::text() const {
    std::string s;
    for (std::size_t k = 0; k < live.size(); ++k) {
        if (live[k] == 0) continue;
        if (!s.empty()) s += ", ";
        s += std::string(kObjectKinds[k]) + " " + std::to_string(live[k]);
    }
    return s.empty() ? "none" : s;
}

ObjectCounts countLiveObjects() {
    ObjectCounts c;
    for (std::size_t k = 0; k < kObjectKinds.size(); ++k) {
        const GLuint highest = g_highest[k].load();
        for (GLuint name = 1; name <= highest; ++name)
            c.live[k] += isLive(static_cast<ObjectKind>(k), name) ? 1 : 0;
    }
    return c;
}

void noteCreated(ObjectKind kind, GLuint name) {
    std::atomic<GLuint>& h = g_highest[static_cast<std::size_t>(kind)];
    for (GLuint now = h.load(); name > now && !h.compare_exchange_weak(now, name);) {
    }
}

} // namespace fl::gl
