// A desktop window with an OpenGL 4.5 core context (GLFW), for the interactive viewer.
// Under a headless machine it runs inside Xvfb (xvfb-run). Failures throw gnomon::Error.
#pragma once

#include <string>

struct GLFWwindow;

namespace gnomon::gl {

class Window {
public:
    Window(const std::string& title, int width, int height, bool debug, bool visible = true);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return mWindow; }
    bool shouldClose() const;
    void swapBuffers();
    void pollEvents();
    // Size of the default framebuffer in pixels.
    void framebufferSize(int& width, int& height) const;

private:
    GLFWwindow* mWindow = nullptr;
};

}  // namespace gnomon::gl
