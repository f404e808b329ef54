// gnomon tune's evaluator: a setting rendered and scored over every view against references
// traced a slice at a time (each once per view, and once more soft for pcss), and timed as
// bench times a frame.
#include <algorithm>
#include <limits>

#include "gnomon/Error.h"
#include "lab/ScoreDetail.h"
#include "lab/TuneDetail.h"

namespace gnomon::detail {

Evaluator::Evaluator(Renderer& renderer, Scene& scene, std::vector<Camera> views,
                     const TuneOptions& options, FrameTimer timer, std::atomic<int>* rowsTraced)
    : mRenderer(renderer),
      mScene(scene),
      mViews(std::move(views)),
      mOptions(options),
      mTimer(std::move(timer)),
      mRowsTraced(rowsTraced) {}

bool Evaluator::traced(const RenderOptions& o) const {
    const bool soft = o.shadow.filter == ShadowFilter::Pcss;
    for (std::size_t v = 0; v < mViews.size(); ++v)
        if (!mReferences.count({v, soft})) return false;
    return true;
}

void Evaluator::trace(const RenderOptions& o, std::chrono::steady_clock::time_point deadline,
                      double& traceSeconds) {
    const bool soft = o.shadow.filter == ShadowFilter::Pcss;
    std::size_t v = 0;
    while (v < mViews.size() && mReferences.count({v, soft}))
        ++v;
    if (v == mViews.size()) return;
    const Key key{v, soft};
    const auto began = std::chrono::steady_clock::now();
    try {
        if (!mTracing || mTracing->key != key) {
            mTracing.reset();
            truth::ReferenceOptions ro = referenceOptions(o, mOptions.score);
            ro.rowsDone = mRowsTraced;
            mScene.camera = mViews[v];  // the trace keeps its own copy of the camera
            mTracing.emplace(Tracing{key, truth::ReferenceTrace(mScene, o, ro)});
        }
        if (mTracing->trace.traceRows(deadline)) {
            mReferences.emplace(key, mTracing->trace.finish());
            mTracing.reset();
        }
    } catch (...) {
        traceSeconds += secondsSince(began);
        mTracing.reset();
        throw;
    }
    traceSeconds += secondsSince(began);
}

TuneTrial Evaluator::failed(const Setting& setting, std::string flags, const std::string& why) {
    TuneTrial t;
    t.options = setting.options;
    t.mapSizes = setting.mapSizes;
    t.flags = std::move(flags);
    t.failure = why;
    t.misclassified = t.awayFromEdges = t.error = t.frameMs =
        std::numeric_limits<double>::infinity();
    return t;
}

TuneTrial Evaluator::run(const Setting& setting, const Setting& start, std::string flags) {
    TuneTrial t;
    const RenderOptions& o = setting.options;
    t.options = o;
    t.mapSizes = setting.mapSizes;
    t.flags = std::move(flags);
    apply(setting);
    try {
        score(t, o);
        t.frameMs = frameMs(setting, start);
    } catch (const Error& e) {
        // A setting the driver cannot hold (maps beyond its memory) is a point of the
        // space that does not exist: recorded, never chosen, and the search goes on. The
        // starting settings must render, as they do for gnomon render.
        if (&setting == &start) throw;
        return failed(setting, std::move(t.flags), e.what());
    }
    return t;
}

double Evaluator::error(const Setting& setting) {
    apply(setting);
    TuneTrial t;
    score(t, setting.options);
    return t.error;
}

void Evaluator::score(TuneTrial& t, const RenderOptions& o) {
    const auto begin = std::chrono::steady_clock::now();
    for (std::size_t v = 0; v < mViews.size(); ++v) {
        mScene.camera = mViews[v];
        ScoreFrame frame = renderForScore(mRenderer, mScene, o, mOptions.score);
        const ScoreResult r =
            compareWithReference(frame, reference(v, o), mScene, o, mOptions.score);
        t.misclassified += r.overall.misclassified / double(mViews.size());
        t.awayFromEdges +=
            (r.overall.falseShadowOutsideBand + r.overall.leakOutsideBand) / double(mViews.size());
    }
    t.error = t.misclassified + t.awayFromEdges;
    mScoreSeconds = secondsSince(begin);
}

const truth::Reference& Evaluator::reference(std::size_t view, const RenderOptions& o) const {
    const auto found = mReferences.find({view, o.shadow.filter == ShadowFilter::Pcss});
    if (found == mReferences.end()) {
        throw Error(ErrorKind::InvalidInput,
                    "tune: a view is scored before its reference is traced");
    }
    return found->second;
}

// As gnomon bench times a frame (every map redrawn, no pass timing: wall time of render()),
// alternating with the starting settings: the ratio of the two medians times the starting
// settings' first median. The machine's drift hits both alike, so a cheaper setting is not
// refused the budget for having been timed at a slow moment. Two settings whose maps take
// different memory reallocate them at every switch, which an application keeping one
// setting never does: each then settles for a frame before the one timed, or the
// reallocation would be charged to whichever setting came second.
double Evaluator::frameMs(const Setting& o, const Setting& start) {
    const bool same = &o == &start;
    if (mTimer) {
        const double ms = mTimer(o.options, o.mapSizes);
        if (same) mBaselineMs = ms;
        return ms;
    }
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
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin)
            .count();
    };
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
    const auto medianOf = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    };
    const double median = medianOf(mine);
    if (same) return mBaselineMs = median;
    return medianOf(theirs) > 0.0 ? mBaselineMs * median / medianOf(theirs) : median;
}

}  // namespace gnomon::detail
