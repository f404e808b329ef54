#include "gl/Window.h"

#include <epoxy/gl.h>  // before GLFW, which then includes no GL header of its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>

#include "gl/Context.h"
#include "gnomon/Error.h"

namespace gnomon::gl {
namespace {
std::string lastGlfwError() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}
}  // namespace

Window::Window(const WindowSettings& settings) {
    if (!glfwInit()) {
        throw Error(ErrorKind::Gl, "cannot open a window: " + lastGlfwError() +
                                       " (no display? run under xvfb-run -a)");
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, settings.debug ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, settings.visible ? GLFW_TRUE : GLFW_FALSE);
    mWindow =
        glfwCreateWindow(settings.width, settings.height, settings.title.c_str(), nullptr, nullptr);
    if (!mWindow) {
        const std::string reason = lastGlfwError();
        glfwTerminate();
        throw Error(ErrorKind::Gl, "cannot open an OpenGL 4.5 core window: " + reason);
    }
    glfwMakeContextCurrent(mWindow);
    try {
        glfwSwapInterval(settings.vsync ? 1 : 0);
        requireGl45();
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
void Window::waitEvents(double seconds) {
    glfwWaitEventsTimeout(seconds);
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
