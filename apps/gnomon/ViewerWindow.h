// The viewer's window-system lifetimes: the GLFW window and its GL context, the Dear ImGui
// session bound to it, and GL textures made from images (the score's error overlay).
#pragma once

#include <epoxy/gl.h>  // before GLFW, which then includes no GL header of its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <algorithm>
#include <string>
#include <utility>

#include "gnomon/gnomon.h"

namespace gnomon::cli::viewer {

class GlfwWindow {
public:
    GlfwWindow(int width, int height) {
        if (!glfwInit()) {
            throw Error(ErrorKind::Gl, "gnomon view: cannot open a window: " + glfwError() +
                                           " (no display? run under xvfb-run -a)");
        }
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        mWindow = glfwCreateWindow(width, height, "gnomon view", nullptr, nullptr);
        if (!mWindow) {
            const std::string reason = glfwError();
            glfwTerminate();
            throw Error(ErrorKind::Gl,
                        "gnomon view: cannot open an OpenGL 4.5 core window: " + reason);
        }
        glfwMakeContextCurrent(mWindow);
        glfwSwapInterval(1);
    }
    ~GlfwWindow() {
        glfwDestroyWindow(mWindow);
        glfwTerminate();
    }
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;
    GLFWwindow* get() const { return mWindow; }

private:
    static std::string glfwError() {
        const char* description = nullptr;
        glfwGetError(&description);
        return description ? description : "unknown GLFW error";
    }
    GLFWwindow* mWindow = nullptr;
};

class ImGuiSession {
public:
    explicit ImGuiSession(GLFWwindow* window) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working folder
        ImGui::StyleColorsDark();
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        ImGui_ImplOpenGL3_Init("#version 410 core");
    }
    ~ImGuiSession() {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    ImGuiSession(const ImGuiSession&) = delete;
    ImGuiSession& operator=(const ImGuiSession&) = delete;
};

// An RGBA8 texture made from an Image (the score's error map).
class ImageTexture {
public:
    ImageTexture() = default;
    explicit ImageTexture(const Image& image) {
        glCreateTextures(GL_TEXTURE_2D, 1, &mName);
        glTextureStorage2D(mName, 1, GL_RGBA8, image.width, image.height);
        glTextureParameteri(mName, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(mName, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        Image rgba = image;
        if (image.channels != 4) {
            rgba = Image(image.width, image.height, 4);
            for (int y = 0; y < image.height; ++y) {
                for (int x = 0; x < image.width; ++x) {
                    for (int c = 0; c < 3; ++c)
                        rgba.at(x, y)[c] = image.at(x, y)[std::min(c, image.channels - 1)];
                    rgba.at(x, y)[3] = 255;
                }
            }
        }
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTextureSubImage2D(mName, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                            rgba.pixels.data());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    }
    ~ImageTexture() {
        if (mName) glDeleteTextures(1, &mName);
    }
    ImageTexture(ImageTexture&& o) noexcept : mName(std::exchange(o.mName, 0)) {}
    ImageTexture& operator=(ImageTexture&& o) noexcept {
        std::swap(mName, o.mName);
        return *this;
    }
    GLuint id() const { return mName; }

private:
    GLuint mName = 0;
};

}  // namespace gnomon::cli::viewer
