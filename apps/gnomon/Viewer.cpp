#include "Viewer.h"

#include <epoxy/gl.h>  // before GLFW, which then includes no GL header of its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <algorithm>
#include <atomic>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <sstream>
#include <thread>

#include "ViewerState.h"
#include "gnomon/gnomon.h"

namespace gnomon::cli {
namespace {

using Clock = std::chrono::steady_clock;

// ---- Window, UI and texture lifetimes -----------------------------------------------------

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

ImTextureID imguiTexture(GLuint name) {
    return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(name));
}

// The default framebuffer's back buffer as an image (docs screenshots of the whole window).
Image readWindow(int width, int height) {
    Image image(width, height, 4);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
    const std::size_t row = std::size_t(width) * 4;
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(image.at(0, y), image.at(0, y) + row, image.at(0, height - 1 - y));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.at(x, y)[3] = 255;
    return image;
}

// ---- Ground truth off the UI thread --------------------------------------------------------

struct ScoreJob {
    ScoreProgress progress;
    std::atomic<bool> done{false};
    std::optional<ScoreResult> result;
    std::string error;
    std::uint64_t revision = 0;  // the state's revision it scored
    std::thread thread;

    ~ScoreJob() {
        progress.cancel = true;
        if (thread.joinable()) thread.join();
    }
};

// ---- One-line docs of the flags, shown as tooltips ----------------------------------------

class FlagDocs {
public:
    FlagDocs() { mFlags.add(mApp); }
    std::string operator()(const std::string& flag) const {
        const CLI::Option* o = mApp.get_option_no_throw(flag);
        return o ? flag + ": " + o->get_description() : flag;
    }

private:
    CLI::App mApp{"flags"};
    RenderFlags mFlags;
};

// The last item's tooltip. Callers that build the text check ImGui::IsItemHovered() first,
// so nothing is formatted on frames where no tooltip shows.
void tooltip(const char* text) {
    if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 32.0f);
        ImGui::TextUnformatted(text);
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
}
void tooltip(const std::string& text) {
    tooltip(text.c_str());
}

