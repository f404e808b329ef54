// Natively GLFW 3.3 with an OpenGL 4.5 core context; in the web build Emscripten's GLFW (the
// 3.2 API) on the page's canvas (Module.canvas) with a WebGL2 context.
#include "gl/Window.h"

#include "gl/Gl.h"  // before GLFW, which then includes no GL header of its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>

#include "gl/Context.h"
#include "gnomon/Error.h"

namespace gnomon::gl {
namespace {
#ifdef __EMSCRIPTEN__
std::string lastGlfwError() {
    return "the browser gave no WebGL2 context on the page's canvas";
}
#else
std::string lastGlfwError() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}
#endif
}  // namespace

Window::Window(const WindowSettings& settings) {
    if (!glfwInit()) {
        throw Error(ErrorKind::Gl, "cannot open a window: " + lastGlfwError() +
                                       " (no display? run under xvfb-run -a)");
    }
#ifdef __EMSCRIPTEN__
    // WebGL2 (the build links for no other); the colour buffer needs no depth of its own.
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_DEPTH_BITS, 0);
    glfwWindowHint(GLFW_STENCIL_BITS, 0);
    const char* kind = "WebGL2";
#else
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, settings.debug ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, settings.visible ? GLFW_TRUE : GLFW_FALSE);
    const char* kind = "OpenGL 4.5 core";
#endif
    mWindow =
        glfwCreateWindow(settings.width, settings.height, settings.title.c_str(), nullptr, nullptr);
    if (!mWindow) {
        const std::string reason = lastGlfwError();
        glfwTerminate();
        throw Error(ErrorKind::Gl, std::string("cannot open an ") + kind + " window: " + reason);
    }
    glfwMakeContextCurrent(mWindow);
    try {
        glfwSwapInterval(settings.vsync ? 1 : 0);
        requireUsable();
#ifdef __EMSCRIPTEN__
        enableWebGlExtensions();
#endif
        if (settings.debug) installDebugOutput();
    } catch (...) {
        glfwDestroyWindow(mWindow);
        glfwTerminate();
        throw;
    }
}

Window::~Window() {
    glfwDestroyWindow(mWindow);
    glfwTerminate();
}

bool Window::shouldClose() const {
    return glfwWindowShouldClose(mWindow) != 0;
}
void Window::swapBuffers() {
    glfwSwapBuffers(mWindow);
}
void Window::pollEvents() {
    glfwPollEvents();
}
void Window::waitEvents([[maybe_unused]] double seconds) {
#ifndef __EMSCRIPTEN__
    glfwWaitEventsTimeout(seconds);  // a page cannot wait: the browser calls it each frame
#endif
}
void Window::setSize(int width, int height) {
    glfwSetWindowSize(mWindow, width, height);
}
void Window::framebufferSize(int& width, int& height) const {
    glfwGetFramebufferSize(mWindow, &width, &height);
}

void Window::clear(float r, float g, float b) {
    int width = 0, height = 0;
    framebufferSize(width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearColor(r, g, b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
}

Image Window::readBack() const {
    int width = 0, height = 0;
    framebufferSize(width, height);
    Image image(std::max(width, 0), std::max(height, 0), 4);
    if (image.pixels.empty()) return image;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    // GL's rows run bottom-up; an Image's top-down.
    const std::size_t row = std::size_t(width) * 4;
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(image.at(0, y), image.at(0, y) + row, image.at(0, height - 1 - y));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.at(x, y)[3] = 255;
    return image;
}

}  // namespace gnomon::gl
