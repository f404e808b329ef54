// window.glfw_xvfb: opens a 128x96 GLFW window with an OpenGL 4.5 core context, clears its
// default framebuffer to a known colour through gl::Window (as the viewer does), reads the
// back buffer back before the swap and checks every pixel. Exit 0: pass, 77: no display or
// no GL 4.5 (skipped), 1: failure.
#include <epoxy/gl.h>

#include <cstdio>
#include <exception>
#include <memory>

#include "gl/Window.h"
#include "gnomon/Error.h"

int main() {
    constexpr int kWidth = 128;
    constexpr int kHeight = 96;
    // Exactly representable in 8-bit channels: 51/255, 102/255, 204/255.
    constexpr int kExpected[3] = {51, 102, 204};

    std::unique_ptr<gnomon::gl::Window> window;
    try {
        window = std::make_unique<gnomon::gl::Window>(gnomon::gl::WindowSettings{
            .title = "gnomon window smoke test", .width = kWidth, .height = kHeight});
    } catch (const gnomon::Error& e) {
        std::printf("skipped: %s\n", e.what());
        return 77;
    }

    try {
        int width = 0;
        int height = 0;
        window->framebufferSize(width, height);
        if (width <= 0 || height <= 0) {
            std::fprintf(stderr, "empty default framebuffer %dx%d\n", width, height);
            return 1;
        }
        window->clear(kExpected[0] / 255.0f, kExpected[1] / 255.0f, kExpected[2] / 255.0f);
        const gnomon::Image image = window->readBack();
        if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
            std::fprintf(stderr, "GL error 0x%04x after clear and read-back\n", error);
            return 1;
        }
        if (image.width != width || image.height != height || image.channels != 4) {
            std::fprintf(stderr, "read back %dx%dx%d; expected %dx%dx4\n", image.width,
                         image.height, image.channels, width, height);
            return 1;
        }
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const std::uint8_t* p = image.at(x, y);
                if (p[0] != kExpected[0] || p[1] != kExpected[1] || p[2] != kExpected[2] ||
                    p[3] != 255) {
                    std::fprintf(stderr, "pixel (%d,%d) is %d,%d,%d,%d; expected %d,%d,%d,255\n", x,
                                 y, p[0], p[1], p[2], p[3], kExpected[0], kExpected[1],
                                 kExpected[2]);
                    return 1;
                }
            }
        }

        window->swapBuffers();
        window->pollEvents();
        std::printf("window %dx%d, framebuffer %dx%d: %s / %s / %s\n", kWidth, kHeight, width,
                    height, reinterpret_cast<const char*>(glGetString(GL_VENDOR)),
                    reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
                    reinterpret_cast<const char*>(glGetString(GL_VERSION)));
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
}