template <typename E>
bool enumCombo(const char* label, E& value, std::initializer_list<E> values) {
    bool changed = false;
    if (ImGui::BeginCombo(label, toString(value))) {
        for (E v : values) {
            if (ImGui::Selectable(toString(v), v == value)) {
                changed = v != value;
                value = v;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

// ---- The viewer ----------------------------------------------------------------------------

class Viewer {
public:
    // `state` and `script` are checked before the window opens (runView).
    Viewer(const ViewArgs& args, bool verbose, int windowWidth, int windowHeight, view::State state,
           std::vector<view::Command> script)
        : mArgs(args),
          mVerbose(verbose),
          mWindow(windowWidth, windowHeight),
          mImGui(mWindow.get()),
          mRenderer(contextOptions(verbose)),
          mState(std::move(state)),
          mScript(std::move(script)),
          mScripted(!args.script.empty()) {
        mRenderer.setPassTiming(mMeasure);
        if (mVerbose) std::fprintf(stderr, "gnomon view: OpenGL %s\n", mRenderer.glInfo().c_str());
    }

    int run() {
        auto last = Clock::now();
        while (!glfwWindowShouldClose(mWindow.get()) && !mQuit) {
            const bool idle = !mScripted && !mState.playing && !mJob && !dirty();
            if (idle) {
                glfwWaitEventsTimeout(0.25);
            } else {
                glfwPollEvents();
            }
            const auto now = Clock::now();
            const double dt = std::chrono::duration<double>(now - last).count();
            last = now;
            if (mState.playing) {
                mState.options.time += dt * mState.speed;
                ++mState.revision;
            }
            frame();
            if (mExitCode != 0) return mExitCode;
            mFrameMs.push_back(
                std::chrono::duration<double, std::milli>(Clock::now() - now).count());
            if (mFrameMs.size() > 600) mFrameMs.erase(mFrameMs.begin());
        }
        return mExitCode;
    }

private:
    static ContextOptions contextOptions(bool verbose) {
        ContextOptions o;
        o.verbose = verbose;
        o.currentContext = true;
        return o;
    }

    bool dirty() const { return mState.revision != mDrawnRevision; }

    void frame() {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        runScript();
        if (mExitCode != 0 || mQuit) {
            ImGui::EndFrame();
            return;
        }
        handleKeys();
        pollScore();  // before any draw list refers to the overlay texture it may replace
        const ImGuiIO& io = ImGui::GetIO();
        const float W = io.DisplaySize.x, H = io.DisplaySize.y;
        const float panelW = std::min(380.0f, W * 0.4f), measureH = std::min(190.0f, H * 0.3f);
        const float viewW = W - panelW, viewH = H - measureH;
        const float mainW = mState.side == view::SideView::None ? viewW : std::floor(viewW * 0.6f);
        controls(panelW, H);
        renderViews(int(mainW * io.DisplayFramebufferScale.x),
                    int(viewH * io.DisplayFramebufferScale.y),
                    int((viewW - mainW) * io.DisplayFramebufferScale.x));
        views(panelW, mainW, viewW, viewH);
        measurePanel(panelW, viewH, viewW, measureH);

        ImGui::Render();
        int fbW = 0, fbH = 0;
        glfwGetFramebufferSize(mWindow.get(), &fbW, &fbH);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, fbW, fbH);
        glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        if (!mWindowShot.empty()) {
            writePng(mWindowShot, readWindow(fbW, fbH));
            std::printf("gnomon view: wrote %s (window)\n", mWindowShot.c_str());
            mWindowShot.clear();
        }
        glfwSwapBuffers(mWindow.get());
        ++mFrames;
    }

    // Draws the camera's view and the side view when something changed.
    void renderViews(int mainW, int mainH, int sideW) {
        mMainOptions = view::mainViewOptions(mState, std::max(mainW, 1), std::max(mainH, 1));
        const bool sizeChanged =
            mMainOptions.width != mDrawnWidth || mMainOptions.height != mDrawnHeight;
        if (dirty() || sizeChanged || mRedraw) {
            mRedraw = false;
            mDrawnRevision = mState.revision;
            mDrawnWidth = mMainOptions.width;
            mDrawnHeight = mMainOptions.height;
            try {
                mRenderer.draw(mState.scene, mMainOptions);
                mFrameError.clear();
                mStats = mRenderer.lastFrameStats();
                recordPasses();
                mSideDirty = true;
            } catch (const Error& e) {
                mFrameError = e.what();
                if (mScripted) fail(std::string("frame: ") + e.what());
            }
        }
        if (mState.side == view::SideView::ShadowMap && sideW > 0 && mainH > 0 &&
            (mSideDirty || sideW != mSideW || mainH != mSideH ||
             mState.selectedLight != mSideLight)) {
            mSideDirty = false;
            mSideW = sideW;
            mSideH = mainH;
            mSideLight = mState.selectedLight;
            mSideTexture = mFrameError.empty()
                               ? mRenderer.drawShadowMapPanel(mState.selectedLight, sideW, mainH)
                               : 0;
        }
    }

    void recordPasses() {
        double shadow = 0.0, main = 0.0;
        for (const PassTiming& p : mStats.passes) {
            (p.light >= 0 ? shadow : main) += p.milliseconds;
        }
        mShadowMs.push_back(float(shadow));
        mMainMs.push_back(float(main));
        if (mShadowMs.size() > 120) {
            mShadowMs.erase(mShadowMs.begin());
            mMainMs.erase(mMainMs.begin());
        }
    }

    // ---- Controls ----

    void controls(float width, float height) {
        ImGui::SetNextWindowPos({0, 0});
        ImGui::SetNextWindowSize({width, height});
        ImGui::Begin(
            "Controls", nullptr,
            ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
        ImGui::PushItemWidth(width * 0.5f);
        sceneControls();
        cameraControls();
        lightControls();
        optionControls();
        ImGui::PopItemWidth();
        ImGui::End();
    }

    // The flag's one-line doc as the last item's tooltip, looked up only while hovered.
    void flagTip(const char* flag) {
        if (ImGui::IsItemHovered()) tooltip(mDocs(flag));
    }

    void changed(bool c) {
        if (c) ++mState.revision;
    }

    void guarded(const std::function<void()>& action) {
        try {
            action();
            mUiError.clear();
        } catch (const Error& e) {
            mUiError = e.what();
        }
    }

    void sceneControls() {
        if (mState.source != mShownSource) {  // loaded by a preset, a script or Load
            mShownSource = mSourceField = mState.source;
            mSavePath = mState.scene.name + "-tuned.json";
        }
        if (!ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) return;
        if (ImGui::BeginCombo("built-in", mState.source.c_str())) {
            for (const SceneInfo& s : builtinScenes()) {
                if (ImGui::Selectable(s.name.c_str(), s.name == mState.source)) {
                    guarded([&] { view::applyFlags(mState, {"--scene", s.name}); });
                }
                tooltip(s.description);
            }
            ImGui::EndCombo();
        }
        tooltip("a built-in scene; for a scene file or a model file, type its path below");
        inputText("file", mSourceField);
        ImGui::SameLine();
        if (ImGui::Button("Load"))
            guarded([&] { view::applyFlags(mState, {"--scene", mSourceField}); });
        bool ground = mState.ground;
        if (ImGui::Checkbox("ground", &ground)) {
            guarded([&] { view::load(mState, mState.source, ground); });
        }
        if (ImGui::IsItemHovered())
            tooltip(mDocs("--ground") + " (reloads the scene: its lights and camera restart)");
        if (ImGui::BeginCombo("preset", "choose...")) {
            std::string group;
            for (const view::PresetEntry& p : view::presets()) {
                if (p.group != group) {
                    group = p.group;
                    ImGui::TextDisabled("%s", group.c_str());
                }
                if (ImGui::Selectable(p.name.c_str()))
                    guarded([&] { view::applyPreset(mState, p); });
                std::string flags;
                for (const std::string& a : p.args)
                    flags += (flags.empty() ? "" : " ") + a;
                tooltip(flags);
            }
            ImGui::EndCombo();
        }
        tooltip(
            "Start from gnomon's defaults, the textbook's numbers for this scene, or one of "
            "docs/techniques.md's examples (which load their scene).");
        inputText("save as", mSavePath);
        ImGui::SameLine();
        if (ImGui::Button("Save")) guarded([&] { save(mSavePath); });
        tooltip(
            "Write a scene file (docs/scene-file.md) that `gnomon render --scene FILE` "
            "renders exactly as this view");
        if (ImGui::Button("Screenshot (F12)")) guarded([&] { screenshot(nextScreenshotPath()); });
        if (!mUiError.empty()) ImGui::TextColored({1, 0.4f, 0.4f, 1}, "%s", mUiError.c_str());
        if (!mLastWritten.empty()) ImGui::TextDisabled("wrote %s", mLastWritten.c_str());
    }

    void cameraControls() {
        if (!ImGui::CollapsingHeader("Camera")) return;
        Camera& c = mState.scene.camera;
        ImGui::TextDisabled("drag: orbit, shift+drag or middle: pan, wheel: zoom");
        changed(ImGui::DragFloat3("eye", &c.eye.x, 0.05f));
        changed(ImGui::DragFloat3("centre", &c.centre.x, 0.05f));
        int projection = c.projection == Projection::Perspective ? 0 : 1;
        if (ImGui::Combo("projection", &projection, "perspective\0orthographic\0")) {
            c.projection = projection == 0 ? Projection::Perspective : Projection::Orthographic;
            changed(true);
        }
        if (c.projection == Projection::Perspective) {
            changed(ImGui::SliderFloat("fovy", &c.fovyDegrees, 5.0f, 120.0f, "%.1f deg"));
        } else {
            changed(ImGui::DragFloat4("l r b t", &c.left, 0.05f));
        }
        changed(ImGui::DragFloat("near", &c.near, 0.01f, 0.001f, c.far * 0.999f, "%.3f"));
        changed(ImGui::DragFloat("far", &c.far, 0.5f, c.near * 1.001f, 1e6f, "%.1f"));
    }

    void lightControls() {
        if (!ImGui::CollapsingHeader("Lights", ImGuiTreeNodeFlags_DefaultOpen)) return;
        std::vector<Light>& lights = mState.scene.lights;
        if (lights.empty()) {
            ImGui::TextDisabled("this scene has no lights");
            return;
        }
        mState.selectedLight = std::clamp(mState.selectedLight, 0, int(lights.size()) - 1);
        auto labelOf = [&](int i) {
            const Light& l = lights[std::size_t(i)];
            return std::to_string(i) + ": " + (l.name.empty() ? toString(l.type) : l.name);
        };
        if (ImGui::BeginCombo("light", labelOf(mState.selectedLight).c_str())) {
            for (int i = 0; i < int(lights.size()); ++i) {
                if (ImGui::Selectable(labelOf(i).c_str(), i == mState.selectedLight))
                    mState.selectedLight = i;
            }
            ImGui::EndCombo();
        }
        tooltip("The light whose controls are below and whose shadow map the side view shows");
        Light& l = lights[std::size_t(mState.selectedLight)];
        ImGui::TextDisabled("right-drag in the view: move this light");
        changed(ImGui::Checkbox("on", &l.enabled));
        ImGui::SameLine();
        changed(ImGui::Checkbox("casts shadows", &l.castsShadows));
        int type = int(l.type);
        if (ImGui::Combo("type", &type, "directional\0spot\0point\0area\0")) {
            l.type = LightType(type);
            changed(true);
        }
        if (l.type != LightType::Directional)
            changed(ImGui::DragFloat3("position", &l.position.x, 0.05f));
        if (l.type != LightType::Point)
            changed(ImGui::DragFloat3("direction", &l.direction.x, 0.01f));
        changed(ImGui::ColorEdit3("colour", &l.colour.x));
        changed(ImGui::DragFloat("intensity", &l.intensity, 0.01f, 0.0f, 1e6f));
        if (l.type != LightType::Directional) {
            changed(ImGui::DragFloat3("attenuation", &l.attenuation.constant, 0.001f, 0.0f, 100.0f,
                                      "%.4f"));
            tooltip("1 / (constant + linear d + quadratic d^2)");
            changed(ImGui::DragFloat("range", &l.range, 0.1f, 0.0f, 1e6f));
            tooltip("point and spot lights end here (0: unlimited)");
        }
        if (l.type == LightType::Spot) {
            changed(ImGui::SliderFloat("inner cone", &l.innerConeDegrees, 0.0f, l.outerConeDegrees,
                                       "%.1f deg"));
            changed(ImGui::SliderFloat("outer cone", &l.outerConeDegrees, l.innerConeDegrees, 89.0f,
                                       "%.1f deg"));
        }
        int mapSizeLog = int(std::lround(std::log2(std::max(l.shadowMapSize, 64))));
        if (ImGui::SliderInt("map size", &mapSizeLog, 6, 13, "")) {
            l.shadowMapSize = 1 << mapSizeLog;
            changed(true);
        }
        ImGui::SameLine();
        ImGui::Text("%d", l.shadowMapSize);
        tooltip("this light's shadow map, texels per side (--map-size overrides every light)");
        ShadowCamera& sc = l.shadowCamera;
        int policy = int(sc.policy);
        if (ImGui::Combo("light camera", &policy, "fit\0manual\0course\0")) {
            sc.policy = ShadowCameraPolicy(policy);
            changed(true);
        }
        if (ImGui::IsItemHovered())
            tooltip(std::string("how the shadow camera is placed: ") + toString(sc.policy) +
                    ". fit: around what can be shadowed; manual: the numbers below; course: "
                    "looking at the view's centre");
        if (sc.policy != ShadowCameraPolicy::Fit) {
            int proj = sc.projection == Projection::Perspective ? 0 : 1;
            if (ImGui::Combo("light projection", &proj, "perspective\0orthographic\0")) {
                sc.projection = proj == 0 ? Projection::Perspective : Projection::Orthographic;
                changed(true);
            }
            if (sc.policy == ShadowCameraPolicy::Manual)
                changed(ImGui::DragFloat3("target", &sc.target.x, 0.05f));
            if (sc.projection == Projection::Perspective) {
                changed(ImGui::SliderFloat("light fovy", &sc.fovyDegrees, 1.0f, 170.0f));
            } else {
                changed(ImGui::DragFloat4("light l r b t", &sc.left, 0.05f));
            }
            changed(ImGui::DragFloat("light near", &sc.near, 0.01f, 0.001f, sc.far * 0.999f));
            changed(ImGui::DragFloat("light far", &sc.far, 0.1f, sc.near * 1.001f, 1e6f));
        }
    }

    void optionControls() {
        RenderOptions& o = mState.options;
        ShadowOptions& s = o.shadow;
        if (ImGui::CollapsingHeader("Shadow map", ImGuiTreeNodeFlags_DefaultOpen)) {
            changed(ImGui::Checkbox("shadows", &s.enabled));
            flagTip("--shadows");
            bool override = s.mapSize > 0;
            if (ImGui::Checkbox("##override", &override)) {
                s.mapSize = override ? 1024 : 0;
                changed(true);
            }
            tooltip("override every light's map size");
            ImGui::SameLine();
            if (override) {
                int log = int(std::lround(std::log2(std::max(s.mapSize, 64))));
                if (ImGui::SliderInt("map-size", &log, 6, 13, "")) {
                    s.mapSize = 1 << log;
                    changed(true);
                }
                ImGui::SameLine();
                ImGui::Text("%d", s.mapSize);
            } else {
                ImGui::TextDisabled("map-size: each light's own");
            }
            flagTip("--map-size");
            changed(enumCombo(
                "depth-format", s.depthFormat,
                {DepthFormat::R8, DepthFormat::Rgba8Packed256, DepthFormat::Rgba8Packed255,
                 DepthFormat::Depth16, DepthFormat::Depth24, DepthFormat::Depth32F}));
            flagTip("--depth-format");
            changed(enumCombo("map-filter", s.mapFilter, {MapFilter::Nearest, MapFilter::Linear}));
            flagTip("--map-filter");
            changed(enumCombo("outside", s.outside, {OutsidePolicy::Lit, OutsidePolicy::Clamp}));
            flagTip("--outside");
        }
        if (ImGui::CollapsingHeader("Tolerances", ImGuiTreeNodeFlags_DefaultOpen)) {
            changed(
                ImGui::DragFloat("bias-constant", &s.biasConstant, 0.0001f, 0.0f, 0.5f, "%.5f"));
            flagTip("--bias-constant");
            changed(ImGui::DragFloat("bias-depth-aware", &s.biasDepthAware, 0.05f, 0.0f, 100.0f));
            flagTip("--bias-depth-aware");
            changed(ImGui::DragFloat("bias-slope", &s.biasSlope, 0.05f, 0.0f, 100.0f));
            flagTip("--bias-slope");
            changed(ImGui::DragFloat("bias-units", &s.biasUnits, 0.1f, 0.0f, 10000.0f));
            flagTip("--bias-units");
            changed(ImGui::Checkbox("receiver-plane", &s.receiverPlane));
            flagTip("--receiver-plane");
            changed(ImGui::DragFloat("normal-offset", &s.normalOffset, 0.05f, 0.0f, 100.0f));
            flagTip("--normal-offset");
            changed(enumCombo("cull", s.cull, {CullMode::Back, CullMode::Front, CullMode::None}));
            flagTip("--cull");
        }
        if (ImGui::CollapsingHeader("Filter", ImGuiTreeNodeFlags_DefaultOpen)) {
            changed(enumCombo("filter", s.filter,
                              {ShadowFilter::None, ShadowFilter::Hw2x2, ShadowFilter::Pcf,
                               ShadowFilter::Poisson, ShadowFilter::Pcss}));
            flagTip("--filter");
            int half = (s.pcfSize - 1) / 2;
            if (ImGui::SliderInt("pcf-size", &half, 0, 4, std::to_string(2 * half + 1).c_str())) {
                s.pcfSize = 2 * half + 1;
                changed(true);
            }
            flagTip("--pcf-size");
            changed(ImGui::DragFloat("light-radius", &s.lightRadius, 0.01f, 0.0f, 100.0f));
            flagTip("--light-radius");
            changed(ImGui::SliderFloat("light-angle", &s.lightAngle, 0.0f, 20.0f, "%.2f deg"));
            flagTip("--light-angle");
            changed(enumCombo("blend-shadows", s.blendShadows,
                              {BlendShadows::Opaque, BlendShadows::None, BlendShadows::Dithered}));
            flagTip("--blend-shadows");
        }
        if (ImGui::CollapsingHeader("Cascades")) {
            changed(
                ImGui::SliderInt("cascades", &s.cascades, 0, 4, s.cascades == 0 ? "auto" : "%d"));
            flagTip("--cascades");
            changed(enumCombo("fit-to", s.fitTo, {FitTo::ViewDepth, FitTo::Boxes}));
            flagTip("--fit-to");
            changed(ImGui::SliderFloat("cascade-lambda", &s.cascadeLambda, 0.0f, 1.0f));
            flagTip("--cascade-lambda");
            changed(ImGui::SliderFloat("cascade-blend", &s.cascadeBlend, 0.0f, 0.5f));
            flagTip("--cascade-blend");
        }
        if (ImGui::CollapsingHeader("Shading")) {
            changed(enumCombo("shadowed", o.shading.shadowedRule,
                              {ShadowedRule::AmbientOnly, ShadowedRule::Factor}));
            flagTip("--shadowed");
            changed(ImGui::SliderFloat("shadow-factor", &o.shading.shadowFactor, 0.0f, 1.0f));
            flagTip("--shadow-factor");
            changed(enumCombo("output-encoding", o.shading.output,
                              {OutputEncoding::Linear, OutputEncoding::Srgb}));
            flagTip("--output-encoding");
            changed(ImGui::ColorEdit3("ambient", &mState.scene.ambient.x));
            tooltip("the scene's ambient light colour, times each material's colour");
            ImGui::TextDisabled("shininess: per material, from the scene");
        }
        if (ImGui::CollapsingHeader("Animation and view", ImGuiTreeNodeFlags_DefaultOpen)) {
            if (ImGui::Button(mState.playing ? "Pause (space)" : "Play (space)"))
                mState.playing = !mState.playing;
            ImGui::SameLine();
            ImGui::SetNextItemWidth(100);
            float speed = float(mState.speed);
            if (ImGui::DragFloat("speed", &speed, 0.05f, -10.0f, 10.0f)) mState.speed = speed;
            tooltip("animation seconds per second");
            float time = float(o.time);
            if (ImGui::DragFloat("time", &time, 0.05f, 0.0f, 1e6f, "%.2f s")) {
                o.time = time;
                changed(true);
            }
            flagTip("--time");
            int lightOnly = o.lightOnly;
            if (ImGui::SliderInt("light-only", &lightOnly, -1, int(mState.scene.lights.size()) - 1,
                                 lightOnly < 0 ? "all" : "%d")) {
                o.lightOnly = lightOnly;
                changed(true);
            }
            flagTip("--light-only");
            changed(enumCombo("debug-view", o.debugView,
                              {DebugView::None, DebugView::Cascades, DebugView::ShadowMap,
                               DebugView::LightFrusta}));
            flagTip("--debug-view");
            changed(ImGui::Checkbox("light frusta (F)", &mState.frusta));
            tooltip("draw every shadow camera's volume as lines over the camera's view");
            bool side = mState.side == view::SideView::ShadowMap;
            if (ImGui::Checkbox("side view: shadow map", &side))
                mState.side = side ? view::SideView::ShadowMap : view::SideView::None;
            if (ImGui::Checkbox("fit view to window", &mState.fitView)) changed(true);
            if (!mState.fitView) {
                int size[2] = {o.width, o.height};
                if (ImGui::DragInt2("size", size, 1.0f, 16, 4096)) {
                    o.width = std::clamp(size[0], 1, 16384);
                    o.height = std::clamp(size[1], 1, 16384);
                    changed(true);
                }
                flagTip("--size");
            }
            if (ImGui::Checkbox("measure passes", &mMeasure)) mRenderer.setPassTiming(mMeasure);
            tooltip("time each pass as gnomon bench does (a glFinish between passes)");
        }
    }

    static void inputText(const char* label, std::string& value) {
        char buffer[1024];
        std::snprintf(buffer, sizeof buffer, "%s", value.c_str());
        if (ImGui::InputText(label, buffer, sizeof buffer)) value = buffer;
    }

    // ---- Views ----

    void views(float x, float mainW, float viewW, float viewH) {
        ImGui::SetNextWindowPos({x, 0});
        ImGui::SetNextWindowSize({viewW, viewH});
        ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {0, 0});
        ImGui::Begin("Views", nullptr,
                     ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                         ImGuiWindowFlags_NoBringToFrontOnFocus);
        ImGui::PopStyleVar();
        const ImGuiIO& io = ImGui::GetIO();
        const ImVec2 origin = ImGui::GetCursorScreenPos();
        if (!mFrameError.empty()) {
            ImGui::PushTextWrapPos(origin.x + mainW - 10);
            ImGui::TextColored({1, 0.4f, 0.4f, 1}, "%s", mFrameError.c_str());
            ImGui::PopTextWrapPos();
        } else if (mRenderer.frameTexture() != 0) {
            const ImVec2 size(float(mDrawnWidth) / io.DisplayFramebufferScale.x,
                              float(mDrawnHeight) / io.DisplayFramebufferScale.y);
            ImGui::Image(imguiTexture(mRenderer.frameTexture()), size, {0, 1}, {1, 0});
            const bool hovered = ImGui::IsItemHovered();
            if (mOverlay && mOverlayTexture.id() != 0) {
                ImGui::GetWindowDrawList()->AddImage(
                    imguiTexture(mOverlayTexture.id()), origin,
                    {origin.x + size.x, origin.y + size.y}, {0, 0}, {1, 1},
                    IM_COL32(255, 255, 255, int(255 * mOverlayOpacity)));
            }
            mouseOnView(hovered, size.y);
        }
        if (mState.side == view::SideView::ShadowMap) {
            ImGui::SetCursorScreenPos({origin.x + mainW, origin.y});
            if (mSideTexture != 0) {
                ImGui::Image(imguiTexture(mSideTexture),
                             {float(mSideW) / io.DisplayFramebufferScale.x,
                              float(mSideH) / io.DisplayFramebufferScale.y},
                             {0, 1}, {1, 0});
            } else {
                ImGui::TextDisabled(
                    "light %d has no shadow map in this frame\n(off, not "
                    "casting, or nothing in view to shadow)",
                    mState.selectedLight);
            }
            ImGui::SetCursorScreenPos({origin.x + mainW + 6, origin.y + 4});
            ImGui::TextColored({1, 1, 0.6f, 1}, "light %d: shadow map (darker = nearer)",
                               mState.selectedLight);
        }
        ImGui::End();
    }

    void mouseOnView(bool hovered, float viewHeight) {
        const ImGuiIO& io = ImGui::GetIO();
        for (int b = 0; b < 3; ++b) {
            if (hovered && ImGui::IsMouseClicked(b)) mDragButton = b;
        }
        if (mDragButton >= 0 && !ImGui::IsMouseDown(mDragButton)) mDragButton = -1;
        const ImVec2 d = io.MouseDelta;
        if (mDragButton >= 0 && (d.x != 0.0f || d.y != 0.0f)) {
            Camera& cam = mState.scene.camera;
            if (mDragButton == 2 || (mDragButton == 0 && io.KeyShift)) {
                view::pan(cam, d.x / viewHeight, d.y / viewHeight);
            } else if (mDragButton == 0) {
                view::orbit(cam, d.x * 0.4f, d.y * 0.4f);
            } else if (!mState.scene.lights.empty()) {
                const glm::vec3 right = glm::cross(cam.centre - cam.eye, cam.up);
                view::orbitLight(mState.scene.lights[std::size_t(mState.selectedLight)], cam.centre,
                                 right, d.x * 0.4f, d.y * 0.4f);
            }
            ++mState.revision;
        }
        if (hovered && io.MouseWheel != 0.0f) {
            view::zoom(mState.scene.camera, std::pow(0.9f, io.MouseWheel));
            ++mState.revision;
        }
    }

    // ---- Measurements ----

    void measurePanel(float x, float y, float width, float height) {
        ImGui::SetNextWindowPos({x, y});
        ImGui::SetNextWindowSize({width, height});
        ImGui::Begin(
            "Measure", nullptr,
            ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
        ImGui::Columns(2, nullptr, true);
        const ImGuiIO& io = ImGui::GetIO();
        ImGui::Text("%.1f fps   %dx%d   %d map(s), %d rendered, %.1f MiB", io.Framerate,
                    mDrawnWidth, mDrawnHeight, mStats.shadowMaps, mStats.shadowPasses,
                    double(mStats.shadowMapBytes) / (1024.0 * 1024.0));
        if (mMeasure) {
            for (const PassTiming& p : mStats.passes)
                ImGui::Text("%-28s %7.2f ms", p.name.c_str(), p.milliseconds);
            if (!mMainMs.empty()) {
                ImGui::PlotLines("main ms", mMainMs.data(), int(mMainMs.size()), 0, nullptr, 0.0f,
                                 FLT_MAX, {0, 34});
                ImGui::PlotLines("shadow ms", mShadowMs.data(), int(mShadowMs.size()), 0, nullptr,
                                 0.0f, FLT_MAX, {0, 34});
            }
        } else {
            ImGui::TextDisabled("pass timing off (Animation and view > measure passes)");
        }
        ImGui::NextColumn();
        scorePanel();
        ImGui::Columns(1);
        ImGui::End();
    }

    void scorePanel() {
        if (mJob) {
            const int rows = std::max(1, mJob->progress.rows.load());
            ImGui::ProgressBar(float(mJob->progress.rowsDone.load()) / float(rows), {-1, 0},
                               "tracing the reference...");
            if (ImGui::Button("Cancel")) mJob.reset();
            return;
        }
        if (ImGui::Button("Score vs ray-traced truth (F5)")) guarded([&] { startScore(); });
        tooltip(
            "gnomon score's engine: each pixel's shadow against an Embree reference of this "
            "frame (runs in the background)");
        if (!mScoreError.empty()) ImGui::TextColored({1, 0.4f, 0.4f, 1}, "%s", mScoreError.c_str());
        if (!mScore) return;
        const ShadowScore& o = mScore->overall;
        if (mScoredRevision != mState.revision)
            ImGui::TextColored({1, 0.8f, 0.3f, 1}, "(settings changed since this score)");
        ImGui::Text("misclassified %.2f%%   mean |error| %.3f   (traced in %.2f s)",
                    100.0 * o.misclassified, o.meanAbsError, mScore->traceSeconds);
        ImGui::Text("false shadow %.2f%%   leak %.2f%%", 100.0 * o.falseShadow, 100.0 * o.leak);
        ImGui::Text("away from edges: false shadow %.2f%%, leak %.2f%%",
                    100.0 * o.falseShadowOutsideBand, 100.0 * o.leakOutsideBand);
        ImGui::Checkbox("error overlay", &mOverlay);
        tooltip("red: false shadow (acne), blue: light leak; pale inside the aliasing band");
        ImGui::SameLine();
        ImGui::SetNextItemWidth(120);
        ImGui::SliderFloat("opacity", &mOverlayOpacity, 0.0f, 1.0f);
    }

    void startScore() {
        RenderOptions options = mMainOptions;
        options.debugView = DebugView::None;  // frusta are lines over the same shadows
        mScoreError.clear();
        ScoreFrame frame = renderForScore(mRenderer, mState.scene, options);
        mRedraw = true;  // the renderer's last frame is now the scored one
        auto job = std::make_unique<ScoreJob>();
        job->revision = mState.revision;
        ScoreJob* raw = job.get();
        auto scene = std::make_shared<Scene>(mState.scene);
        job->thread = std::thread([raw, scene, options, frame = std::move(frame)]() mutable {
            try {
                raw->result = scoreFrame(std::move(frame), *scene, options, {}, &raw->progress);
            } catch (const std::exception& e) {
                raw->error = e.what();
            }
            raw->done = true;
        });
        mJob = std::move(job);
    }

    void pollScore() {
        if (!mJob || !mJob->done) return;
        mJob->thread.join();
        if (mJob->result) {
            mScore = std::move(mJob->result);
            mScoredRevision = mJob->revision;
            mOverlayTexture = ImageTexture(mScore->errors);
            mOverlay = true;
            std::printf(
                "gnomon view: score: misclassified %.4f, false shadow %.4f, leak %.4f "
                "(%.2f s)\n",
                mScore->overall.misclassified, mScore->overall.falseShadow, mScore->overall.leak,
                mScore->traceSeconds);
        } else {
            mScoreError = mJob->error;
            if (mScripted) fail("score: " + mJob->error);
        }
        mJob.reset();
    }

    // ---- Files ----

    std::string nextScreenshotPath() {
        const std::string base = mArgs.screenshotDir + "/gnomon-view-" + mState.scene.name + "-";
        for (int n = 1;; ++n) {
            char name[16];
            std::snprintf(name, sizeof name, "%03d.png", n);
            std::FILE* f = std::fopen((base + name).c_str(), "rb");
            if (!f) return base + name;
            std::fclose(f);
        }
    }

    // The PNG gnomon render writes for these settings: the same renderer, read back.
    void screenshot(const std::string& path) {
        writePng(path, mRenderer.render(mState.scene, mMainOptions));
        mRedraw = true;
        mLastWritten = path;
        std::printf("gnomon view: wrote %s (%dx%d)\n", path.c_str(), mMainOptions.width,
                    mMainOptions.height);
    }

    void save(const std::string& path) {
        saveSceneFile(path, mState.source, mState.scene, mMainOptions, mState.ground);
        mLastWritten = path;
        std::printf("gnomon view: wrote %s\n", path.c_str());
    }

    void handleKeys() {
        const ImGuiIO& io = ImGui::GetIO();
        if (io.WantCaptureKeyboard) return;
        if (ImGui::IsKeyPressed(GLFW_KEY_F12, false)) key("F12");
        if (ImGui::IsKeyPressed(GLFW_KEY_F5, false)) key("F5");
        if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) key("F");
        if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) key("space");
    }

    // Keys and scripted `key` commands go through here alike.
    void key(const std::string& name) {
        if (name == "F12") {
            guarded([&] { screenshot(nextScreenshotPath()); });
        } else if (name == "F5") {
            if (!mJob) guarded([&] { startScore(); });
        } else if (name == "F") {
            mState.frusta = !mState.frusta;
            ++mState.revision;
        } else if (name == "space") {
            mState.playing = !mState.playing;
        } else {
            throw Error(ErrorKind::InvalidInput,
                        "key '" + name +
                            "': known keys are F12 (screenshot), F5 (score), F "
                            "(frusta), space (play/pause)");
        }
    }

    // ---- Script ----

    void fail(const std::string& message) {
        std::fprintf(stderr, "gnomon: error: %s: %s\n", mArgs.script.c_str(), message.c_str());
        mExitCode = 1;
    }

    void runScript() {
        if (!mScripted) return;
        if (mWaitFrames > 0) {
            --mWaitFrames;
            if (mWaitFrames > 0) return;
        }
        if (mWaitScore) {
            if (mJob) return;
            mWaitScore = false;
        }
        if (mRepeatLeft > 0) {  // one repetition per frame
            --mRepeatLeft;
            try {
                runCommand(mRepeated);
            } catch (const Error& e) {
                std::fprintf(stderr, "gnomon: error: %s:%d: %s\n", mArgs.script.c_str(),
                             mRepeated.line, e.what());
                mExitCode = e.kind() == ErrorKind::InvalidInput ? 2 : 1;
            }
            return;
        }
        while (mNext < mScript.size() && mWaitFrames == 0 && mRepeatLeft == 0 && !mWaitScore &&
               !mQuit) {
            const view::Command& c = mScript[mNext++];
            try {
                runCommand(c);
            } catch (const Error& e) {
                std::fprintf(stderr, "gnomon: error: %s:%d: %s\n", mArgs.script.c_str(), c.line,
                             e.what());
                mExitCode = e.kind() == ErrorKind::InvalidInput ? 2 : 1;
                return;
            }
            if (mExitCode != 0) return;
        }
        if (mNext >= mScript.size() && mWaitFrames == 0 && mRepeatLeft == 0 && !mWaitScore)
            mScripted = false;
    }

    void runCommand(const view::Command& c) {
        if (view::applyCommand(mState, c)) return;
        const std::string arg = c.args.empty() ? "" : c.args[0];
        if (c.verb == "wait") {
            if (!std::regex_match(arg, std::regex(R"(\d{1,6})"))) {
                throw Error(ErrorKind::InvalidInput,
                            "wait: expected a frame count, got '" + arg + "'");
            }
            mWaitFrames = std::stoi(arg);
        } else if (c.verb == "screenshot") {
            // The frame as it stands after this command: settle the view first.
            settleOptions();
            screenshot(arg);
        } else if (c.verb == "window-shot") {
            mWindowShot = arg;  // at the end of this frame, with the UI drawn
            mWaitFrames = 1;    // what follows runs on the next frame
        } else if (c.verb == "save") {
            settleOptions();
            save(arg);
        } else if (c.verb == "load") {
            view::applyFlags(mState, {"--scene", arg});
        } else if (c.verb == "score") {
            settleOptions();
            mJob.reset();
            startScore();
        } else if (c.verb == "wait-score") {
            mWaitScore = true;
        } else if (c.verb == "expect-score") {
            expectScore(c);
        } else if (c.verb == "key") {
            key(arg);
        } else if (c.verb == "repeat") {
            mRepeated = view::repeatedCommand(c);
            mRepeatLeft = std::stoi(c.args[0]);
        } else if (c.verb == "measure") {
            if (arg != "on" && arg != "off") {
                throw Error(ErrorKind::InvalidInput,
                            "measure: expected on or off, got '" + arg + "'");
            }
            mMeasure = arg == "on";
            mRenderer.setPassTiming(mMeasure);
        } else if (c.verb == "stats") {
            printStats();
        } else if (c.verb == "quit") {
            mQuit = true;
        }
    }

    // The main view's options after this frame's commands so far, at the last frame's size:
    // what a scripted screenshot, save or score uses.
    void settleOptions() {
        mMainOptions =
            view::mainViewOptions(mState, std::max(mDrawnWidth, 1), std::max(mDrawnHeight, 1));
    }

    void expectScore(const view::Command& c) {
        if (!mScore)
            throw Error(ErrorKind::InvalidInput,
                        "expect-score: no score yet (run score, wait-score)");
        const ShadowScore& o = mScore->overall;
        const std::map<std::string, double> metrics = {
            {"misclassified", o.misclassified},
            {"false-shadow", o.falseShadow},
            {"leak", o.leak},
            {"false-shadow-outside-band", o.falseShadowOutsideBand},
            {"leak-outside-band", o.leakOutsideBand},
            {"mean-abs-error", o.meanAbsError}};
        const auto it = metrics.find(c.args[0]);
        if (it == metrics.end()) {
            throw Error(ErrorKind::InvalidInput,
                        "expect-score: unknown metric '" + c.args[0] +
                            "' (misclassified, false-shadow, leak, false-shadow-outside-band, "
                            "leak-outside-band, mean-abs-error)");
        }
        if (c.args[1] != "<" && c.args[1] != ">") {
            throw Error(ErrorKind::InvalidInput, "expect-score: operator must be < or >");
        }
        char* end = nullptr;
        const double bound = std::strtod(c.args[2].c_str(), &end);
        if (end == c.args[2].c_str() || *end != '\0') {
            throw Error(ErrorKind::InvalidInput,
                        "expect-score: expected a number, got '" + c.args[2] + "'");
        }
        const bool ok = c.args[1] == "<" ? it->second < bound : it->second > bound;
        std::printf("gnomon view: expect %s %s %s: %.4f %s\n", c.args[0].c_str(), c.args[1].c_str(),
                    c.args[2].c_str(), it->second, ok ? "ok" : "FAILED");
        if (!ok) {
            fail("line " + std::to_string(c.line) + ": expected " + c.args[0] + " " + c.args[1] +
                 " " + c.args[2] + ", measured " + std::to_string(it->second));
        }
    }

    void printStats() {
        std::vector<double> sorted = mFrameMs;
        std::sort(sorted.begin(), sorted.end());
        const double median = sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
        std::printf(
            "gnomon view: %s %dx%d in a %dx%d window: %zu frames, median frame %.1f ms "
            "(%.1f fps)\n",
            mState.scene.name.c_str(), mDrawnWidth, mDrawnHeight, int(ImGui::GetIO().DisplaySize.x),
            int(ImGui::GetIO().DisplaySize.y), sorted.size(), median,
            median > 0.0 ? 1000.0 / median : 0.0);
        mFrameMs.clear();
    }

    const ViewArgs& mArgs;
    bool mVerbose;
    GlfwWindow mWindow;
    ImGuiSession mImGui;
    Renderer mRenderer;
    view::State mState;
    FlagDocs mDocs;

    RenderOptions mMainOptions;
    std::uint64_t mDrawnRevision = ~std::uint64_t(0);
    int mDrawnWidth = 0, mDrawnHeight = 0;
    bool mRedraw = false;
    std::string mFrameError, mUiError, mLastWritten, mSavePath, mSourceField, mShownSource;
    FrameStats mStats;
    std::vector<float> mShadowMs, mMainMs;
    std::vector<double> mFrameMs;
    bool mMeasure = true;

    GLuint mSideTexture = 0;
    int mSideW = 0, mSideH = 0, mSideLight = -1;
    bool mSideDirty = true;
    int mDragButton = -1;

    std::unique_ptr<ScoreJob> mJob;
    std::optional<ScoreResult> mScore;
    std::uint64_t mScoredRevision = 0;
    std::string mScoreError;
    ImageTexture mOverlayTexture;
    bool mOverlay = false;
    float mOverlayOpacity = 0.6f;

    std::vector<view::Command> mScript;
    std::size_t mNext = 0;
    bool mScripted = false, mWaitScore = false, mQuit = false;
    int mWaitFrames = 0;
    int mRepeatLeft = 0;
    view::Command mRepeated;
    std::string mWindowShot;
    long mFrames = 0;
    int mExitCode = 0;
};

}  // namespace

CLI::App* addViewCommand(CLI::App& app, ViewArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "view",
        "open the interactive viewer: the camera's view beside a light's shadow map, "
        "every option on a control (GLFW window; docs/viewer.md)");
    cmd->add_option("--scene", args.scene,
                    "built-in scene name, scene file (.json), glTF or other model file "
                    "(default tutorial-room)");
    cmd->add_option("--script", args.script,
                    "run the commands in FILE, one per frame (`wait N` lets N frames pass): "
                    "screenshots, settings, scores, quit (docs/viewer.md)");
    cmd->add_option("--window", args.window, "window size WIDTHxHEIGHT (default 1280x720)");
    cmd->add_option("--screenshot-dir", args.screenshotDir,
                    "folder where F12 writes gnomon-view-SCENE-NNN.png (default .)");
    args.flags.add(*cmd);
    return cmd;
}

