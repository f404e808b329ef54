// gnomon::tune: coordinate descent (lab/TuneSearch.h) over shadow settings, each trial
// rendered and scored over every view against references traced once, and timed as bench
// times a frame.
#include "gnomon/Tune.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include <nlohmann/json.hpp>

#include "gnomon/Error.h"
#include "gnomon/OptionSchema.h"
#include "lab/ScoreDetail.h"
#include "lab/TuneSearch.h"
#include "scene/SceneUtil.h"
#include "shadow/ShadowMath.h"

namespace gnomon {

namespace {

bool hasFittedSun(const Scene& s) {
    for (const Light& l : s.lights) {
        if (l.type == LightType::Directional && l.castsShadows &&
            l.shadowCamera.policy == ShadowCameraPolicy::Fit) {
            return true;
        }
    }
    return false;
}

const std::vector<std::string> kMapSizes = {"512", "1024", "2048", "4096"};

// Triangles the shadow casters draw at full detail. From about this many, a shadow pass on
// llvmpipe costs more in triangles than in texels (docs/results/performance.md, "Triangles"),
// so stand-in casters (--caster-detail) free time a larger map can use; below it they save
// little and only add trials.
constexpr std::size_t kStandInTriangles = 20000;

// Lights whose map sizes are searched one by one: every shadowed light that is on (the
// scene's switches, or --light-only's) when there are two to kMaxSizedApart of them and the
// options leave each its own size (map-size 0) with shadows on, so a scene's sun can take the
// texels its spot does not need. Otherwise none: one map size is searched for all (with many
// lights, three more trials per light and sweep would swamp the search; mixed-lights has 16).
constexpr std::size_t kMaxSizedApart = 8;
std::vector<int> lightsSizedApart(const Scene& scene, const RenderOptions& o) {
    std::vector<int> lights;
    if (o.shadow.mapSize != 0 || !o.shadow.enabled) return lights;
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        if (lightIsOn(scene, o, i) && scene.lights[i].castsShadows) lights.push_back(int(i));
    if (lights.size() < 2 || lights.size() > kMaxSizedApart) lights.clear();
    return lights;
}

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
Space searchSpace(const Scene& scene, const RenderOptions& o, search::Point& start) {
    Space result;
    result.sizedLights = lightsSizedApart(scene, o);
    for (const Light& l : scene.lights)
        result.ownSizes.push_back(shadowMapSizeOf(l));
    std::vector<search::Parameter>& space = result.parameters;
    // Each option by where it lives in RenderOptions (optionAt), so a wrong one fails to
    // compile; the values as the CLI spells them.
    std::vector<const OptionSpec*>& specs = result.specs;
    auto add = [&](const void* field, std::vector<std::string> values) {
        specs.push_back(&optionAt(o, field));
        space.push_back({specs.back()->name, std::move(values)});
    };
    const ShadowOptions& s = o.shadow;
    add(&s.filter, {"none", "pcf", "poisson", "pcss"});
    add(&s.pcfSize, {"1", "3", "5", "7"});
    if (result.sizedLights.empty()) add(&s.mapSize, kMapSizes);
    add(&s.receiverPlane, {"on", "off"});
    add(&s.normalOffset, {"0", "0.5", "1", "2"});
    add(&s.biasDepthAware, {"0.5", "1", "2", "4"});
    add(&s.biasSlope, {"0", "0.7", "1.5", "3"});
    add(&s.biasConstant, {"0", "0.00005", "0.0002"});
    if (hasFittedSun(scene)) add(&s.cascades, {"auto", "1", "2", "3", "4"});
    if (triangleCount(scene, /*castersOnly=*/true) >= kStandInTriangles)
        add(&s.casterDetail, {"1", "0.3", "0.1"});
    start.clear();
    for (std::size_t i = 0; i < space.size(); ++i) {
        search::Parameter& p = space[i];
        const OptionSpec& spec = *specs[i];
        // The same value however it is spelled ("5e-05" and "0.00005").
        auto at = std::find_if(p.values.begin(), p.values.end(), [&](const std::string& v) {
            RenderOptions candidate = o;
            return !parseOption(spec, v, candidate) && spec.get(candidate) == spec.get(o);
        });
        if (at == p.values.end()) at = p.values.insert(p.values.begin(), formatOption(spec, o));
        start.push_back(int(at - p.values.begin()));
    }
    result.options = space.size();
    for (int light : result.sizedLights) {
        search::Parameter p{"light " + std::to_string(light) + " map-size", kMapSizes};
        const std::string own = std::to_string(result.ownSizes[std::size_t(light)]);
        auto at = std::find(p.values.begin(), p.values.end(), own);
        if (at == p.values.end()) at = p.values.insert(p.values.begin(), own);
        start.push_back(int(at - p.values.begin()));
        space.push_back(std::move(p));
    }
    return result;
}

// A point of the search as settings: the options, and every light's map size (its own
// unless the search sets it). `flags` says what differs from the start: CLI flags for
// options, "light N map-size S" for a light's size (a scene-file light's shadow-map-size).
struct Setting {
    RenderOptions options;
    std::vector<int> mapSizes;
};

Setting settingAt(const Space& space, const search::Point& point, const RenderOptions& start,
                  std::string& flags) {
    Setting s{start, space.ownSizes};
    flags.clear();
    auto add = [&](const std::string& text) { flags += (flags.empty() ? "" : " ") + text; };
    for (std::size_t i = 0; i < space.parameters.size(); ++i) {
        const search::Parameter& p = space.parameters[i];
        const std::string& value = p.values[std::size_t(point[i])];
        if (i >= space.options) {
            const auto light = std::size_t(space.sizedLights[i - space.options]);
            s.mapSizes[light] = std::stoi(value);
            if (s.mapSizes[light] != space.ownSizes[light]) add(p.name + " " + value);
            continue;
        }
        const OptionSpec& spec = *space.specs[i];
        if (const auto problem = parseOption(spec, value, s.options))
            throw Error(ErrorKind::InvalidInput, "tune: --" + p.name + ": " + *problem);
        if (spec.get(s.options) != spec.get(start)) add("--" + p.name + " " + value);
    }
    return s;
}

class Evaluator {
public:
    Evaluator(Renderer& renderer, Scene& scene, std::vector<Camera> views,
              const TuneOptions& options)
        : mRenderer(renderer), mScene(scene), mViews(std::move(views)), mOptions(options) {}

