// The web build's side of Context.h: the page makes the WebGL2 context on its canvas and the
// Renderer draws in it (ContextOptions::currentContext); there is no headless context in a
// browser, no OpenGL 4.5 and no KHR_debug.
#include <emscripten/html5_webgl.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "gl/Context.h"
#include "gl/Gl.h"
#include "gnomon/Error.h"

namespace gnomon::gl {
namespace {
[[noreturn]] void fail(const std::string& message) {
    throw Error(ErrorKind::Gl, message);
}
}  // namespace

HeadlessContext::HeadlessContext(bool, bool, Api) {
    fail(
        "a browser has no headless OpenGL context: draw in the page's WebGL2 context "
        "(ContextOptions::currentContext)");
}

HeadlessContext::~HeadlessContext() = default;

void HeadlessContext::makeCurrent() {}

bool hasCurrentContext() {
    return emscripten_webgl_get_current_context() != 0;
}

void requireGl45() {
    fail("a browser has WebGL2, not OpenGL 4.5 (" + currentGlInfo() + ")");
}

void requireGles3() {
    const GLubyte* v = glGetString(GL_VERSION);
    int major = 0;
    if (!v || std::sscanf(reinterpret_cast<const char*>(v), "OpenGL ES %d", &major) != 1 ||
        major < 3) {
        fail("no usable WebGL: gnomon needs WebGL2 (OpenGL ES 3.0), the browser gave " +
             currentGlInfo());
    }
}

void requireUsable() {
    requireGles3();
}

void installDebugOutput() {}  // WebGL reports errors through the browser's console

void enableWebGlExtensions() {
    const EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context = emscripten_webgl_get_current_context();
    for (const char* name : {"EXT_color_buffer_float", "OES_texture_float_linear",
                             "EXT_depth_clamp", "EXT_float_blend"})
        emscripten_webgl_enable_extension(context, name);
    emscripten_webgl_enable_WEBGL_multi_draw(context);
}

}  // namespace gnomon::gl
