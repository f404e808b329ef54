// The viewer's one class, declared for the files that define it: the app loop, frame and
// input (Viewer.cpp), the ImGui panels (ViewerControls.cpp, ViewerPanels.cpp), the score job
// and files (ViewerJobs.cpp) and the script runner (ViewerScript.cpp).
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "ImGuiSession.h"
#include "Viewer.h"
#include "ViewerState.h"
#include "gl/Objects.h"
#include "gl/Window.h"
#include "gnomon/gnomon.h"

namespace gnomon::cli::viewer {

// ---- Jobs: a score, a tune -----------------------------------------------------------------

// Natively a job steps its task to the end on a thread of its own, so the window stays live;
// a web page has no threads, so there the app loop steps it a slice a frame (pollScore,
// pollTune), and the page never freezes.
#ifdef __EMSCRIPTEN__
inline constexpr bool kJobThreads = false;
#else
inline constexpr bool kJobThreads = true;
#endif
// The time a frame gives a job's slice when it runs on the app loop.
inline constexpr double kJobSliceSeconds = 0.03;

// The ground-truth score of a frame (ScoreTask).
struct ScoreJob {
    std::unique_ptr<ScoreTask> task;
    std::atomic<bool> done{false};
    std::optional<ScoreResult> result;
    std::string error;
    std::uint64_t revision = 0;  // the state's revision it scored
    std::thread thread;          // kJobThreads only

    ~ScoreJob() {
        if (task) task->cancel();
        if (thread.joinable()) thread.join();
    }
};

// gnomon tune for the current view (TuneTask): many renders and scores. Natively on its own
// thread with its own headless renderer (the window's context stays with the app loop); in
// the page on the viewer's renderer between frames. It works on a copy of the scene.
struct TuneJob {
    std::unique_ptr<Renderer> renderer;  // kJobThreads only: the thread's own
    std::shared_ptr<Scene> scene;
    std::unique_ptr<TuneTask> task;      // made and stepped on the job's thread natively
    std::atomic<bool> cancelled{false};  // the user stopped it: the search ends with what it has
    std::atomic<int> trials{0};          // trials done
    std::atomic<bool> done{false};
    std::optional<TuneResult> result;
    std::string error;
    std::mutex mutex;
    std::string latest;  // the last trial, as a line (guarded by `mutex`)
    std::uint64_t revision = 0;
    std::thread thread;

