#include <gpu/Gl.h>
#include <renderer/context/GlContext.h>

namespace fl {

std::string describeCurrentGl(const std::string& platform) {
    const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return platform + ", OpenGL " + (version ? version : "?") + ", " + gl::rendererName();
}

void initialiseCurrentGl(const std::string& platform) {
    const int version = epoxy_gl_version();
    if (version < 45)
        throw gl::GlError(platform + ": OpenGL 4.5 core required, context offers " +
                          std::to_string(version / 10) + "." + std::to_string(version % 10));
    gl::installDebugOutput();
    gl::throwIfErrors("context initialisation");
}

} // namespace fl
