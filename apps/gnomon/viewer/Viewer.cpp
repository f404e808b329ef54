// `gnomon view`'s entry point and app loop: the window's frames, what each frame draws, and
// the keyboard and mouse on the view. The panels, the score job and the script are elsewhere.
#include "Viewer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "ViewerApp.h"

namespace gnomon::cli::viewer {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

Viewer::Viewer(const ViewArgs& args, bool verbose, int windowWidth, int windowHeight,
               view::State state, std::vector<view::Command> script)
    : mArgs(args),
      mVerbose(verbose),
      mWindow(gl::WindowSettings{
          .title = "gnomon view", .width = windowWidth, .height = windowHeight, .vsync = true}),
      mImGui(mWindow.handle()),
      mRenderer(contextOptions(verbose)),
      mState(std::move(state)),
      mScript(std::move(script)),
      mScripted(!args.script.empty()) {
    mRenderer.setPassTiming(mMeasure);
    // The view moves frame to frame: stabilised maps hold still while they cover it.
    mRenderer.setFollowing(true);
    if (mVerbose) std::fprintf(stderr, "gnomon view: OpenGL %s\n", mRenderer.glInfo().c_str());
}

int Viewer::run() {
    while (step()) {
    }
    return mExitCode;
}

bool Viewer::step() {
    if (mWindow.shouldClose() || mQuit || mExitCode != 0) return false;
    const bool idle = !mScripted && !mState.playing && !mJob && !mTuneJob && !dirty();
    if (idle) {
        mWindow.waitEvents(0.25);
    } else {
        mWindow.pollEvents();
    }
    const auto now = Clock::now();
    const double dt = mLastStep == Clock::time_point{}
                          ? 0.0
                          : std::chrono::duration<double>(now - mLastStep).count();
    mLastStep = now;
    if (mState.playing) {
        mState.options.time += dt * mState.speed;
        ++mState.revision;
    }
    frame();
    if (mExitCode != 0) return false;
    mFrameMs.push_back(std::chrono::duration<double, std::milli>(Clock::now() - now).count());
    if (mFrameMs.size() > 600) mFrameMs.erase(mFrameMs.begin());
    return true;
}

void Viewer::replaceState(view::State state) {
    const std::uint64_t revision = mState.revision, viewRevision = mState.viewRevision;
    mJob.reset();
    mTuneJob.reset();
    mScore.reset();
    mTune.reset();
    mOverlayTexture = gl::Texture{};
    mOverlay = false;
    mState = std::move(state);
    mState.revision = revision + 1;
    mState.viewRevision = viewRevision + 1;
}

ContextOptions Viewer::contextOptions(bool verbose) {
    ContextOptions o;
    o.verbose = verbose;
    o.currentContext = true;
    return o;
}

bool Viewer::dirty() const {
    return mState.revision != mDrawnRevision || mState.viewRevision != mDrawnViewRevision;
}

void Viewer::frame() {
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
    pollTune();
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
    mWindow.clear(0.08f, 0.08f, 0.09f);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (!mWindowShot.empty()) {
        writePng(mWindowShot, mWindow.readBack());
        std::printf("gnomon view: wrote %s (window)\n", mWindowShot.c_str());
        mWindowShot.clear();
    }
    mWindow.swapBuffers();
    ++mFrames;
}

// Draws the camera's view and the side view when something changed.
void Viewer::renderViews(int mainW, int mainH, int sideW) {
    mMainOptions = view::mainViewOptions(mState, std::max(mainW, 1), std::max(mainH, 1));
    const bool sizeChanged =
        mMainOptions.width != mDrawnWidth || mMainOptions.height != mDrawnHeight;
    if (dirty() || sizeChanged || mRedraw) {
        mRedraw = false;
        mDrawnRevision = mState.revision;
        mDrawnViewRevision = mState.viewRevision;
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
    dropStaleOverlay();
    if (mState.side == view::SideView::ShadowMap && sideW > 0 && mainH > 0 &&
        (mSideDirty || sideW != mSideW || mainH != mSideH || mState.selectedLight != mSideLight)) {
        mSideDirty = false;
        mSideW = sideW;
        mSideH = mainH;
        mSideLight = mState.selectedLight;
        mSideTexture = mFrameError.empty()
                           ? mRenderer.drawShadowMapPanel(mState.selectedLight, sideW, mainH)
                           : GlTexture{};
    }
}

// The error map belongs to the frame it scored: over a moved camera, another setting or
// another size it would paint a double exposure, so it goes as soon as the frame moves on
// (view-only toggles keep it). Scoring again (F5) brings a fresh one.
void Viewer::dropStaleOverlay() {
    if (!mOverlayTexture || !mScore) return;
    if (mScoredRevision != mState.revision || mScore->errors.width != mDrawnWidth ||
        mScore->errors.height != mDrawnHeight) {
        mOverlayTexture = gl::Texture{};
        mOverlay = false;
    }
}

void Viewer::recordPasses() {
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

// Left drag orbits the camera (with shift: pans), middle drag pans, right drag moves the
// selected light; a left drag that starts on a light's icon selects that light and moves it.
void Viewer::mouseOnView(bool hovered, float viewHeight, int iconUnderMouse) {
    const ImGuiIO& io = ImGui::GetIO();
    for (int b = 0; b < 3; ++b) {
        if (hovered && ImGui::IsMouseClicked(b)) {
            mDragButton = b;
            mDragIcon = b == 0 && iconUnderMouse >= 0;
            if (mDragIcon) mState.selectedLight = iconUnderMouse;
        }
    }
    if (mDragButton >= 0 && !ImGui::IsMouseDown(mDragButton)) mDragButton = -1;
    const ImVec2 d = io.MouseDelta;
    if (mDragButton >= 0 && (d.x != 0.0f || d.y != 0.0f)) {
        Camera& cam = mState.scene.camera;
        if (mDragButton == 2 || (mDragButton == 0 && io.KeyShift && !mDragIcon)) {
            view::pan(cam, d.x / viewHeight, d.y / viewHeight);
        } else if (mDragButton == 0 && !mDragIcon) {
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

void Viewer::handleKeys() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureKeyboard) return;
    if (ImGui::IsKeyPressed(GLFW_KEY_F12, false)) key("F12");
    if (ImGui::IsKeyPressed(GLFW_KEY_F5, false)) key("F5");
    if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) key("F");
    if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) key("space");
}

// Keys and scripted `key` commands go through here alike.
void Viewer::key(const std::string& name) {
    if (name == "F12") {
        guarded([&] { screenshot(nextScreenshotPath()); });
    } else if (name == "F5") {
        if (!mJob) guarded([&] { startScore(); });
    } else if (name == "F") {
        mState.frusta = !mState.frusta;
        ++mState.viewRevision;
    } else if (name == "space") {
        mState.playing = !mState.playing;
    } else {
        throw Error(ErrorKind::InvalidInput,
                    "key '" + name +
                        "': known keys are F12 (screenshot), F5 (score), F "
                        "(frusta), space (play/pause)");
    }
}

}  // namespace gnomon::cli::viewer

namespace gnomon::cli {

CLI::App* addViewCommand(CLI::App& app, ViewArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "view",
        "open the viewer: the view beside a light's shadow map, every option on a control "
        "(docs/viewer.md)");
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
    std::error_code ec;
    if (!std::filesystem::is_directory(args.screenshotDir, ec)) {
        throw Error(ErrorKind::InvalidInput,
                    "--screenshot-dir: '" + args.screenshotDir + "' is not a folder");
    }
    std::vector<view::Command> script;
    if (!args.script.empty()) {
        std::error_code missing;
        if (!std::filesystem::is_regular_file(args.script, missing)) {
            throw Error(ErrorKind::InvalidInput, "--script: no such file '" + args.script + "'");
        }
        std::ifstream in(args.script, std::ios::binary);
        if (!in) throw Error(ErrorKind::Io, "--script: cannot read '" + args.script + "'");
        std::stringstream text;
        text << in.rdbuf();
        script = view::parseScript(text.str(), args.script);
    }
    view::State state;
    view::load(state, args.scene, args.flags.ground, args.flags.upAxis());
    args.flags.placeCameraAndSun(state.scene);
    printWarnings(state.scene);
    state.options = args.flags.resolve(state.scene);
    if (args.flags.given(optionAt(state.options, &state.options.width))) state.fitView = false;
    viewer::Viewer viewer(args, verbose, width, height, std::move(state), std::move(script));
    return viewer.run();
}

}  // namespace gnomon::cli
