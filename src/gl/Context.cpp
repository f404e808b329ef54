#include "gl/Context.h"

#include <dlfcn.h>
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <cstring>
#include <mutex>
#include <vector>

#include "gnomon/Error.h"

namespace gnomon::gl {
namespace {

std::string eglErrorName(EGLint e) {
    switch (e) {
        case EGL_NOT_INITIALIZED:
            return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS:
            return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC:
            return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE:
            return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG:
            return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT:
            return "EGL_BAD_CONTEXT";
        case EGL_BAD_DISPLAY:
            return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH:
            return "EGL_BAD_MATCH";
        case EGL_BAD_PARAMETER:
            return "EGL_BAD_PARAMETER";
        default: {
            char buf[32];
            std::snprintf(buf, sizeof buf, "EGL error 0x%04X", unsigned(e));
            return buf;
        }
    }
}

[[noreturn]] void fail(const std::string& sentence) {
    throw Error(ErrorKind::Gl, sentence);
}

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const std::size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p; p = std::strstr(p + 1, name)) {
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    }
    return false;
}

// The display is initialised once and never terminated: it is shared by every context in
// the process, and eglTerminate would unload the driver (making a second Renderer pay the
// start-up again, and leaving leak checkers unable to name the driver's own allocations).
std::mutex gDisplayMutex;
EGLDisplay gDisplay = EGL_NO_DISPLAY;
std::string gPlatform;

EGLDisplay openDisplay(std::string& platform) {
    // epoxy aborts the process when libEGL is missing; check first to say so in words.
    if (void* lib = dlopen("libEGL.so.1", RTLD_LAZY | RTLD_LOCAL)) {
        dlclose(lib);
    } else {
        fail("no usable OpenGL: libEGL.so.1 is missing (install the Debian package libegl1)");
    }
    const char* clientExts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    std::string tried;
    if (hasExtension(clientExts, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d =
            eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) {
            platform = "EGL surfaceless";
            return d;
        }
        tried += " surfaceless: " + eglErrorName(eglGetError()) + ";";
    }
    if (hasExtension(clientExts, "EGL_EXT_platform_device") &&
        hasExtension(clientExts, "EGL_EXT_device_enumeration")) {
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (eglQueryDevicesEXT(16, devices, &count)) {
            for (EGLint i = 0; i < count; ++i) {
                EGLDisplay d =
                    eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) {
                    platform = "EGL device " + std::to_string(i);
                    return d;
                }
            }
        }
        tried += " device: " + eglErrorName(eglGetError()) + ";";
    }
    if (!clientExts || !*clientExts) {
        fail(
            "no usable OpenGL: libEGL found no EGL driver (install Mesa's libegl-mesa0 and "
            "libgl1-mesa-dri, or your GPU vendor's EGL)");
    }
    if (tried.empty()) {
        fail(
            "no usable OpenGL: EGL offers neither the surfaceless nor the device platform "
            "(client extensions: " +
            std::string(clientExts) + ")");
    }
    fail("no usable OpenGL: EGL could not be initialised (" + tried.substr(1) +
         " is Mesa's driver package libgl1-mesa-dri installed?)");
}

}  // namespace

