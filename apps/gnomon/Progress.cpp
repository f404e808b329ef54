#include "Progress.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>

namespace gnomon::cli {
namespace {

volatile std::sig_atomic_t gInterrupts = 0;

extern "C" void onInterrupt(int) {
    if (gInterrupts > 0) {
        // The second Ctrl-C: the user does not want to wait for the current step.
        std::signal(SIGINT, SIG_DFL);
        std::raise(SIGINT);
    }
    gInterrupts = gInterrupts + 1;
}

}  // namespace

void catchInterrupts() {
    struct sigaction action {};
    action.sa_handler = &onInterrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, nullptr);
}

bool interrupted() {
    return gInterrupts > 0;
}

void checkInterrupt(const std::string& doing) {
    if (interrupted()) throw Interrupted("interrupted while " + doing);
}

Activity::Activity(std::string label, std::function<double()> fraction)
    : mLabel(std::move(label)), mFraction(std::move(fraction)) {
    // The thread runs even when nothing is shown: it also polls `fraction`, which may act on
    // an interrupt (the score's tracing is cancelled from there).
    mThread = std::thread([this] { run(); });
}

Activity::~Activity() {
    {
        std::lock_guard<std::mutex> lock(mMutex);
        mDone = true;
    }
    mWake.notify_all();
    if (mThread.joinable()) mThread.join();
}

void Activity::run() {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    const bool terminal = isatty(STDERR_FILENO) != 0;
    std::unique_lock<std::mutex> lock(mMutex);
    // Silent for the first second: most commands end before anyone waits.
    for (int i = 0; i < 4 && !mDone; ++i) {
        if (mFraction) mFraction();
        mWake.wait_for(lock, std::chrono::milliseconds(250), [this] { return mDone; });
    }
    while (!mDone) {
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        const double f = mFraction ? mFraction() : -1.0;
        if (!terminal) {
            mWake.wait_for(lock, std::chrono::milliseconds(250), [this] { return mDone; });
            continue;
        }
        char amount[32] = "";
        if (f >= 0.0) std::snprintf(amount, sizeof amount, " %3.0f %%", 100.0 * std::min(f, 1.0));
        // \r and erase-to-end-of-line: one line rewritten in place.
        std::fprintf(stderr, "\r\033[Kgnomon: %s ...%s (%.0f s)%s", mLabel.c_str(), amount, seconds,
                     interrupted() ? " stopping after this step" : "");
        std::fflush(stderr);
        mShown = true;
        mWake.wait_for(lock, std::chrono::milliseconds(250), [this] { return mDone; });
    }
    if (mShown) {
        std::fprintf(stderr, "\r\033[K");
        std::fflush(stderr);
    }
}

Scene loadWithProgress(const std::string& nameOrPath, UpAxis up) {
    Scene scene = [&] {
        const Activity activity("loading " + nameOrPath);
        return loadScene(nameOrPath, up);
    }();
    checkInterrupt("loading " + nameOrPath);
    return scene;
}

}  // namespace gnomon::cli
