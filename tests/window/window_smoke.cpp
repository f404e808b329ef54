// window.glfw_xvfb: opens a 128x96 GLFW window with an OpenGL 4.5 core context, clears its
// default framebuffer to a known colour, reads the centre pixel back from the back buffer
// before the swap and checks it. Exit 0: pass, 77: no display or no GL 4.5 (skipped),
// 1: failure.
#include <epoxy/gl.h>

#include <cstdio>
#include <exception>
#include <memory>

#include "gl/Window.h"
#include "gnomon/Error.h"

int main() {
    constexpr int kWidth = 128;
    constexpr int kHeight = 96;
    // Exactly representable in 8-bit channels: 51/255, 102/255, 204/255, 255/255.
    constexpr GLubyte kExpected[4] = {51, 102, 204, 255};

    std::unique_ptr<gnomon::gl::Window> window;
    try {
        window = std::make_unique<gnomon::gl::Window>("gnomon window smoke test", kWidth, kHeight,
                                                      /*debug=*/false);
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

        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, width, height);
        glDisable(GL_SCISSOR_TEST);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glClearColor(kExpected[0] / 255.0f, kExpected[1] / 255.0f, kExpected[2] / 255.0f,
                     kExpected[3] / 255.0f);
        glClear(GL_COLOR_BUFFER_BIT);

        GLubyte pixel[4] = {0, 0, 0, 0};
        glReadBuffer(GL_BACK);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(width / 2, height / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
        if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
            std::fprintf(stderr, "GL error 0x%04x after clear and read-back\n", error);
            return 1;
        }
        // RGB must match exactly; alpha only when the default framebuffer stores it.
        GLint alphaBits = 0;
        glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_BACK_LEFT,
                                              GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE, &alphaBits);
        const bool rgbOk =
            pixel[0] == kExpected[0] && pixel[1] == kExpected[1] && pixel[2] == kExpected[2];
        const bool alphaOk = alphaBits == 0 || pixel[3] == kExpected[3];
        if (!rgbOk || !alphaOk) {
            std::fprintf(stderr,
                         "centre pixel (%d,%d) is %d,%d,%d,%d; expected %d,%d,%d,%d "
                         "(%d alpha bits)\n",
                         width / 2, height / 2, pixel[0], pixel[1], pixel[2], pixel[3],
                         kExpected[0], kExpected[1], kExpected[2], kExpected[3], alphaBits);
            return 1;
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
