#include "gl/Window.h"

#include <GLFW/glfw3.h>

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

Window::Window(const std::string& title, int width, int height, bool debug, bool visible) {
    if (!glfwInit()) {
        throw Error(ErrorKind::Gl, "cannot open a window: " + lastGlfwError() +
                                       " (no display? run under xvfb-run -a)");
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
    mWindow = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!mWindow) {
        const std::string reason = lastGlfwError();
        glfwTerminate();
        throw Error(ErrorKind::Gl, "cannot open an OpenGL 4.5 core window: " + reason);
    }
    glfwMakeContextCurrent(mWindow);
    try {
        glfwSwapInterval(0);
        requireGl45();
        if (debug) installDebugOutput();
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
void Window::framebufferSize(int& width, int& height) const {
    glfwGetFramebufferSize(mWindow, &width, &height);
}

}  // namespace gnomon::gl
