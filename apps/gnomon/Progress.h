// Signs of life and Ctrl-C for the CLI's long work.
//
// Activity: while it lives, a line on stderr says what is being done, for how long and, when
// known, how far ("gnomon: tracing the reference ... 42 % (3 s)"). It appears only after a
// second (short work stays silent) and only when stderr is a terminal (logs and pipes get no
// carriage returns); it is erased when the activity ends.
//
// Interrupts: the first Ctrl-C (SIGINT) only sets a flag that long loops check between
// steps, so that they can save what they finished; a second one ends the process at once.
// An interrupted command exits with code 130 (128 + SIGINT, as shells report it).
#pragma once

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "gnomon/Scene.h"

namespace gnomon::cli {

constexpr int kInterruptedExitCode = 130;

// Installs the SIGINT handler (once per process).
void catchInterrupts();
bool interrupted();
// Thrown where work stops for a Ctrl-C; main() prints its message and exits 130.
struct Interrupted : std::runtime_error {
    using std::runtime_error::runtime_error;
};
// Throws Interrupted("interrupted while <doing>") when Ctrl-C was pressed.
void checkInterrupt(const std::string& doing);

class Activity {
public:
    // `fraction`, when given, reports progress in [0, 1] (negative: unknown), polled from the
    // activity's own thread.
    explicit Activity(std::string label, std::function<double()> fraction = {});
    ~Activity();
    Activity(const Activity&) = delete;
    Activity& operator=(const Activity&) = delete;

private:
    void run();

    std::string mLabel;
    std::function<double()> mFraction;
    std::mutex mMutex;
    std::condition_variable mWake;
    bool mDone = false;
    bool mShown = false;
    std::thread mThread;
};

// loadScene with an activity line ("loading Sponza.gltf"), then an interrupt check.
Scene loadWithProgress(const std::string& nameOrPath, UpAxis up = UpAxis::Y);

}  // namespace gnomon::cli