    // Scores `setting` over every view (means), and times it on the first against `start`
    // (the starting settings; the very object for their own trial).
    TuneTrial run(const Setting& setting, const Setting& start, std::string flags,
                  double& traceSeconds) {
        TuneTrial t;
        const RenderOptions& o = setting.options;
        t.options = o;
        t.mapSizes = setting.mapSizes;
        t.flags = std::move(flags);
        apply(setting);
        try {
            score(t, o, traceSeconds);
            t.frameMs = frameMs(setting, start);
        } catch (const Error& e) {
            // A setting the driver cannot hold (maps beyond its memory) is a point of the
            // space that does not exist: recorded, never chosen, and the search goes on. The
            // starting settings must render, as they do for gnomon render.
            if (&setting == &start) throw;
            t.failure = e.what();
            t.misclassified = t.awayFromEdges = t.error = t.frameMs =
                std::numeric_limits<double>::infinity();
        }
        return t;
    }

    // `setting`'s error over every view (the mean), untimed.
    double error(const Setting& setting, double& traceSeconds) {
        apply(setting);
        TuneTrial t;
        score(t, setting.options, traceSeconds);
        return t.error;
    }

    // Wall-clock seconds of the last scoring over every view, tracing left out.
    double lastScoreSeconds() const { return mScoreSeconds; }

private:
    // Renders and scores `o` over every view: the means.
    void score(TuneTrial& t, const RenderOptions& o, double& traceSeconds) {
        const auto begin = std::chrono::steady_clock::now();
        const double traced = traceSeconds;
        for (std::size_t v = 0; v < mViews.size(); ++v) {
            mScene.camera = mViews[v];
            ScoreFrame frame = renderForScore(mRenderer, mScene, o, mOptions.score);
            const ScoreResult r = detail::compareWithReference(frame, reference(v, o, traceSeconds),
                                                               mScene, o, mOptions.score);
            t.misclassified += r.overall.misclassified / double(mViews.size());
            t.awayFromEdges += (r.overall.falseShadowOutsideBand + r.overall.leakOutsideBand) /
                               double(mViews.size());
        }
        t.error = t.misclassified + t.awayFromEdges;
        mScoreSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count() -
            (traceSeconds - traced);
    }

    void apply(const Setting& setting) { applyMapSizes(setting.mapSizes, mScene); }

