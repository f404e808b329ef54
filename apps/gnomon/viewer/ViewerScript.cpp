// The --script runner: one command per frame (waits, repeats, screenshots, scores and their
// expectations), errors reported with the script's line and turned into the exit code.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <regex>

#include "ViewerApp.h"

namespace gnomon::cli::viewer {

void Viewer::fail(const std::string& message) {
    std::fprintf(stderr, "gnomon: error: %s: %s\n", mArgs.script.c_str(), message.c_str());
    mExitCode = 1;
}

void Viewer::runScript() {
    if (!mScripted) return;
    if (mWaitFrames > 0) {
        --mWaitFrames;
        if (mWaitFrames > 0) return;
    }
    if (mWaitScore) {
        if (mJob) return;
        mWaitScore = false;
    }
    if (mWaitTune) {
        if (mTuneJob) return;
        mWaitTune = false;
    }
    if (mRepeatLeft > 0) {  // one repetition per frame
        --mRepeatLeft;
        try {
            runCommand(mRepeated);
        } catch (const Error& e) {
            std::fprintf(stderr, "gnomon: error: %s:%d: %s\n", mArgs.script.c_str(), mRepeated.line,
                         e.what());
            mExitCode = e.kind() == ErrorKind::InvalidInput ? 2 : 1;
        }
        return;
    }
    while (mNext < mScript.size() && mWaitFrames == 0 && mRepeatLeft == 0 && !mWaitScore &&
           !mWaitTune && !mQuit) {
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
    if (mNext >= mScript.size() && mWaitFrames == 0 && mRepeatLeft == 0 && !mWaitScore &&
        !mWaitTune)
        mScripted = false;
}

void Viewer::runCommand(const view::Command& c) {
    if (view::applyCommand(mState, c)) return;
    const std::string arg = c.args.empty() ? "" : c.args[0];
    if (c.verb == "wait") {
        if (!std::regex_match(arg, std::regex(R"(\d{1,6})"))) {
            throw Error(ErrorKind::InvalidInput, "wait: expected a frame count, got '" + arg + "'");
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
    } else if (c.verb == "tune") {
        settleOptions();
        mTuneJob.reset();
        startTune();
    } else if (c.verb == "wait-tune") {
        mWaitTune = true;
    } else if (c.verb == "apply-tune") {
        applyTune();
    } else if (c.verb == "expect-score") {
        expectScore(c);
    } else if (c.verb == "key") {
        key(arg);
    } else if (c.verb == "repeat") {
        mRepeated = view::repeatedCommand(c);
        mRepeatLeft = std::stoi(c.args[0]);
    } else if (c.verb == "measure") {
        if (arg != "on" && arg != "off") {
            throw Error(ErrorKind::InvalidInput, "measure: expected on or off, got '" + arg + "'");
        }
        mMeasure = arg == "on";
        mRenderer.setPassTiming(mMeasure);
    } else if (c.verb == "tab") {
        mSelectTab = tabIndex(arg);
        if (mSelectTab < 0) {
            throw Error(ErrorKind::InvalidInput,
                        "tab: expected Scene, Lights, Shadows or Filter, got '" + arg + "'");
        }
        mWaitFrames = 2;  // shown on the next frame, laid out by the one after
    } else if (c.verb == "expect-fits") {
        if (mControlsOverflow > 0.0f) {
            char message[160];
            std::snprintf(message, sizeof message,
                          "expect-fits: the %s tab needs %.0f more pixels than the window has",
                          kControlTabs[mTab], mControlsOverflow);
            fail(message);
        }
    } else if (c.verb == "stats") {
        printStats();
    } else if (c.verb == "quit") {
        mQuit = true;
    }
}

// The main view's options after this frame's commands so far, at the last frame's size:
// what a scripted screenshot, save or score uses.
void Viewer::settleOptions() {
    mMainOptions =
        view::mainViewOptions(mState, std::max(mDrawnWidth, 1), std::max(mDrawnHeight, 1));
}

void Viewer::expectScore(const view::Command& c) {
    if (!mScore)
        throw Error(ErrorKind::InvalidInput, "expect-score: no score yet (run score, wait-score)");
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
        fail("line " + std::to_string(c.line) + ": expected " + c.args[0] + " " + c.args[1] + " " +
             c.args[2] + ", measured " + std::to_string(it->second));
    }
}

void Viewer::printStats() {
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

}  // namespace gnomon::cli::viewer