HeadlessContext::HeadlessContext(bool debug, bool verbose, Api api) {
    std::lock_guard lock(gDisplayMutex);
    if (gDisplay == EGL_NO_DISPLAY) gDisplay = openDisplay(gPlatform);
    EGLDisplay display = gDisplay;
    mPlatform = gPlatform;
    mDisplay = display;
    const bool es = api == Api::Gles3;
    const std::string none = es ? "no usable OpenGL ES" : "no usable OpenGL";
    if (!eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API)) {
        fail(none + ": this EGL cannot bind the " + (es ? "OpenGL ES" : "desktop OpenGL") +
             " API (" + eglErrorName(eglGetError()) + ")");
    }
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
        const EGLint attribs[] = {EGL_RENDERABLE_TYPE, es ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT,
                                  EGL_NONE};
        EGLint n = 0;
        if (!eglChooseConfig(display, attribs, &config, 1, &n) || n < 1) {
            fail(none + ": EGL has no config for " + (es ? "OpenGL ES 3" : "desktop OpenGL"));
        }
    }
    // ES: 3.0, or whichever later version the driver gives.
    std::vector<EGLint> contextAttribs = {EGL_CONTEXT_MAJOR_VERSION, es ? 3 : 4,
                                          EGL_CONTEXT_MINOR_VERSION, es ? 0 : 5};
    if (!es) {
        contextAttribs.insert(contextAttribs.end(), {EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT});
    }
    contextAttribs.insert(contextAttribs.end(),
                          {EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE, EGL_NONE});
    mContext = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttribs.data());
    if (mContext == EGL_NO_CONTEXT) {
        const EGLint e = eglGetError();
        fail(none + ": the driver cannot create an " + (es ? "OpenGL ES 3.0" : "OpenGL 4.5 core") +
             " context (" + eglErrorName(e) + "; gnomon needs " +
             (es ? "OpenGL ES 3.0" : "OpenGL 4.5") + ", Mesa's llvmpipe provides it)");
    }
    try {
        makeCurrent();
        if (verbose) {
            std::fprintf(stderr, "gnomon: OpenGL %s via %s\n", currentGlInfo().c_str(),
                         mPlatform.c_str());
        }
        if (es) {
            requireGles3();
        } else {
            requireGl45();
        }
        if (debug) installDebugOutput();
    } catch (...) {
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display, mContext);
        throw;
    }
}

HeadlessContext::~HeadlessContext() {
    std::lock_guard lock(gDisplayMutex);
    eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(mDisplay, mContext);
}

void HeadlessContext::makeCurrent() {
    if (eglGetCurrentContext() == mContext) return;
    if (!eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, mContext)) {
        fail("cannot make the OpenGL context current without a surface (" +
             eglErrorName(eglGetError()) + ")");
    }
}

bool hasCurrentContext() {
    if (eglGetCurrentContext() != EGL_NO_CONTEXT) return true;
    // GLX only if some library (GLFW) already loaded libGL: never load it here.
    void* libGl = dlopen("libGL.so.1", RTLD_LAZY | RTLD_NOLOAD);
    if (!libGl) return false;
    using GetCurrent = void* (*)();
    auto getCurrent = reinterpret_cast<GetCurrent>(dlsym(libGl, "glXGetCurrentContext"));
    const bool current = getCurrent && getCurrent() != nullptr;
    dlclose(libGl);
    return current;
}

void requireGl45() {
    const int version = epoxy_gl_version();
    GLint mask = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
    if (version < 45 || !(mask & GL_CONTEXT_CORE_PROFILE_BIT)) {
        fail("no usable OpenGL: gnomon needs OpenGL 4.5 core, the driver gave " + currentGlInfo());
    }
}

void requireGles3() {
    if (epoxy_is_desktop_gl() || epoxy_gl_version() < 30) {
        fail("no usable OpenGL ES: gnomon's ES path needs OpenGL ES 3.0, the driver gave " +
             currentGlInfo());
    }
}

namespace {
void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity,
                               GLsizei length, const GLchar* message, const void*) {
    (void)source;
    (void)id;
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    const char* kind = type == GL_DEBUG_TYPE_ERROR         ? "error"
                       : type == GL_DEBUG_TYPE_PERFORMANCE ? "performance"
                                                           : "warning";
    std::fprintf(stderr, "gnomon: GL %s: %.*s\n", kind, int(length), message);
}
}  // namespace

void installDebugOutput() {
    if (!epoxy_has_gl_extension("GL_KHR_debug") && epoxy_gl_version() < 43) return;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
}

void requireUsable() {
    epoxy_is_desktop_gl() ? requireGl45() : requireGles3();
}

}  // namespace gnomon::gl
