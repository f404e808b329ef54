// How wrong are the shadows? (issue 4) Renders a frame, reads back every light's shadow
// visibility per pixel (an output of the main pass), and compares it with a ray-traced
// reference of the same view (Embree): the surface each pixel sees, traced from the same
// camera through the pixel's centre, and a shadow ray to each light.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "gnomon/Image.h"
#include "gnomon/Options.h"
#include "gnomon/Renderer.h"
#include "gnomon/Scene.h"
#include "gnomon/ScenePath.h"

namespace gnomon {

struct ScoreOptions {
    int softSamples = 64;     // rays to each light's surface per pixel for the soft reference
    float bandTexels = 2.0f;  // aliasing band: map texels either side of a reference boundary
    int threads = 0;          // ray-tracing threads, 0 = every core
    // Contacts, in world units: the leak is also scored over the pixels whose occluder lies
    // within this distance along the shadow ray (ShadowScore::contactLeak). 0: the options'
    // contact-length when contact shadows are on, else not scored.
    float contactRange = 0.0f;
    // Explain the errors (ScoreResult::errorCells and causes): a few shadow rays per leak,
    // worth it for one score, not for every trial of a search.
    bool explain = false;
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
    // With ScoreOptions::contactRange: the pixels the reference shadows by an occluder within
    // that distance (contacts), and the share of them rendered lit (the leak at contacts).
    long contactPixels = 0;
    double contactLeak = 0.0;
    double traced = 0.0;  // the share of the pairs a shadow ray decided (--shadow-rays)
};

// --blend-shadows coloured: the light the renderer lets through (visibility x transmittance,
// per channel) against the reference's, over the pixel x light pairs where either passes a
// tinting (blended) caster.
struct TintScore {
    long cells = 0;             // pixel x light pairs tinted by the renderer or the reference
    long cellsOutsideBand = 0;  // of them, away from the reference's shadow boundaries
    double meanError = 0.0;     // mean |rendered - reference| per channel, 0..1 (x 255: steps)
    double meanErrorOutsideBand = 0.0;
    // The colour alone: pairs where both let light past the opaque casters (rendered
    // visibility and the reference at least 0.5), |rendered tint - reference tint|. Apart
    // from the opaque shadow's edges, which misclassification already counts.
    long cellsBothLit = 0;
    double meanColourError = 0.0;
};

// One pixel x light the render got wrong (ScoreResult::errorCells; gnomon score's
// errors.csv), with the facts that explain most errors.
struct ErrorCell {
    int x = 0, y = 0;          // pixel, rows top first
    int light = 0;             // index into Scene::lights
    bool leak = false;         // reference shadowed, rendered lit; else false shadow
    bool inBand = false;       // inside the aliasing band around a reference shadow boundary
    float lightCosine = 0.0f;  // cos of the angle between the surface's normal and the light
    // Leaks: distance along the shadow ray to the first occluder, world units; -1 for false
    // shadow and where the hard ray is clear (a soft reference's leak).
    float occluderDistance = -1.0f;
    float texelWorld = 0.0f;  // world size of the map texel the lookup used
    float visibility = 0.0f;  // the rendered visibility (0 shadowed .. 1 lit)
};

// The errors away from shadow edges (outside the aliasing band), pixel x light pairs, by
// what explains them (ScoreResult::causes; src/truth/ErrorCauses.h gives the thresholds):
// grazing, the surface within 5.7 degrees of edge-on to the light (the map's resolution
// limit, under a tenth of the light); at a contact, a leak whose occluder lies within four
// map texels of the surface's plane (what moves a lookup off its surface reaches past it);
// other, the rest.
struct ErrorCauses {
    long falseShadowGrazing = 0, falseShadowOther = 0;
    long leakGrazing = 0, leakContact = 0, leakOther = 0;
};

struct ScoreResult {
    std::vector<ShadowScore> lights;  // one per shadowed light
    ShadowScore overall;
    TintScore tint;              // as tintErrors: scored only where there are coloured shadows
    bool softReference = false;  // filter pcss: compared with the soft reference
    // Pixels left out: the reference sees a receiving surface there and the render drew
    // another one, or none (a thin part seen edge-on that rasterisation misses, an alpha
    // mask read at another mip level). Their shadows are not the same surface's.
    long otherSurfacePixels = 0;
    float contactRange = 0.0f;  // the distance ShadowScore::contactLeak used (0: not scored)
    double traceSeconds = 0.0;  // ray tracing wall time
    Image render;               // the frame scored
    Image errors;               // the error map (see truth/Metrics.h)
    // The transmitted light's error map where the scene has coloured shadows (blended casters
    // and --blend-shadows coloured); empty, and `tint` all zero, where it has none.
    Image tintErrors;
    // With ScoreOptions::explain: every misclassified pixel x light, rows top first, and the
    // ones away from edges counted by cause.
    std::vector<ErrorCell> errorCells;
    ErrorCauses causes;
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

// scoreFrame in slices, for a caller that must return between them: a web page has no
// threads, so its viewer traces a few rows between frames and shows the progress; natively
// the viewer's job thread steps one until done (scoreFrame itself is such a loop). The
// result is scoreFrame's, number for number, however the rows are sliced.
class ScoreTask {
public:
    // Takes what renderForScore read back, and copies the scene: the task may outlive the
    // caller's edits. Throws gnomon::Error for bad score options, as scoreFrame does.
    ScoreTask(ScoreFrame frame, const Scene& scene, const RenderOptions& options,
              const ScoreOptions& scoreOptions = {});
    ~ScoreTask();
    ScoreTask(ScoreTask&&) noexcept;
    ScoreTask& operator=(ScoreTask&&) noexcept;

