#include <gpu/Gl.h>
#include <renderer/context/EglContext.h>

#include <epoxy/egl.h>

#include <cstring>
#include <sstream>
#include <vector>

namespace fl {

namespace {

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p; p = std::strstr(p + 1, name))
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

std::string eglErrorText(const char* what) {
    std::ostringstream s;
    s << what << " failed (EGL error 0x" << std::hex << eglGetError() << ")";
    return s.str();
}

struct Candidate {
    EGLDisplay display;
    std::string platform;
};

// Every display worth trying, in order of preference: each enumerated device, then surfaceless.
std::vector<Candidate> candidateDisplays(std::vector<std::string>& failures) {
    std::vector<Candidate> out;
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (hasExtension(client, "EGL_EXT_platform_device") &&
        hasExtension(client, "EGL_EXT_device_enumeration")) {
        EGLint count = 0;
        EGLDeviceEXT devices[16];
        if (eglQueryDevicesEXT(16, devices, &count)) {
            for (EGLint i = 0; i < count; ++i) {
                EGLDisplay d =
                    eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (d != EGL_NO_DISPLAY)
                    out.push_back({d, "EGL device " + std::to_string(i)});
                else
                    failures.push_back(eglErrorText("eglGetPlatformDisplayEXT(device)"));
            }
        } else {
            failures.push_back(eglErrorText("eglQueryDevicesEXT"));
        }
    } else {
        failures.push_back("EGL_EXT_platform_device not offered by the EGL client");
    }
    if (hasExtension(client, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d =
            eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY)
            out.push_back({d, "EGL surfaceless"});
        else
            failures.push_back(eglErrorText("eglGetPlatformDisplayEXT(surfaceless)"));
    } else {
        failures.push_back("EGL_MESA_platform_surfaceless not offered by the EGL client");
    }
    return out;
}

EGLContext createContext(EGLDisplay display, bool debug, std::string& failure) {
    if (!eglBindAPI(EGL_OPENGL_API)) {
        failure = eglErrorText("eglBindAPI(OpenGL)");
        return EGL_NO_CONTEXT;
    }
    const char* ext = eglQueryString(display, EGL_EXTENSIONS);
    if (!hasExtension(ext, "EGL_KHR_surfaceless_context")) {
        failure = "no EGL_KHR_surfaceless_context";
        return EGL_NO_CONTEXT;
    }
    EGLConfig config = nullptr;
    if (!hasExtension(ext, "EGL_KHR_no_config_context")) {
        const EGLint attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint n = 0;
        if (!eglChooseConfig(display, attribs, &config, 1, &n) || n == 0) {
            failure = eglErrorText("eglChooseConfig(OpenGL)");
            return EGL_NO_CONTEXT;
        }
    }
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                              4,
                              EGL_CONTEXT_MINOR_VERSION,
                              5,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK,
                              EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                              EGL_CONTEXT_OPENGL_DEBUG,
                              debug ? EGL_TRUE : EGL_FALSE,
                              EGL_NONE};
    EGLContext ctx = eglCreateContext(display, config, EGL_NO_CONTEXT, attribs);
    if (ctx == EGL_NO_CONTEXT) failure = eglErrorText("eglCreateContext(GL 4.5 core)");
    return ctx;
}

} // namespace

std::unique_ptr<EglContext> EglContext::create(bool debug) {
    std::vector<std::string> failures;
    for (const Candidate& c : candidateDisplays(failures)) {
        EGLint major = 0, minor = 0;
        if (!eglInitialize(c.display, &major, &minor)) {
            failures.push_back(c.platform + ": " + eglErrorText("eglInitialize"));
            continue;
        }
        std::string failure;
        EGLContext ctx = createContext(c.display, debug, failure);
        if (ctx == EGL_NO_CONTEXT) {
            failures.push_back(c.platform + ": " + failure);
            eglTerminate(c.display);
            continue;
        }
        if (!eglMakeCurrent(c.display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
            failures.push_back(c.platform + ": " + eglErrorText("eglMakeCurrent"));
            eglDestroyContext(c.display, ctx);
            eglTerminate(c.display);
            continue;
        }
        std::unique_ptr<EglContext> out(new EglContext());
        out->display_ = c.display;
        out->context_ = ctx;
        initialiseCurrentGl(c.platform);
        out->description_ = describeCurrentGl(c.platform);
        return out;
    }
    std::string msg = "no headless OpenGL 4.5 core context could be created:";
    for (const std::string& f : failures) msg += "\n  " + f;
    throw gl::GlError(msg);
}

EglContext::~EglContext() {
    if (display_) {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context_) eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }
}

void EglContext::makeCurrent() {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
        throw gl::GlError(eglErrorText("eglMakeCurrent"));
}

} // namespace fl