    // Traced once per view (and once more soft, for pcss, as gnomon score compares it).
    const truth::Reference& reference(std::size_t view, const RenderOptions& o,
                                      double& traceSeconds) {
        const bool soft = o.shadow.filter == ShadowFilter::Pcss;
        const auto key = std::make_pair(view, soft);
        auto found = mReferences.find(key);
        if (found == mReferences.end()) {
            double seconds = 0.0;
            found = mReferences
                        .emplace(key,
                                 detail::traceForScore(mScene, o, mOptions.score, nullptr, seconds))
                        .first;
            traceSeconds += seconds;
        }
        return found->second;
    }

    // As gnomon bench times a frame (every map redrawn, no pass timing: wall time of
    // render()), alternating with the starting settings: the ratio of the two medians times
    // the starting settings' first median. The machine's drift hits both alike, so a
    // cheaper setting is not refused the budget for having been timed at a slow moment.
    // Two settings whose maps take different memory reallocate them at every switch, which
    // an application keeping one setting never does: each then settles for a frame before
    // the one timed, or the reallocation would be charged to whichever setting came second.
    double frameMs(const Setting& o, const Setting& start) {
        mScene.camera = mViews.front();
        std::vector<double> mine, theirs;
        auto time = [&](const Setting& setting, bool settle) {
            apply(setting);
            if (settle) {
                mRenderer.invalidateShadowMaps();
                mRenderer.render(mScene, setting.options);
            }
            mRenderer.invalidateShadowMaps();
            const auto begin = std::chrono::steady_clock::now();
            mRenderer.render(mScene, setting.options);
            return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                             begin)
                .count();
        };
        const bool same = &o == &start;
        time(o, false);  // warm-up: programs compiled, buffers sized
        const std::size_t bytes = mRenderer.lastFrameStats().shadowMapBytes;
        bool settle = false;
        if (!same) {
            time(start, false);
            settle = mRenderer.lastFrameStats().shadowMapBytes != bytes;
        }
        for (int i = 0; i < mOptions.timedFrames; ++i) {
            mine.push_back(time(o, settle));
            if (!same) theirs.push_back(time(start, settle));
        }
        const double median = medianOf(mine);
        if (same) return mBaselineMs = median;
        return medianOf(theirs) > 0.0 ? mBaselineMs * median / medianOf(theirs) : median;
    }

    static double medianOf(std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    }

    Renderer& mRenderer;
    Scene& mScene;
    std::vector<Camera> mViews;
    const TuneOptions& mOptions;
    std::map<std::pair<std::size_t, bool>, truth::Reference> mReferences;
    double mBaselineMs = 0.0;  // the starting settings' first median
    double mScoreSeconds = 0.0;
};

// `c` moved sideways, eye and target alike, by `dx` and `dy` pixels of an image `height`
// pixels high, measured at the target's distance: the picture moves by about that much there.
// Along the picture's own axes, as the renderer builds its view (gnomon::viewFromWorld, with
// its fallback where the camera looks along `up`).
Camera shiftedCamera(const Camera& c, int height, float dx, float dy) {
    const float distance = glm::length(c.centre - c.eye);
    if (!(distance > 0.0f) || height < 1) return c;
    const glm::mat4 worldFromView = glm::inverse(gnomon::viewFromWorld(c));
    const float viewHeight = c.projection == Projection::Perspective
                                 ? 2.0f * distance * std::tan(0.5f * glm::radians(c.fovyDegrees))
                                 : c.top - c.bottom;
    const glm::vec3 move = viewHeight / float(height) *
                           (dx * glm::vec3(worldFromView[0]) + dy * glm::vec3(worldFromView[1]));
    Camera moved = c;
    moved.eye += move;
    moved.centre += move;
    return moved;
}

// TuneOptions::checkShifted: `best` against `first` on every view moved half a pixel four
// ways, each shift's views traced anew.
TuneResult::ShiftCheck checkShifted(Renderer& renderer, Scene& scene,
                                    const std::vector<Camera>& views, const TuneOptions& options,
                                    const Setting& first, const Setting& best,
                                    const search::Noise& noise, double& traceSeconds) {
    const glm::vec2 shifts[] = {{0.5f, 0.0f}, {-0.5f, 0.0f}, {0.0f, 0.5f}, {0.0f, -0.5f}};
    TuneResult::ShiftCheck check;
    check.done = check.holds = true;
    for (const glm::vec2& d : shifts) {
        std::vector<Camera> moved;
        for (const Camera& c : views)
            moved.push_back(shiftedCamera(c, first.options.height, d.x, d.y));
        Evaluator evaluator(renderer, scene, moved, options);
        check.startErrors.push_back(evaluator.error(first, traceSeconds));
        check.bestErrors.push_back(evaluator.error(best, traceSeconds));
        check.holds = check.holds &&
                      search::noWorse(check.bestErrors.back(), check.startErrors.back(), noise);
    }
    return check;
}

}  // namespace

