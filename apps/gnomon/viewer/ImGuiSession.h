// The Dear ImGui session bound to the viewer's window (gl::Window): its context and its GLFW
// and OpenGL 3 backends (which make their own GL calls), created and destroyed in order; the
// UI font (DejaVu Sans) and sizes scaled by the window's content scale (HiDPI screens).
#pragma once

#include <algorithm>
#include <cstdio>
#include <filesystem>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#ifdef __EMSCRIPTEN__
#include <emscripten/html5.h>
#endif
#include <imgui.h>

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

namespace gnomon::cli::viewer {

class ImGuiSession {
public:
    explicit ImGuiSession(GLFWwindow* window) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;  // no imgui.ini left in the working folder
        const float scale = std::clamp(contentScale(window), 1.0f, 4.0f);
        style(scale);
        loadFont(io, scale);
        ImGui_ImplGlfw_InitForOpenGL(window, true);
#ifdef __EMSCRIPTEN__
        ImGui_ImplOpenGL3_Init("#version 300 es");  // WebGL2
#else
        ImGui_ImplOpenGL3_Init("#version 410 core");
#endif
    }
    ~ImGuiSession() {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    ImGuiSession(const ImGuiSession&) = delete;
    ImGuiSession& operator=(const ImGuiSession&) = delete;

private:
    // Screen pixels per window unit: the desktop's scale, or the page's device pixel ratio
    // (Emscripten's GLFW has the 3.2 API, without content scales).
    static float contentScale([[maybe_unused]] GLFWwindow* window) {
#ifdef __EMSCRIPTEN__
        return float(emscripten_get_device_pixel_ratio());
#else
        float xScale = 1.0f, yScale = 1.0f;
        glfwGetWindowContentScale(window, &xScale, &yScale);
        return std::max(xScale, yScale);
#endif
    }

    // Dear ImGui's dark theme, less boxy: rounded frames, roomier rows, a tool's blue.
    static void style(float scale) {
        ImGui::StyleColorsDark();
        ImGuiStyle& s = ImGui::GetStyle();
        s.WindowRounding = 0.0f;
        s.FrameRounding = 3.0f;
        s.GrabRounding = 3.0f;
        s.TabRounding = 3.0f;
        s.FramePadding = {6.0f, 3.0f};
        s.ItemSpacing = {7.0f, 4.0f};
        s.WindowBorderSize = 0.0f;
        s.Colors[ImGuiCol_WindowBg] = {0.11f, 0.11f, 0.12f, 1.0f};
        s.Colors[ImGuiCol_Header] = {0.20f, 0.25f, 0.32f, 1.0f};
        s.Colors[ImGuiCol_Tab] = {0.16f, 0.19f, 0.24f, 1.0f};
        s.ScaleAllSizes(scale);
    }
    static void loadFont(ImGuiIO& io, float scale) {
#ifdef GNOMON_UI_FONT
        constexpr float kPixels = 15.0f;  // DejaVu Sans at 15 px reads as 11 pt
        std::error_code ec;
        if (std::filesystem::is_regular_file(GNOMON_UI_FONT, ec) &&
            io.Fonts->AddFontFromFileTTF(GNOMON_UI_FONT, kPixels * scale)) {
            return;
        }
        std::fprintf(stderr,
                     "gnomon view: warning: cannot read the font %s; using the built-in "
                     "one\n",
                     GNOMON_UI_FONT);
#endif
        ImFontConfig config;
        config.SizePixels = 13.0f * scale;
        io.Fonts->AddFontDefault(&config);
    }
};

}  // namespace gnomon::cli::viewer
