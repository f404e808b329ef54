// How wrong are the shadows? (issue 4) Renders a frame, reads back every light's shadow
// visibility per pixel (an output of the main pass), and compares it with a ray-traced
// reference of the same view (Embree): the surface each pixel sees, traced from the same
// camera through the pixel's centre, and a shadow ray to each light.
#pragma once

#include <atomic>
#include <string>
#include <vector>

#include "gnomon/Image.h"
#include "gnomon/Options.h"
#include "gnomon/Renderer.h"
#include "gnomon/Scene.h"

namespace gnomon {

struct ScoreOptions {
    int softSamples = 64;     // rays to each light's surface per pixel for the soft reference
    float bandTexels = 2.0f;  // aliasing band: map texels either side of a reference boundary
    int threads = 0;          // ray-tracing threads, 0 = every core
};

// Fractions are of the pixels where a light's shadow can show (`pixels`): the light reaches
// the surface the camera sees, and that surface receives shadows.
struct ShadowScore {
    int light = -1;              // index into Scene::lights; -1 for every light together
    std::string type;            // "directional", "spot", "point", "area" or "all"
    long pixels = 0;             // pixel x light pairs scored
    long bandPixels = 0;         // of them, inside the aliasing band
    double misclassified = 0.0;  // rendered visibility < 0.5 disagrees with the reference
    double falseShadow = 0.0;    // reference lit, rendered shadowed (acne, over-wide filters)
    double leak = 0.0;           // reference shadowed, rendered lit (peter-panning, misses)
    double falseShadowOutsideBand = 0.0;  // the same, away from shadow boundaries
    double leakOutsideBand = 0.0;
    double meanAbsError = 0.0;  // mean |rendered visibility - reference visibility|
};

struct ScoreResult {
    std::vector<ShadowScore> lights;  // one per shadowed light
    ShadowScore overall;
    bool softReference = false;  // filter pcss: compared with the soft reference
    double traceSeconds = 0.0;   // ray tracing wall time
    Image render;                // the frame scored
    Image errors;                // the error map (see truth/Metrics.h)
};

// score() in two halves, so that the ray tracing can run off the GL thread (gnomon view):
// renderForScore draws the frame and reads back its shadow visibility (the renderer's
// thread); scoreFrame traces the reference and compares (any thread, no GL).
struct ScoreFrame {
    Image render;
    ShadowVisibility visibility;
};
// Progress of scoreFrame, readable from another thread: rows traced of `rows`. Setting
// `cancel` stops the tracing early; scoreFrame then throws gnomon::Error.
struct ScoreProgress {
    std::atomic<int> rowsDone{0};
    std::atomic<int> rows{0};
    std::atomic<bool> cancel{false};
};
ScoreFrame renderForScore(Renderer& renderer, const Scene& scene, const RenderOptions& options,
                          const ScoreOptions& scoreOptions = {});
ScoreResult scoreFrame(ScoreFrame frame, const Scene& scene, const RenderOptions& options,
                       const ScoreOptions& scoreOptions = {}, ScoreProgress* progress = nullptr);

// Scores `options` on `scene`. Throws gnomon::Error like Renderer::render.
ScoreResult score(Renderer& renderer, const Scene& scene, const RenderOptions& options,
                  const ScoreOptions& scoreOptions = {});

// The result as JSON (every field, fractions as numbers in [0, 1]).
std::string toJson(const ScoreResult& result, const std::string& scene,
                   const RenderOptions& options);

}  // namespace gnomon
