// OpenGL 4.5 core contexts. HeadlessContext renders without a window or X server through
// EGL: Mesa's surfaceless platform first, then the device platform (which NVIDIA's EGL also
// offers); everything is drawn into framebuffer objects. Failures throw one sentence that
// names what is missing.
#pragma once

#include <string>

namespace gnomon::gl {

class HeadlessContext {
public:
    // `verbose` prints the GL vendor/renderer/version and EGL platform to stderr.
    HeadlessContext(bool debug, bool verbose);
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
// "vendor / renderer / version" of the current context.
std::string currentGlInfo();
// Throws gnomon::Error unless the current context is OpenGL >= 4.5 core.
void requireGl45();
// Routes KHR_debug messages of the current context to stderr (errors and warnings).
void installDebugOutput();

}  // namespace gnomon::gl