TuneResult tune(Renderer& renderer, Scene& scene, const RenderOptions& start,
                const TuneOptions& options, TuneProgress* progress,
                const std::function<void(const TuneTrial&)>& onTrial) {
    if (!(options.budgetMs >= 0.0) || options.timedFrames < 1 || options.timedFrames > 1000 ||
        options.maxSweeps < 1 || !(options.timeLimitSeconds >= 0.0)) {
        throw Error(ErrorKind::InvalidInput,
                    "tune: the budget must be >= 0 ms, timed frames 1..1000, sweeps >= 1, the "
                    "time limit >= 0 s");
    }
    const auto began = std::chrono::steady_clock::now();
    const auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    };
    const detail::RestoreView restore(scene);
    std::vector<Camera> views = {scene.camera};
    views.insert(views.end(), options.extraViews.begin(), options.extraViews.end());
    TuneResult result;
    result.views = int(views.size());
    search::Point startPoint;
    const Space space = searchSpace(scene, start, startPoint);
    Evaluator evaluator(renderer, scene, views, options);
    std::string flags;
    const Setting first = settingAt(space, startPoint, start, flags);
    // The starting settings first: their frame time is the budget when none is given.
    result.trials.push_back(evaluator.run(first, first, "", result.traceSeconds));
    if (onTrial) onTrial(result.trials.back());
    if (progress) ++progress->trialsDone;
    result.budgetMs = options.budgetMs > 0.0 ? options.budgetMs : result.trials[0].frameMs;
    // The check on shifted views runs after the search and within its time limit: four
    // references per view, as long as the first ones took, and eight scorings as long as the
    // first trial's are kept back.
    const double checkSeconds =
        options.checkShifted ? 4.0 * result.traceSeconds + 8.0 * evaluator.lastScoreSeconds() : 0.0;
    // Errors are fractions of the pixels of every view: two pixels is the score's floor.
    search::Noise noise;
    noise.pixels = double(start.width) * double(start.height) * double(views.size());
    std::map<search::Point, int> trialOf = {{startPoint, 0}};
    const search::SearchResult found = search::coordinateDescent(
        space.parameters, startPoint, result.budgetMs,
        [&](const search::Point& p) {
            if (!trialOf.count(p)) {
                const Setting setting = settingAt(space, p, start, flags);
                result.trials.push_back(evaluator.run(setting, first, flags, result.traceSeconds));
                trialOf[p] = int(result.trials.size()) - 1;
                if (onTrial) onTrial(result.trials.back());
                if (progress) ++progress->trialsDone;
            }
            const TuneTrial& t = result.trials[std::size_t(trialOf[p])];
            return search::Evaluation{t.error, t.frameMs};
        },
        options.maxSweeps,
        [&] {
            if (progress && progress->cancel.load()) return true;
            result.timedOut = options.timeLimitSeconds > 0.0 &&
                              elapsed() + checkSeconds >= options.timeLimitSeconds;
            return result.timedOut;
        },
        noise);
    result.sweeps = found.sweeps;
    result.trades = found.trades;
    result.interrupted = found.stopped && !result.timedOut;
    result.seconds = elapsed();
    if (found.best >= 0) result.best = trialOf[found.trials[std::size_t(found.best)].point];
    result.chosen = result.best;
    if (options.checkShifted && result.best > 0 && !result.interrupted) {
        const TuneTrial& bestTrial = result.trials[std::size_t(result.best)];
        const Setting best{bestTrial.options, bestTrial.mapSizes};
        result.shifted =
            checkShifted(renderer, scene, views, options, first, best, noise, result.traceSeconds);
        if (!result.shifted.holds) result.chosen = 0;
        result.seconds = elapsed();
    }
    std::vector<search::Trial> all;
    for (const TuneTrial& t : result.trials)
        all.push_back({{}, {t.error, t.frameMs}});
    result.front = search::paretoFront(all);
    result.beatsStart = search::beatsFirst(all, noise);
    if (result.chosen > 0) {
        const TuneTrial& c = result.trials[std::size_t(result.chosen)];
        result.sameQuality = search::errorsTie(c.error, result.trials[0].error, noise);
    }
    return result;
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
