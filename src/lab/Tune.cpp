// gnomon::tune and TuneTask: coordinate descent (lab/TuneSearch.h) over shadow settings, each
// trial rendered and scored over every view against references traced once, and timed as
// bench times a frame (lab/TuneEvaluator.cpp), done a step at a time.
//
// The search itself knows nothing of steps: it is deterministic given its evaluations and its
// stop checks, so every step runs it again from the start over the trials so far, with an
// evaluation that throws at the first point without a trial. The task then evaluates that
// point over the next steps (its references in slices, then its trial) and runs it again.
// The stop checks it passed are remembered and pass again; a new one is made when reached,
// before the trial after it, as tune() always made it. The check on shifted views that
// follows is eight scorings in a row, one a step.
#include "gnomon/Tune.h"

#include <limits>

#include <nlohmann/json.hpp>

#include "gnomon/Error.h"
#include "lab/ScoreDetail.h"
#include "lab/TuneDetail.h"

namespace gnomon {

namespace detail {

namespace {

using Phase = TuneTaskState::Phase;

const TuneOptions& checked(const TuneOptions& options) {
    if (!(options.budgetMs >= 0.0) || options.timedFrames < 1 || options.timedFrames > 1000 ||
        options.maxSweeps < 1 || !(options.timeLimitSeconds >= 0.0)) {
        throw Error(ErrorKind::InvalidInput,
                    "tune: the budget must be >= 0 ms, timed frames 1..1000, sweeps >= 1, the "
                    "time limit >= 0 s");
    }
    return options;
}

std::vector<Camera> viewsOf(const Scene& scene, const TuneOptions& options) {
    std::vector<Camera> views = {scene.camera};
    views.insert(views.end(), options.extraViews.begin(), options.extraViews.end());
    return views;
}

Setting startSetting(const Space& space, const search::Point& point, const RenderOptions& start) {
    std::string flags;
    return settingAt(space, point, start, flags);
}

// Thrown by the search's evaluation at the first point without a trial.
struct Pending {};

// What the task does next: evaluate `setting` with `evaluator`, as a trial of the search (the
// starting settings' in Phase::Start) or as a scoring of the check on shifted views.
struct Work {
    enum class Kind { None, Trial, Check } kind = Kind::None;
    Evaluator* evaluator = nullptr;
    Setting setting;
    std::string flags;
};

// The error-versus-time front, the first trial that beats the start, and whether the chosen
// one keeps the start's quality.
void finish(TuneTaskState& s) {
    TuneResult& r = s.result;
    std::vector<search::Trial> all;
    for (const TuneTrial& t : r.trials)
        all.push_back({{}, {t.error, t.frameMs}});
    r.front = search::paretoFront(all);
    r.beatsStart = search::beatsFirst(all, s.noise);
    if (r.chosen > 0) {
        const TuneTrial& c = r.trials[std::size_t(r.chosen)];
        r.sameQuality = search::errorsTie(c.error, r.trials[0].error, s.noise);
    }
    s.phase = Phase::Done;
}

// The search ended: its best, and whether the check on shifted views follows.
void endSearch(TuneTaskState& s, const search::SearchResult& found) {
    TuneResult& r = s.result;
    r.sweeps = found.sweeps;
    r.trades = found.trades;
    r.interrupted = found.stopped && !r.timedOut;
    r.seconds = s.elapsed();
    if (found.best >= 0) r.best = s.trialOf[found.trials[std::size_t(found.best)].point];
    r.chosen = r.best;
    s.phase = Phase::Done;  // finish() follows, unless the check on shifted views does first
    if (s.options.checkShifted && r.best > 0 && !r.interrupted) {
        const TuneTrial& best = r.trials[std::size_t(r.best)];
        s.best = Setting{best.options, best.mapSizes};
        r.shifted.done = r.shifted.holds = true;
        s.phase = Phase::Shifted;
    }
}

// The search run from the start over the trials so far: the point it asks for next that has
// no trial, or nothing once it has ended (endSearch).
std::optional<search::Point> replay(TuneTaskState& s) {
    if (s.pending) return s.pending;
    int calls = 0;
    std::optional<search::Point> next;
    search::SearchResult found;
    try {
        found = search::coordinateDescent(
            s.space.parameters, s.startPoint, s.result.budgetMs,
            [&](const search::Point& p) {
                const auto at = s.trialOf.find(p);
                if (at == s.trialOf.end()) {
                    next = p;
                    throw Pending{};
                }
                const TuneTrial& t = s.result.trials[std::size_t(at->second)];
                return search::Evaluation{t.error, t.frameMs};
            },
            s.options.maxSweeps,
            [&] {
                if (++calls <= s.passedChecks) return false;
                if (s.cancel->load()) return true;
                s.result.timedOut = s.options.timeLimitSeconds > 0.0 &&
                                    s.elapsed() + s.checkSeconds >= s.options.timeLimitSeconds;
                if (s.result.timedOut) return true;
                s.passedChecks = calls;
                return false;
            },
            s.noise);
    } catch (const Pending&) {
        s.pending = next;
        s.pendingCheck = calls;
        return next;
    }
    endSearch(s, found);
    return std::nullopt;
}

// The check's next scoring: scoring k scores the views of shift k / 2, each traced anew, with
// the starting settings (k even) or the best (k odd).
Work nextCheck(TuneTaskState& s) {
    static const glm::vec2 shifts[] = {{0.5f, 0.0f}, {-0.5f, 0.0f}, {0.0f, 0.5f}, {0.0f, -0.5f}};
    const int k = s.checksDone.load();
    if (s.shiftedIndex != k / 2) {
        const glm::vec2 d = shifts[k / 2];
        std::vector<Camera> moved;
        for (const Camera& c : s.views)
            moved.push_back(shiftedCamera(c, s.first.options.height, d.x, d.y));
        s.shifted = std::make_unique<Evaluator>(s.renderer, s.scene, std::move(moved), s.options,
                                                s.timer, &s.rowsTraced);
        s.shiftedIndex = k / 2;
    }
    return {Work::Kind::Check, s.shifted.get(), k % 2 ? s.best : s.first, ""};
}

Work next(TuneTaskState& s) {
    if (s.phase == Phase::Start) return {Work::Kind::Trial, &s.evaluator, s.first, ""};
    if (s.phase == Phase::Search) {
        if (s.pending && s.cancel->load()) {
            // Given up: the check before it is made again, and now stops the search.
            s.passedChecks = s.pendingCheck - 1;
            s.pending.reset();
            s.evaluator.dropTrace();
        }
        if (const std::optional<search::Point> p = replay(s)) {
            Work w{Work::Kind::Trial, &s.evaluator, {}, ""};
            w.setting = settingAt(s.space, *p, s.start, w.flags);
            return w;
        }
    }
    if (s.phase == Phase::Shifted) {
        if (s.cancel->load()) {
            s.result.shifted = {};
            s.result.interrupted = true;
        } else if (s.checksDone.load() < 8) {
            return nextCheck(s);
        } else if (!s.result.shifted.holds) {
            s.result.chosen = 0;
        }
        s.shifted.reset();
        s.result.seconds = s.elapsed();
    }
    finish(s);
    return {};
}

void trialDone(TuneTaskState& s) {
    if (s.onTrial) s.onTrial(s.result.trials.back());
    ++*s.trialsDone;
}

// The search's pending point as `trial`.
void recordPending(TuneTaskState& s, TuneTrial trial) {
    s.result.trials.push_back(std::move(trial));
    s.trialOf[*s.pending] = int(s.result.trials.size()) - 1;
    s.pending.reset();
    trialDone(s);
}

void perform(TuneTaskState& s, const Work& w) {
    TuneResult& r = s.result;
    if (w.kind == Work::Kind::Check) {
        const double error = w.evaluator->error(w.setting);
        const bool best = s.checksDone.load() % 2 == 1;
        (best ? r.shifted.bestErrors : r.shifted.startErrors).push_back(error);
        if (best) {
            r.shifted.holds =
                r.shifted.holds &&
                search::noWorse(r.shifted.bestErrors.back(), r.shifted.startErrors.back(), s.noise);
        }
        ++s.checksDone;
        return;
    }
    if (s.phase == Phase::Search) {
        recordPending(s, s.evaluator.run(w.setting, s.first, w.flags));
        return;
    }
    // The starting settings first: their frame time is the budget when none is given.
    r.trials.push_back(s.evaluator.run(s.first, s.first, ""));
    s.trialOf[s.startPoint] = 0;
    trialDone(s);
    r.budgetMs = s.options.budgetMs > 0.0 ? s.options.budgetMs : r.trials[0].frameMs;
    // The check on shifted views runs after the search and within its time limit: four
    // references per view, as long as the first ones took, and eight scorings as long as the
    // first trial's are kept back.
    s.checkSeconds =
        s.options.checkShifted ? 4.0 * r.traceSeconds + 8.0 * s.evaluator.lastScoreSeconds() : 0.0;
    s.phase = Phase::Search;
}

// Slices of references until `deadline`, then at most one trial or scoring.
void work(TuneTaskState& s, std::chrono::steady_clock::time_point deadline) {
    for (;;) {
        const Work w = next(s);
        if (w.kind == Work::Kind::None) return;
        if (w.evaluator->traced(w.setting.options)) {
            perform(s, w);
            return;
        }
        try {
            w.evaluator->trace(w.setting.options, deadline, s.result.traceSeconds);
        } catch (const Error& e) {
            // A trial of the search that cannot be traced fails as one that cannot be
            // rendered does; the start's and the check's end the task.
            if (s.phase != Phase::Search) throw;
            recordPending(s, Evaluator::failed(w.setting, w.flags, e.what()));
            return;
        }
        if (std::chrono::steady_clock::now() >= deadline) return;
    }
}

}  // namespace

TuneTaskState::TuneTaskState(Renderer& renderer_, Scene& scene_, const RenderOptions& start_,
                             const TuneOptions& options_,
                             std::function<void(const TuneTrial&)> onTrial_, TuneProgress* progress,
                             FrameTimer timer_)
    : made(std::chrono::steady_clock::now()),
      options(checked(options_)),
      renderer(renderer_),
      scene(scene_),
      start(start_),
      onTrial(std::move(onTrial_)),
      timer(std::move(timer_)),
      views(viewsOf(scene_, options)),
      space(searchSpace(scene_, start_, startPoint)),
      first(startSetting(space, startPoint, start_)),
      evaluator(renderer_, scene_, views, options, timer, &rowsTraced) {
    if (progress) {
        trialsDone = &progress->trialsDone;
        cancel = &progress->cancel;
    }
    result.views = int(views.size());
    // Errors are fractions of the pixels of every view: two pixels is the score's floor.
    noise.pixels = double(start.width) * double(start.height) * double(views.size());
    seconds = secondsSince(made);
}

double TuneTaskState::elapsed() const {
    return seconds + (stepBegan ? secondsSince(*stepBegan) : 0.0);
}

}  // namespace detail

TuneTask::TuneTask(Renderer& renderer, Scene& scene, const RenderOptions& start,
                   const TuneOptions& options, std::function<void(const TuneTrial&)> onTrial)
    : mState(std::make_unique<detail::TuneTaskState>(renderer, scene, start, options,
                                                     std::move(onTrial))) {}
TuneTask::TuneTask(std::unique_ptr<detail::TuneTaskState> state) : mState(std::move(state)) {}
TuneTask::~TuneTask() = default;
TuneTask::TuneTask(TuneTask&&) noexcept = default;
TuneTask& TuneTask::operator=(TuneTask&&) noexcept = default;

bool TuneTask::step(double seconds) {
    detail::TuneTaskState& s = *mState;
    if (s.phase == detail::TuneTaskState::Phase::Done) return true;
    const auto deadline = detail::deadlineAfter(seconds);
    s.stepBegan = std::chrono::steady_clock::now();
    // The views and map sizes the trials set are the scene's own again between steps.
    const detail::RestoreView restore(s.scene);
    try {
        detail::work(s, deadline);
    } catch (...) {
        s.seconds += detail::secondsSince(*s.stepBegan);
        s.stepBegan.reset();
        throw;
    }
    s.seconds += detail::secondsSince(*s.stepBegan);
    s.stepBegan.reset();
    return s.phase == detail::TuneTaskState::Phase::Done;
}

int TuneTask::trialsDone() const {
    return mState->trialsDone->load();
}
int TuneTask::checksDone() const {
    return mState->checksDone.load();
}
int TuneTask::rowsTraced() const {
    return mState->rowsTraced.load();
}
void TuneTask::cancel() {
    *mState->cancel = true;
}

TuneResult TuneTask::result() {
    if (mState->phase != detail::TuneTaskState::Phase::Done) {
        throw Error(ErrorKind::InvalidInput, "tune: the result is asked for before it is ready");
    }
    return std::move(mState->result);
}

TuneResult detail::tuneWith(const FrameTimer& timer, Renderer& renderer, Scene& scene,
                            const RenderOptions& start, const TuneOptions& options,
                            TuneProgress* progress,
                            const std::function<void(const TuneTrial&)>& onTrial) {
    TuneTask task(
        std::make_unique<TuneTaskState>(renderer, scene, start, options, onTrial, progress, timer));
    while (!task.step(std::numeric_limits<double>::infinity())) {
    }
    return task.result();
}

TuneResult tune(Renderer& renderer, Scene& scene, const RenderOptions& start,
                const TuneOptions& options, TuneProgress* progress,
                const std::function<void(const TuneTrial&)>& onTrial) {
    return detail::tuneWith({}, renderer, scene, start, options, progress, onTrial);
}

void applyMapSizes(const std::vector<int>& mapSizes, Scene& scene) {
    if (mapSizes.size() != scene.lights.size()) return;
    for (std::size_t i = 0; i < mapSizes.size(); ++i) {
        Light& l = scene.lights[i];
        // A size equal to the default stays unnamed (0), as the scene may have had it (a point
        // light drawn as a cube then takes its 1024 per face, as it started).
        l.shadowMapSize = mapSizes[i] == kDefaultShadowMapSize ? 0 : mapSizes[i];
    }
}

std::string toJson(const TuneResult& r, const std::string& scene) {
    auto trial = [](const TuneTrial& t) {
        if (!t.failure.empty()) return nlohmann::json{{"flags", t.flags}, {"failed", t.failure}};
        return nlohmann::json{{"flags", t.flags},
                              {"map_sizes", t.mapSizes},
                              {"misclassified", t.misclassified},
                              {"away_from_edges", t.awayFromEdges},
                              {"error", t.error},
                              {"frame_ms", t.frameMs}};
    };
    nlohmann::json j;
    j["scene"] = scene;
    j["views"] = r.views;
    j["budget_ms"] = r.budgetMs;
    j["sweeps"] = r.sweeps;
    j["trades"] = r.trades;
    j["interrupted"] = r.interrupted;
    j["timed_out"] = r.timedOut;
    j["seconds"] = r.seconds;
    j["trace_seconds"] = r.traceSeconds;
    j["best"] = r.best;
    j["start_on_front"] = r.beatsStart < 0;
    j["beats_start"] = r.beatsStart;
    j["chosen"] = r.chosen;
    j["same_quality"] = r.sameQuality;
    if (r.shifted.done) {
        j["shifted"] = {{"start_errors", r.shifted.startErrors},
                        {"best_errors", r.shifted.bestErrors},
                        {"holds", r.shifted.holds}};
    }
    j["front"] = r.front;
    j["trials"] = nlohmann::json::array();
    for (const TuneTrial& t : r.trials)
        j["trials"].push_back(trial(t));
    return j.dump(2) + "\n";
}

}  // namespace gnomon
