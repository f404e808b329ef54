// score()'s two steps apart, for what traces a view once and compares it more than once or
// across frames (score over a path: flicker between frames; tune: many settings, one view).
#pragma once

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
