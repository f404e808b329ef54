// gnomon tune's parts, for TuneTask (lab/Tune.cpp) and the tests: what the search varies
// (TuneSpace.cpp), the evaluator that renders, scores and times a setting against references
// traced in slices (TuneEvaluator.cpp), and the task's state.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gnomon/OptionSchema.h"
#include "gnomon/Tune.h"
#include "lab/TuneSearch.h"
#include "truth/Reference.h"

namespace gnomon::detail {

// What the search varies: options by their names, then one map size per light of
// `sizedLights` (parameter i >= options is that light's). `ownSizes`: every light's map size
// when the search began (shadowMapSizeOf; the evaluator sets them on the scene per trial).
struct Space {
    std::vector<search::Parameter> parameters;
    std::size_t options = 0;
    std::vector<const OptionSpec*> specs;  // the first `options` parameters' options
    std::vector<int> sizedLights;
    std::vector<int> ownSizes;
};

// The settings searched, each with the starting value among its values; `start` gets the
// index of that value per parameter.
Space searchSpace(const Scene& scene, const RenderOptions& o, search::Point& start);

// A point of the search as settings: the options, and every light's map size (its own
// unless the search sets it).
struct Setting {
    RenderOptions options;
    std::vector<int> mapSizes;
};
// `flags` says what differs from the start: CLI flags for options, "light N map-size S" for
// a light's size (a scene-file light's shadow-map-size).
Setting settingAt(const Space& space, const search::Point& point, const RenderOptions& start,
                  std::string& flags);

// `c` moved sideways, eye and target alike, by `dx` and `dy` pixels of an image `height`
// pixels high, measured at the target's distance.
Camera shiftedCamera(const Camera& c, int height, float dx, float dy);

// A trial's frame time from its setting instead of timed renders: for tests that compare two
// searches' courses, which live timings (they differ from run to run) would part where two
// errors tie. Empty: renders are timed.
using FrameTimer =
    std::function<double(const RenderOptions& options, const std::vector<int>& mapSizes)>;

// Renders and scores settings over views against references traced once per view (and once
// more soft, for pcss, as gnomon score compares it), a slice at a time; times them as bench
// times a frame.
class Evaluator {
public:
    // `rowsTraced` (optional) counts the reference rows traced.
    Evaluator(Renderer& renderer, Scene& scene, std::vector<Camera> views,
              const TuneOptions& options, FrameTimer timer, std::atomic<int>* rowsTraced);

    // Every reference `o` is scored against is traced.
    bool traced(const RenderOptions& o) const;
    // Traces rows of the first reference `o` lacks until `deadline` (at least one row), its
    // time added to `traceSeconds`. Throws gnomon::Error as the trace does (and drops it).
    void trace(const RenderOptions& o, std::chrono::steady_clock::time_point deadline,
               double& traceSeconds);
    // Forgets a reference traced in part (its trial was given up).
    void dropTrace() { mTracing.reset(); }

    // Scores `setting` over every view (means), and times it on the first against `start`
    // (the starting settings; the very object for their own trial). The references must be
    // traced. A setting that cannot be rendered is a failed trial, except the start's.
    TuneTrial run(const Setting& setting, const Setting& start, std::string flags);
    // `setting` as a trial that could not be evaluated (`why`): never chosen.
    static TuneTrial failed(const Setting& setting, std::string flags, const std::string& why);
    // `setting`'s error over every view (the mean), untimed; the references traced.
    double error(const Setting& setting);
    // Wall-clock seconds of the last scoring over every view.
    double lastScoreSeconds() const { return mScoreSeconds; }

private:
    using Key = std::pair<std::size_t, bool>;  // view, soft
    struct Tracing {
        Key key;
        truth::ReferenceTrace trace;
    };
    void score(TuneTrial& t, const RenderOptions& o);
    void apply(const Setting& setting) { applyMapSizes(setting.mapSizes, mScene); }
    const truth::Reference& reference(std::size_t view, const RenderOptions& o) const;
    double frameMs(const Setting& o, const Setting& start);

    Renderer& mRenderer;
    Scene& mScene;
    std::vector<Camera> mViews;
    const TuneOptions& mOptions;
    FrameTimer mTimer;
    std::atomic<int>* mRowsTraced;
    std::map<Key, truth::Reference> mReferences;
    std::optional<Tracing> mTracing;  // the reference being traced
    double mBaselineMs = 0.0;         // the starting settings' first median
    double mScoreSeconds = 0.0;
};

// TuneTask's state. tune() makes one counting in its TuneProgress; tests give a FrameTimer.
struct TuneTaskState {
    TuneTaskState(Renderer& renderer, Scene& scene, const RenderOptions& start,
                  const TuneOptions& options, std::function<void(const TuneTrial&)> onTrial,
                  TuneProgress* progress = nullptr, FrameTimer timer = {});
    double elapsed() const;  // the task's seconds: its making and its steps, this one so far

    enum class Phase { Start, Search, Shifted, Done };
    const std::chrono::steady_clock::time_point made;
    const TuneOptions options;
    Renderer& renderer;
    Scene& scene;
    const RenderOptions start;
    const std::function<void(const TuneTrial&)> onTrial;
    const FrameTimer timer;
    std::atomic<int> ownTrialsDone{0}, checksDone{0}, rowsTraced{0};
    std::atomic<bool> ownCancel{false};
    std::atomic<int>* trialsDone = &ownTrialsDone;
    std::atomic<bool>* cancel = &ownCancel;
    std::vector<Camera> views;
    search::Point startPoint;
    const Space space;
    const Setting first;
    Evaluator evaluator;
    search::Noise noise;
    TuneResult result;
    std::map<search::Point, int> trialOf;  // each point evaluated: its trial
    Phase phase = Phase::Start;
    double checkSeconds = 0.0;  // kept back from the time limit for the shifted views
    // The search is run again over the trials so far at every step (lab/Tune.cpp): the stop
    // checks known to have passed, and the point being evaluated with the check before it.
    int passedChecks = 0;
    std::optional<search::Point> pending;
    int pendingCheck = 0;
    // The check on shifted views: the best setting, the shift whose views `shifted` scores.
    Setting best;
    std::unique_ptr<Evaluator> shifted;
    int shiftedIndex = -1;
    double seconds = 0.0;  // the making and the finished steps
    std::optional<std::chrono::steady_clock::time_point> stepBegan;
};

// tune() with `timer` for the frame times (empty: timed renders, as tune() has them).
TuneResult tuneWith(const FrameTimer& timer, Renderer& renderer, Scene& scene,
                    const RenderOptions& start, const TuneOptions& options,
                    TuneProgress* progress = nullptr,
                    const std::function<void(const TuneTrial&)>& onTrial = {});

}  // namespace gnomon::detail