    // One step of the task, cancelled first if the user asked.
    bool step(double seconds) {
        if (cancelled) task->cancel();
        return task->step(seconds);
    }
    ~TuneJob() {
        cancelled = true;
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

// ---- The viewer ----------------------------------------------------------------------------

// The Controls panel's tabs (ViewerControls.cpp), as the script's `tab` names them.
inline constexpr const char* kControlTabs[4] = {"Scene", "Lights", "Shadows", "Filter"};

class Viewer {
public:
    // `state` and `script` are checked before the window opens (runView).
    Viewer(const ViewArgs& args, bool verbose, int windowWidth, int windowHeight, view::State state,
           std::vector<view::Command> script);

    // The app loop until the window closes, a script quits or fails: the exit code.
    int run();
    // One turn of it: events, the animation clock, a frame. False once the viewer is done
    // (a page, whose browser runs the loop, calls this once a frame).
    bool step();
    int exitCode() const { return mExitCode; }
    // What is shown: the web page writes it into its address.
    const view::State& state() const { return mState; }
    // A frame of the current state is drawn, with all its shadow maps and no error.
    bool frameReady() const {
        return mFrames > 0 && !dirty() && mFrameError.empty() && mDrawnWidth > 0;
    }
    const std::string& frameError() const { return mFrameError; }
    // The camera's view as last drawn, in pixels.
    int drawnWidth() const { return mDrawnWidth; }
    int drawnHeight() const { return mDrawnHeight; }
    // The file the viewer last wrote (a screenshot, a scene file): the page hands it to the
    // browser's downloads.
    const std::string& lastWritten() const { return mLastWritten; }
    // The last score and how many have finished (the page's title reports each).
    const std::optional<ScoreResult>& lastScore() const { return mScore; }
    int scoresDone() const { return mScoresDone; }
    // Where the camera's view is in the window (screen units): x, y, width, height.
    const std::array<float, 4>& viewRect() const { return mViewRect; }
    // The window's new size in screen units (the page's canvas follows the browser's window).
    void resize(int width, int height) { mWindow.setSize(width, height); }
    // Shows another scene and options (the page's address changed): the score, tune and
    // their overlay of the old view go.
    void replaceState(view::State state);

private:
    // The app loop's frame and the input (Viewer.cpp).
    static ContextOptions contextOptions(bool verbose);
    bool dirty() const;
    void frame();
    void renderViews(int mainW, int mainH, int sideW);
    void dropStaleOverlay();
    void recordPasses();

    // ---- Controls (ViewerControls.cpp) ----

    void controls(float width, float height);
    void flagTip(const OptionSpec& spec);
    bool option(const OptionSpec& spec);
    void changed(bool c);
    void guarded(const std::function<void()>& action);
    void sceneControls();
    void cameraControls();
    void lightControls();
    static int tabOf(OptionGroup group);
    void groupControls(int tab);
    void optionControls(OptionGroup group);
    void optionControl(const OptionSpec& spec);
    void outputControls();
    void sizeControl(const OptionSpec& spec);
    void mapSizeControl(const OptionSpec& spec);
    void lightOnlyControl(const OptionSpec& spec);
    static int tabIndex(const std::string& name);
    static void inputText(const char* label, std::string& value);

    // ---- Views (ViewerPanels.cpp; mouseOnView in Viewer.cpp) ----

    void views(float x, float mainW, float viewW, float viewH);
    int lightIcons(const ImVec2& origin, const ImVec2& size, bool hovered);
    void cubeFaceLabels(const ImVec2& origin, const ImVec2& size);
    void mouseOnView(bool hovered, float viewHeight, int iconUnderMouse);

    // ---- Measurements (ViewerPanels.cpp) ----

    void measurePanel(float x, float y, float width, float height);
    void passTimes();
    void scorePanel();
    void tunePanel();

    // ---- Score job and files (ViewerJobs.cpp) ----

    void startScore();
    void pollScore();
    void stepScore();
    void startTune();
    void pollTune();
    void stepTune();
    void applyTune();
    std::string nextScreenshotPath();
    void screenshot(const std::string& path);
    void save(const std::string& path);

    // ---- Keys (Viewer.cpp) ----

    void handleKeys();
    void key(const std::string& name);

    // ---- Script (ViewerScript.cpp) ----

    void fail(const std::string& message);
    void runScript();
    void runCommand(const view::Command& c);
    void settleOptions();
    void expectScore(const view::Command& c);
    void printStats();

    const ViewArgs& mArgs;
    bool mVerbose;
    gl::Window mWindow;
    ImGuiSession mImGui;
    Renderer mRenderer;
    view::State mState;
    FlagDocs mDocs;

    RenderOptions mMainOptions;
    std::uint64_t mDrawnRevision = ~std::uint64_t(0), mDrawnViewRevision = 0;
    int mDrawnWidth = 0, mDrawnHeight = 0;
    bool mRedraw = false;
    std::string mFrameError, mUiError, mLastWritten, mSavePath, mSourceField, mShownSource;
    FrameStats mStats;
    std::vector<float> mShadowMs, mMainMs;
    std::vector<double> mFrameMs;
    bool mMeasure = true;

    GlTexture mSideTexture;
    int mSideW = 0, mSideH = 0, mSideLight = -1;
    bool mSideDirty = true;
    int mDragButton = -1;
    bool mDragIcon = false;  // the left drag started on a light's icon: it moves that light

    std::unique_ptr<ScoreJob> mJob;
    std::optional<ScoreResult> mScore;
    int mScoresDone = 0;
    std::uint64_t mScoredRevision = 0;
    std::string mScoreError;
    gl::Texture mOverlayTexture;
    bool mOverlay = false;
    float mOverlayOpacity = 0.6f;

    std::unique_ptr<TuneJob> mTuneJob;
    std::optional<TuneResult> mTune;
    std::uint64_t mTunedRevision = 0;
    std::string mTuneError;

    std::vector<view::Command> mScript;
    std::size_t mNext = 0;
    bool mScripted = false, mWaitScore = false, mWaitTune = false, mQuit = false;
    int mWaitFrames = 0;
    int mRepeatLeft = 0;
    view::Command mRepeated;
    std::string mWindowShot;
    int mTab = 0, mSelectTab = -1;   // the controls' tab shown; one to show next frame
    float mControlsOverflow = 0.0f;  // how far the shown tab scrolls (0: it fits)
    long mFrames = 0;
    std::array<float, 4> mViewRect{};
    std::chrono::steady_clock::time_point mLastStep;
    int mExitCode = 0;
};

}  // namespace gnomon::cli::viewer