int runView(const ViewArgs& args, bool verbose) {
    static const std::regex kSize(R"((\d{2,5})x(\d{2,5}))");
    std::smatch m;
    if (!std::regex_match(args.window, m, kSize)) {
        throw Error(ErrorKind::InvalidInput,
                    "--window: expected WIDTHxHEIGHT such as 1280x720, got '" + args.window + "'");
    }
    const int width = std::stoi(m[1].str()), height = std::stoi(m[2].str());
    if (width < 320 || height < 240 || width > 16384 || height > 16384) {
        throw Error(ErrorKind::InvalidInput,
                    "--window: " + args.window + " is outside 320x240..16384x16384");
    }
    // Bad input is reported before a window opens.
    std::vector<view::Command> script;
    if (!args.script.empty()) {
        std::ifstream in(args.script, std::ios::binary);
        if (!in) throw Error(ErrorKind::Io, "--script: cannot read '" + args.script + "'");
        std::stringstream text;
        text << in.rdbuf();
        script = view::parseScript(text.str(), args.script);
    }
    view::State state;
    view::load(state, args.scene, args.flags.ground);
    printWarnings(state.scene);
    state.options = args.flags.resolve(state.scene);
    if (args.flags.app->count("--size") > 0) state.fitView = false;
    Viewer viewer(args, verbose, width, height, std::move(state), std::move(script));
    return viewer.run();
}

}  // namespace gnomon::cli
