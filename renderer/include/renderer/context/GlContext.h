#pragma once
// The GL 4.5 core context a renderer draws with. Passes never know which kind they run in.

#include <glm/glm.hpp>

#include <memory>
#include <string>

namespace fl {

class GlContext {
  public:
    virtual ~GlContext() = default;
    GlContext() = default;
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    /// Makes this context current on the calling thread.
    virtual void makeCurrent() = 0;
    /// Human-readable description: platform, GL version and renderer.
    [[nodiscard]] virtual std::string description() const = 0;
};

/// Reads GL_VERSION / GL_RENDERER of the current context into one line.
std::string describeCurrentGl(const std::string& platform);

/// Verifies the current context is at least GL 4.5 core and installs the debug callback;
/// throws fl::gl::GlError otherwise.
void initialiseCurrentGl(const std::string& platform);

} // namespace fl
