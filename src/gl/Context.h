// OpenGL 4.5 core contexts (and OpenGL ES 3 ones, the web build's API, for its path through
// the tests). HeadlessContext renders without a window or X server through EGL: Mesa's
// surfaceless platform first, then the device platform (which NVIDIA's EGL also offers);
// everything is drawn into framebuffer objects. Failures throw one sentence that names what
// is missing.
#pragma once

#include <string>

#include "gl/Caps.h"

namespace gnomon::gl {

class HeadlessContext {
public:
    // `verbose` prints the GL vendor/renderer/version and EGL platform to stderr. `api`:
    // OpenGL 4.5 core, or OpenGL ES 3.0 or later (whatever the driver gives from 3.0 up).
    HeadlessContext(bool debug, bool verbose, Api api = Api::Gl45);
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    void makeCurrent();
    // e.g. "EGL surfaceless (Mesa)".
    const std::string& platform() const { return mPlatform; }

private:
    void* mDisplay = nullptr;
    void* mContext = nullptr;
    std::string mPlatform;
};

// True when this thread has a current EGL or GLX context (a GLFW window's, for example).
bool hasCurrentContext();
// Throws gnomon::Error unless the current context is OpenGL >= 4.5 core.
void requireGl45();
// Throws gnomon::Error unless the current context is OpenGL ES >= 3.0.
void requireGles3();
// Either, by the current context's API.
void requireUsable();
// Routes KHR_debug messages of the current context to stderr (errors and warnings).
void installDebugOutput();
#ifdef __EMSCRIPTEN__
// Enables on the current WebGL2 context the extensions the renderer uses where the browser
// has them (gl::Caps then finds them): WebGL hands an extension's features over only once
// it is enabled.
void enableWebGlExtensions();
#endif

}  // namespace gnomon::gl
