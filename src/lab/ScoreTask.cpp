// gnomon::ScoreTask: scoreFrame in slices (the reference traced a few rows per step, then the
// comparison), and scoreFrame as one such task stepped to the end.
#include <limits>
#include <optional>

#include "gnomon/Error.h"
#include "gnomon/Score.h"
#include "lab/ScoreDetail.h"

namespace gnomon {

// What the task scores and how far it got. The scene is the task's own copy, or scoreFrame's
// caller's (which outlives the call); the progress counters and the cancel flag are the
// task's own, or scoreFrame's ScoreProgress.
struct ScoreTask::State {
    State(ScoreFrame scored, const Scene& s, bool copyScene, const RenderOptions& o,
          const ScoreOptions& so, ScoreProgress* progress)
        : options(o),
          scoreOptions(so),
          referenceOptions(detail::referenceOptions(o, so)),
          frame(std::move(scored)) {
        if (copyScene) ownScene.emplace(s);
        scene = copyScene ? &*ownScene : &s;
        if (progress) {
            rowsDone = &progress->rowsDone;
            cancel = &progress->cancel;
            progress->rows = o.height;
        }
        *rowsDone = 0;
        referenceOptions.rowsDone = rowsDone;
        referenceOptions.cancel = cancel;
    }

    std::optional<Scene> ownScene;
    const Scene* scene = nullptr;
    const RenderOptions options;
    const ScoreOptions scoreOptions;
    truth::ReferenceOptions referenceOptions;
    ScoreFrame frame;
    std::atomic<int> ownRowsDone{0};
    std::atomic<bool> ownCancel{false};
    std::atomic<int>* rowsDone = &ownRowsDone;
    std::atomic<bool>* cancel = &ownCancel;
    std::optional<truth::ReferenceTrace> trace;  // from the first step until every row is traced
    std::optional<truth::Reference> reference;   // then until the comparison
    std::optional<ScoreResult> result;
    double traceSeconds = 0.0;
};

ScoreTask::ScoreTask(ScoreFrame frame, const Scene& scene, const RenderOptions& options,
                     const ScoreOptions& scoreOptions)
    : mState(std::make_unique<State>(std::move(frame), scene, /*copyScene=*/true, options,
                                     scoreOptions, nullptr)) {}
ScoreTask::ScoreTask(std::unique_ptr<State> state) : mState(std::move(state)) {}
ScoreTask::~ScoreTask() = default;
ScoreTask::ScoreTask(ScoreTask&&) noexcept = default;
ScoreTask& ScoreTask::operator=(ScoreTask&&) noexcept = default;

bool ScoreTask::step(double seconds) {
    State& s = *mState;
    if (s.result) return true;
    const auto deadline = detail::deadlineAfter(seconds);
    if (!s.reference) {
        // Timed as traceForScore times a whole trace: the tracer's set-up and the rows.
        const auto began = std::chrono::steady_clock::now();
        bool traced = false;
        try {
            if (!s.trace) s.trace.emplace(*s.scene, s.options, s.referenceOptions);
            traced = s.trace->traceRows(deadline);
        } catch (...) {
            s.traceSeconds += detail::secondsSince(began);
            throw;
        }
        s.traceSeconds += detail::secondsSince(began);
        if (!traced) return false;
        s.reference = s.trace->finish();
        s.trace.reset();
        if (std::chrono::steady_clock::now() >= deadline) return false;
    }
    if (s.cancel->load()) throw Error(ErrorKind::InvalidInput, "ray-traced reference cancelled");
    ScoreResult result =
        detail::compareWithReference(s.frame, *s.reference, *s.scene, s.options, s.scoreOptions);
    result.traceSeconds = s.traceSeconds;
    s.result = std::move(result);
    s.reference.reset();
    return true;
}

int ScoreTask::rowsDone() const {
    return mState->rowsDone->load();
}
int ScoreTask::rows() const {
    return mState->options.height;
}
void ScoreTask::cancel() {
    *mState->cancel = true;
}

ScoreResult ScoreTask::result() {
    if (!mState->result) {
        throw Error(ErrorKind::InvalidInput, "score: the result is asked for before it is ready");
    }
    return std::move(*mState->result);
}

// The task over the caller's scene (no copy: the call outlives nothing), counting in
// `progress`, stepped without a time limit: one step traces every row, the same step compares.
ScoreResult scoreFrame(ScoreFrame frame, const Scene& scene, const RenderOptions& options,
                       const ScoreOptions& scoreOptions, ScoreProgress* progress) {
    ScoreTask task(std::make_unique<ScoreTask::State>(std::move(frame), scene, /*copyScene=*/false,
                                                      options, scoreOptions, progress));
    while (!task.step(std::numeric_limits<double>::infinity())) {
    }
    return task.result();
}

}  // namespace gnomon
