// score()'s two steps apart, for what traces a view once and compares it more than once or
// across frames (score over a path: flicker between frames; tune: many settings, one view).
#pragma once

#include "gnomon/Score.h"
#include "truth/Reference.h"

namespace gnomon::detail {

// The reference of the view `options` renders (soft with filter pcss); `seconds`: wall time.
truth::Reference traceForScore(const Scene& scene, const RenderOptions& options,
                               const ScoreOptions& scoreOptions, ScoreProgress* progress,
                               double& seconds);

// `frame` scored against `reference` (traced for the same view and size); traceSeconds 0.
ScoreResult compareWithReference(const ScoreFrame& frame, const truth::Reference& reference,
                                 const Scene& scene, const RenderOptions& options,
                                 const ScoreOptions& scoreOptions);

}  // namespace gnomon::detail
