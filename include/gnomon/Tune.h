// Shadow settings calibrated against ray-traced truth (gnomon tune): a search over the
// tolerances, filter and its size, map size (per light when a scene has several shadowed
// lights) and cascades for the lowest error over one or more views within a frame-time
// budget. The reference of each view is traced once and
// reused for every setting tried.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "gnomon/Options.h"
#include "gnomon/Renderer.h"
#include "gnomon/Scene.h"
#include "gnomon/Score.h"

namespace gnomon {

struct TuneOptions {
    // Frame-time budget in ms, measured as gnomon bench measures a frame (every map redrawn,
    // from the first view); 0: the starting settings' own frame time. Each trial is timed
    // over `timedFrames` frames alternating with the starting settings, and reported as the
    // starting settings' time times the ratio of the two medians (drift cancels out).
    double budgetMs = 0.0;
    int timedFrames = 5;
    int maxSweeps = 3;
    // Wall-clock seconds the search may take, from the call (tracing the references and the
    // starting settings' trial included; those always finish; a TuneTask counts the time in
    // its steps); 0: no limit. At the limit the
    // trial under way finishes and the search stops with what it found (TuneResult::timedOut).
    // The check on shifted views (checkShifted) comes within it: the search stops that much
    // sooner, as long as four tracings and eight scorings of the first trial took.
    // Nine minutes, so that a whole `gnomon tune` (loading, the trial under way at the limit,
    // the files written) keeps within ten on the slowest real scenes (871k triangles at 512²:
    // a trial takes 5-15 s there).
    double timeLimitSeconds = 540.0;
    std::vector<Camera> extraViews;  // scored besides the scene's camera
    ScoreOptions score;
    // After the search, score the best setting and the starting one again on four copies of
    // every view with the camera moved sideways by half a pixel (right, left, up, down), each
    // against its own reference. A shadow score counts pixels, and a setting can win on one
    // pixel grid by a few of them: only a gain that shows on every shifted copy is the
    // setting's own (TuneResult::shifted). Off: the best is taken as found.
    bool checkShifted = true;
};

// One setting tried, scored over every view (means) and timed.
struct TuneTrial {
    RenderOptions options;
    // Per light of the scene, its shadow map size in this trial (shadowMapSizeOf): the
    // search sets them one by one when two to eight lights cast shadows and
    // options.shadow.mapSize is 0; otherwise they are the scene's own.
    std::vector<int> mapSizes;
    // What differs from the starting settings ("" = none): CLI flags, and "light N map-size
    // S" for a light's own size.
    std::string flags;
    double misclassified = 0.0;
    double awayFromEdges = 0.0;  // false shadow + leak outside the aliasing band
    double error = 0.0;          // what the search minimises: misclassified + awayFromEdges
    double frameMs = 0.0;
    // Why the setting could not be rendered ("" = it was), e.g. maps beyond the driver's
    // memory: its error and time are then infinite, so it is never chosen.
    std::string failure;
};

struct TuneResult {
    std::vector<TuneTrial> trials;  // trials[0]: the starting settings
    // The lowest error within the budget and, of the errors the same as it, the fastest (-1:
    // none fits).
    int best = -1;
    std::vector<int> front;  // error-versus-time front, fastest first
    // The first trial that beats the starting settings (-1: none): a lower error for no more
    // time, or the same error for less. Errors are the same when they differ by less than 2 %
    // of the larger or 2 pixels, whichever is more; times within 5 % are the same, and a
    // trial within 5 % over the budget fits it.
    int beatsStart = -1;
    // The best against the starting settings on the views shifted by half a pixel
    // (TuneOptions::checkShifted), one error per shift (the mean over the views), and whether
    // the best's was no worse on each (lower, or the same as above): a setting whose gain is
    // the pixel grid's loses on some shift. Not done (`done` false) when the best
    // is the starting settings, none fits the budget, or the search was interrupted.
    struct ShiftCheck {
        bool done = false;
        std::vector<double> startErrors, bestErrors;
        bool holds = false;
    } shifted;
    // The setting tune recommends (what `gnomon tune --out` writes and the viewer applies):
    // the best, unless the shifted views did not bear its gain out, then the starting
    // settings (0); -1 when no setting fits the budget.
    int chosen = -1;
    // The chosen setting (not the starting one) has the starting settings' error, as above:
    // it saves time at the same quality.
    bool sameQuality = false;
    double budgetMs = 0.0;
    int views = 0;
    int sweeps = 0;
    int trades = 0;            // pairs of changes that trade time the search moved to
    bool interrupted = false;  // progress->cancel stopped it: what was found so far
    bool timedOut = false;     // TuneOptions::timeLimitSeconds stopped it: the same
    double seconds = 0.0;      // the search's wall-clock time (a TuneTask's: in its steps)
    double traceSeconds = 0.0;
};

struct TuneProgress {
    std::atomic<int> trialsDone{0};
    std::atomic<bool> cancel{false};
};

// Searches from `start` on `scene` (its camera is moved to each view and put back).
// `onTrial` (optional) is called after each trial. Throws gnomon::Error as score does.
// A TuneTask stepped until done: the same search, the same result.
TuneResult tune(Renderer& renderer, Scene& scene, const RenderOptions& start,
                const TuneOptions& options, TuneProgress* progress = nullptr,
                const std::function<void(const TuneTrial&)>& onTrial = {});

namespace detail {
struct TuneTaskState;
}

// tune() in steps, for a caller that must return between them: a web page has no threads, so
// its viewer runs a step between frames and shows the progress; natively the viewer's job
// thread steps one until done. A step does one piece of the search: a slice of a view's
// reference trace (the bulk of the time), or one trial's renders, scores and timings, or one
// scoring of the check on shifted views. The trials, best and choice are tune()'s for the
// same renders, scores and frame times, however the steps are sliced.
class TuneTask {
public:
    // The same inputs as tune(). The renderer, the scene and the callback are used by step
    // (on the renderer's thread) and must outlive the task; the scene must not change while
    // the task lives (make it a copy the caller keeps), though between steps its camera and
    // lights are as given. Throws gnomon::Error for bad options, as tune() does.
    TuneTask(Renderer& renderer, Scene& scene, const RenderOptions& start,
             const TuneOptions& options, std::function<void(const TuneTrial&)> onTrial = {});
    explicit TuneTask(std::unique_ptr<detail::TuneTaskState> state);  // tune()'s, the tests'
    ~TuneTask();
    TuneTask(TuneTask&&) noexcept;
    TuneTask& operator=(TuneTask&&) noexcept;

