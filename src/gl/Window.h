// A desktop window with an OpenGL 4.5 core context (GLFW), for the interactive viewer.
// Under a headless machine it runs inside Xvfb (xvfb-run). Failures throw gnomon::Error.
// The window's default framebuffer is drawn and read here, so that its users make no GL
// calls of their own.
#pragma once

#include <string>

#include "gnomon/Image.h"

struct GLFWwindow;

namespace gnomon::gl {

struct WindowSettings {
    std::string title = "gnomon";
    int width = 1280;
    int height = 720;
    bool debug = false;   // a debug context with GL messages on stderr
    bool visible = true;  // false: an off-screen window (tests)
    bool vsync = false;   // swap on the display's refresh (an interactive app)
};

class Window {
public:
    explicit Window(const WindowSettings& settings);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    // For toolkits bound to the window (Dear ImGui's GLFW backend).
    GLFWwindow* handle() const { return mWindow; }
    bool shouldClose() const;
    void swapBuffers();
    void pollEvents();
    // Sleeps until an event arrives or `seconds` pass (an idle app's loop).
    void waitEvents(double seconds);
    // Resizes the window (in the page: its canvas) to width x height screen units.
    void setSize(int width, int height);
    // Size of the default framebuffer in pixels.
    void framebufferSize(int& width, int& height) const;
    // Binds the default framebuffer, sets the viewport to all of it and clears it to the
    // colour (r, g, b), opaque.
    void clear(float r, float g, float b);
    // The back buffer as drawn so far (before the swap): RGBA8, first row at the top,
    // alpha 255.
    Image readBack() const;

private:
    GLFWwindow* mWindow = nullptr;
};

}  // namespace gnomon::gl