    // Traces reference rows for about `seconds` (at least one row, on scoreOptions.threads
    // threads, 0 = every core; the first step also puts the scene in the tracer), and
    // compares once every row is traced: in the step that traced the last row if its time
    // is not up, else in the next. Returns whether the result is ready. Throws gnomon::Error
    // as scoreFrame does, and once cancelled. Not thread-safe: one thread steps.
    bool step(double seconds);
    // Progress, readable from any thread while another steps: rows traced of rows().
    int rowsDone() const;
    int rows() const;
    // From any thread: the step under way stops taking rows, and it and every later step
    // throw gnomon::Error ("cancelled"), as scoreFrame does when ScoreProgress::cancel is set.
    void cancel();
    // The result, once step has returned true (it is moved out: ask once). traceSeconds is
    // the tracing time summed over the steps. Throws gnomon::Error before then.
    ScoreResult result();

private:
    struct State;
    explicit ScoreTask(std::unique_ptr<State> state);
    friend ScoreResult scoreFrame(ScoreFrame, const Scene&, const RenderOptions&,
                                  const ScoreOptions&, ScoreProgress*);
    std::unique_ptr<State> mState;
};

// Scores `options` on `scene`. Throws gnomon::Error like Renderer::render.
ScoreResult score(Renderer& renderer, const Scene& scene, const RenderOptions& options,
                  const ScoreOptions& scoreOptions = {});

// The result as JSON (every field, fractions as numbers in [0, 1]).
std::string toJson(const ScoreResult& result, const std::string& scene,
                   const RenderOptions& options);
// ScoreResult::errorCells as CSV, a header and one row per cell (gnomon score's errors.csv):
// x, y, light, kind (leak or false-shadow), in_band (0 or 1), light_cosine,
// occluder_distance (along the shadow ray, world units, -1: none), occluder_height_texels
// (its height above the surface's plane, distance x light_cosine, in map texels),
// texel_world, visibility.
std::string errorCellsCsv(const ScoreResult& result);

// Temporal stability over a path (gnomon score --path): every frame scored as score() does,
// and between each frame and the one before it the flicker: the previous frame's view drawn
// again with this frame's maps and lights, and the share of its pixel x light pairs whose
// rendered shadow changed while the reference's did not (truth/Flicker.h: the camera's own
// motion and steadily misplaced edges do not count). Each frame after the first costs a
// second render when the camera moved.
struct PathFrameScore {
    ShadowScore overall;
    long compared = 0;     // pixel x light pairs compared with the frame before
    long flickered = 0;    // of them: rendered shadow changed, reference's did not
    double flicker = 0.0;  // flickered / compared; 0 on the first frame
    Image errors;  // with keepErrorMaps: the error map, flicker in yellow (where the previous
                   // frame's view saw it)
};
struct PathScoreResult {
    std::string path;
    int framesAsked = 0;
    std::vector<PathFrameScore> frames;  // the frames finished, in order
    double meanFlicker = 0.0;            // over frame pairs (frames 1..)
    double maxFlicker = 0.0;
    double meanMisclassified = 0.0;
    bool softReference = false;
    double traceSeconds = 0.0;
    bool interrupted = false;  // progress->cancel stopped it: `frames` holds what was finished
};
// `scene` is moved along `path` and put back as it was. `progress` (optional): each frame's
// tracing, and cancel, after which the frames finished are returned with `interrupted`.
// `onFrame` (optional) is called after each frame with the result so far.
PathScoreResult scorePath(Renderer& renderer, Scene& scene, const RenderOptions& options,
                          const ScenePath& path, const ScoreOptions& scoreOptions,
                          bool keepErrorMaps, ScoreProgress* progress = nullptr,
                          const std::function<void(const PathScoreResult&)>& onFrame = {});
std::string toJson(const PathScoreResult& result, const std::string& scene,
                   const RenderOptions& options);

}  // namespace gnomon
