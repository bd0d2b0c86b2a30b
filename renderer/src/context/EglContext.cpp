#include <gpu/Gl.h>
#include <renderer/context/EglContext.h>

#include <epoxy/egl.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
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

// The enumerated EGL devices, or none (with the reason in `failures`) when the client offers no
// device enumeration.
std::vector<EGLDeviceEXT> eglDevices(const char* client, std::vector<std::string>& failures) {
    if (!hasExtension(client, "EGL_EXT_platform_device") ||
        !hasExtension(client, "EGL_EXT_device_enumeration")) {
        failures.push_back("EGL_EXT_platform_device not offered by the EGL client");
        return {};
    }
    EGLint count = 0;
    if (!eglQueryDevicesEXT(0, nullptr, &count)) {
        failures.push_back(eglErrorText("eglQueryDevicesEXT"));
        return {};
    }
    std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(std::max(count, 0)));
    if (count > 0 && !eglQueryDevicesEXT(count, devices.data(), &count)) {
        failures.push_back(eglErrorText("eglQueryDevicesEXT"));
        return {};
    }
    devices.resize(static_cast<std::size_t>(std::max(count, 0)));
    return devices;
}

// Device `index`'s display as a candidate, or nothing (reason in `failures`).
void addDevice(std::vector<Candidate>& out, EGLDeviceEXT device, std::size_t index,
               std::vector<std::string>& failures) {
    EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
    if (d != EGL_NO_DISPLAY)
        out.push_back({d, "EGL device " + std::to_string(index)});
    else
        failures.push_back("EGL device " + std::to_string(index) + ": " +
                           eglErrorText("eglGetPlatformDisplayEXT(device)"));
}

// Every display worth trying, in order of preference: each enumerated device, then surfaceless.
// With a chosen device (FLOODLIGHT_EGL_DEVICE), only that one: a user who names a device wants
// its numbers, not a silent fallback to another.
std::vector<Candidate> candidateDisplays(std::optional<std::size_t> chosen,
                                         std::vector<std::string>& failures) {
    std::vector<Candidate> out;
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    const std::vector<EGLDeviceEXT> devices = eglDevices(client, failures);
    if (chosen) {
        if (*chosen < devices.size()) addDevice(out, devices[*chosen], *chosen, failures);
        return out;
    }
    for (std::size_t i = 0; i < devices.size(); ++i) addDevice(out, devices[i], i, failures);
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

std::optional<std::size_t> chosenEglDevice() {
    const char* text = std::getenv(kEglDeviceVariable);
    if (text == nullptr || *text == '\0') return std::nullopt;
    std::size_t index = 0;
    const char* end = text + std::strlen(text);
    const auto [p, ec] = std::from_chars(text, end, index);
    if (ec != std::errc() || p != end || index > 1024)
        throw EglDeviceError(std::string(kEglDeviceVariable) + "=" + text +
                             ": not a device index (0, 1, ...; unset: the first that works)");
    return index;
}

std::vector<EglDeviceInfo> listEglDevices() {
    std::vector<std::string> failures;
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    const std::vector<EGLDeviceEXT> devices = eglDevices(client, failures);
    std::vector<EglDeviceInfo> out;
    for (std::size_t i = 0; i < devices.size(); ++i) {
        EglDeviceInfo info{i, ""};
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        EGLint major = 0, minor = 0;
        if (d == EGL_NO_DISPLAY || !eglInitialize(d, &major, &minor)) {
            info.renderer = "(cannot be opened: " + eglErrorText("eglInitialize") + ")";
            out.push_back(info);
            continue;
        }
        std::string failure;
        EGLContext ctx = createContext(d, false, failure);
        if (ctx != EGL_NO_CONTEXT && eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
            info.renderer = gl::rendererName();
            eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        } else {
            info.renderer = "(no OpenGL 4.5 core context: " +
                            (failure.empty() ? eglErrorText("eglMakeCurrent") : failure) + ")";
        }
        if (ctx != EGL_NO_CONTEXT) eglDestroyContext(d, ctx);
        eglTerminate(d);
        out.push_back(info);
    }
    return out;
}

std::unique_ptr<EglContext> EglContext::create(bool debug) {
    const std::optional<std::size_t> chosen = chosenEglDevice();
    std::vector<std::string> failures;
    const std::vector<Candidate> candidates = candidateDisplays(chosen, failures);
    if (chosen && candidates.empty() && failures.empty()) {
        const std::vector<EglDeviceInfo> found = listEglDevices();
        std::string msg = std::string(kEglDeviceVariable) + "=" + std::to_string(*chosen) +
                          ": no such EGL device; " + std::to_string(found.size()) + " found";
        for (const EglDeviceInfo& d : found)
            msg += "\n  " + std::to_string(d.index) + ": " + d.renderer;
        throw EglDeviceError(msg);
    }
    for (const Candidate& c : candidates) {
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
    std::string msg = chosen ? std::string(kEglDeviceVariable) + "=" + std::to_string(*chosen) +
                                   ": no OpenGL 4.5 core context on that device:"
                             : "no headless OpenGL 4.5 core context could be created:";
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