    // Works for about `seconds`: slices of reference rows until then (at least one row), and
    // at most one trial or shifted-view scoring, after which it returns (a trial cannot be
    // cut: it may run past the time). Returns whether the result is ready. Throws
    // gnomon::Error as tune() does; the task is then of no further use.
    // TuneOptions::timeLimitSeconds counts the time spent in steps (and making the task),
    // not the time between them.
    bool step(double seconds);
    // Progress, readable from any thread while another steps: trials done (TuneResult::trials
    // so far), scorings of the check on shifted views done (8 when checked: four shifts, the
    // start's and the best's), and reference rows traced over every view so far.
    int trialsDone() const;
    int checksDone() const;
    int rowsTraced() const;
    // From any thread: the search stops with what it found (TuneResult::interrupted), as
    // TuneProgress::cancel stops tune(). A trial whose references are being traced is given
    // up (the starting settings' always finishes: it sets the budget), and so is the check
    // on shifted views. The next steps finish at once.
    void cancel();
    // The result, once step has returned true (it is moved out: ask once). Throws
    // gnomon::Error before then.
    TuneResult result();

private:
    std::unique_ptr<detail::TuneTaskState> mState;
};

// Gives each light of `scene` its map size in `mapSizes` (one per light, as
// TuneTrial::mapSizes holds them); sizes for another light count change nothing (a scene
// edited since the search).
void applyMapSizes(const std::vector<int>& mapSizes, Scene& scene);

// The result as JSON: every trial with its flags and numbers, the best and the front.
std::string toJson(const TuneResult& result, const std::string& scene);

}  // namespace gnomon
