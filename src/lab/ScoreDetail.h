// score()'s two steps apart, for what traces a view once and compares it more than once or
// across frames (score over a path: flicker between frames; tune: many settings, one view).
#pragma once

#include <algorithm>
#include <chrono>

#include "gnomon/Score.h"
#include "truth/Reference.h"

namespace gnomon::detail {

// Puts a scene's camera and lights back however a path or a search that moves them ends.
class RestoreView {
public:
    explicit RestoreView(Scene& scene)
        : mScene(scene), mCamera(scene.camera), mLights(scene.lights) {}
    ~RestoreView() {
        mScene.camera = mCamera;
        mScene.lights = mLights;
    }
    RestoreView(const RestoreView&) = delete;
    RestoreView& operator=(const RestoreView&) = delete;

private:
    Scene& mScene;
    Camera mCamera;
    std::vector<Light> mLights;
};

// What the score asks of the reference for `options` (soft with filter pcss, the contacts'
// range, the score's threads), once the score's options are checked (throws gnomon::Error).
truth::ReferenceOptions referenceOptions(const RenderOptions& options,
                                         const ScoreOptions& scoreOptions,
                                         truth::TracerKind tracer = truth::defaultTracer());

// The end of a slice of `seconds` from now (steps of ScoreTask and TuneTask); none for a slice
// too long to count.
inline std::chrono::steady_clock::time_point deadlineAfter(double seconds) {
    const auto now = std::chrono::steady_clock::now();
    if (!(seconds < 1e9)) return std::chrono::steady_clock::time_point::max();
    return now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                     std::chrono::duration<double>(std::max(seconds, 0.0)));
}
inline double secondsSince(std::chrono::steady_clock::time_point begin) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

// The reference of the view `options` renders (soft with filter pcss); `seconds`: wall time.
// `tracer`: the rays' backend (truth/Tracer.h), a choice for tests and tools, not an option.
truth::Reference traceForScore(const Scene& scene, const RenderOptions& options,
                               const ScoreOptions& scoreOptions, ScoreProgress* progress,
                               double& seconds, truth::TracerKind tracer = truth::defaultTracer());

// `frame` scored against `reference` (traced for the same view and size); traceSeconds 0.
// Its render moves into the result (its visibility stays).
ScoreResult compareWithReference(ScoreFrame& frame, const truth::Reference& reference,
                                 const Scene& scene, const RenderOptions& options,
                                 const ScoreOptions& scoreOptions);

}  // namespace gnomon::detail
