#include "lab/TuneSearch.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace gnomon::search {

namespace {

// Every point evaluated once: a sweep revisits the current point's neighbours.
class Memo {
public:
    Memo(SearchResult& result, const std::function<Evaluation(const Point&)>& evaluate)
        : mResult(result), mEvaluate(evaluate) {}
    int trial(const Point& p) {
        const auto found = mIndex.find(p);
        if (found != mIndex.end()) return found->second;
        mResult.trials.push_back({p, mEvaluate(p)});
        const int i = int(mResult.trials.size()) - 1;
        mIndex.emplace(p, i);
        return i;
    }

private:
    SearchResult& mResult;
    const std::function<Evaluation(const Point&)>& mEvaluate;
    std::map<Point, int> mIndex;
};

// The search's state and its two moves. A move returns whether the current point moved, or
// nothing when `stop` ended the search.
class Descent {
public:
    Descent(const std::vector<Parameter>& parameters, double budgetMs,
            const std::function<Evaluation(const Point&)>& evaluate,
            const std::function<bool()>& stop, const Noise& noise, SearchResult& result)
        : mParameters(parameters),
          mBudget(budgetMs),
          mNoise(noise),
          mStop(stop),
          mResult(result),
          mMemo(result, evaluate) {}

    // The start is always evaluated, asked to stop or not: it is the point every result
    // holds (and, in gnomon tune, the budget).
    void start(const Point& p) { mCurrent = mMemo.trial(p); }

    // Every other value of each parameter in turn, the rest held; the current point moves
    // to the best within the budget that lowers the error (an over-budget current point
    // gives way to any feasible one).
    std::optional<bool> sweep() {
        bool moved = false;
        for (std::size_t p = 0; p < mParameters.size(); ++p) {
            int bestHere = mCurrent;
            if (!eachOtherValue(p, [&](int t) { bestHere = better(t, bestHere); }))
                return std::nullopt;
            moved |= bestHere != mCurrent;
            mCurrent = bestHere;
        }
        return moved;
    }

    // Pairs that trade time: a single change that lowers the error but breaks the budget (a
    // larger map) may fit beside one that saves time (a smaller filter), a pair that
    // changing one setting at a time never tries. From a point no single change improves,
    // the two best over-budget changes are each tried with every change of another
    // parameter that is faster than the point itself.
    std::optional<bool> trade() {
        struct Change {
            std::size_t parameter;
            int trial;
        };
        std::vector<Change> over, faster;
        for (std::size_t p = 0; p < mParameters.size(); ++p) {
            // Every trial is known already after a sweep that stayed.
            const bool going = eachOtherValue(p, [&](int t) {
                if (!feasible(t) && error(t) < error(mCurrent) &&
                    !errorsTie(error(t), error(mCurrent), mNoise))
                    over.push_back({p, t});
                if (ms(t) < ms(mCurrent)) faster.push_back({p, t});
            });
            if (!going) return std::nullopt;
        }
        std::sort(over.begin(), over.end(), [&](const Change& a, const Change& b) {
            return error(a.trial) < error(b.trial);
        });
        if (over.size() > 2) over.resize(2);
        int bestHere = mCurrent;
        for (const Change& gain : over) {
            for (const Change& saving : faster) {
                if (saving.parameter == gain.parameter) continue;
                if (stopping()) return std::nullopt;
                Point pair = point(gain.trial);
                pair[saving.parameter] = point(saving.trial)[saving.parameter];
                bestHere = better(mMemo.trial(pair), bestHere);
            }
        }
        const bool moved = bestHere != mCurrent;
        mCurrent = bestHere;
        return moved;
    }

private:
    // Evaluates the current point with parameter `p` at each of its other values, handing
    // each trial to `visit`; false when `stop` ended the search first.
    template <typename Visit>
    bool eachOtherValue(std::size_t p, Visit&& visit) {
        for (int v = 0; v < int(mParameters[p].values.size()); ++v) {
            if (v == point(mCurrent)[p]) continue;
            if (stopping()) return false;
            Point next = point(mCurrent);
            next[p] = v;
            visit(mMemo.trial(next));
        }
        return true;
    }

    const Point& point(int t) const { return mResult.trials[std::size_t(t)].point; }
    double error(int t) const { return mResult.trials[std::size_t(t)].eval.error; }
    double ms(int t) const { return mResult.trials[std::size_t(t)].eval.ms; }
    bool feasible(int t) const { return fitsBudget(ms(t), mBudget, mNoise); }
    bool stopping() { return mStop && (mResult.stopped = mStop()); }
    // `t` (just evaluated) or `incumbent`, whichever the current point should move to.
    int better(int t, int incumbent) const {
        const Evaluation& a = mResult.trials[std::size_t(t)].eval;
        const Evaluation& b = mResult.trials[std::size_t(incumbent)].eval;
        const bool wins = feasible(t) && (!feasible(incumbent) || preferred(a, b, mNoise));
        return wins ? t : incumbent;
    }

    const std::vector<Parameter>& mParameters;
    double mBudget;
    const Noise& mNoise;
    const std::function<bool()>& mStop;
    SearchResult& mResult;
    Memo mMemo;
    int mCurrent = -1;
};

}  // namespace

bool errorsTie(double a, double b, const Noise& noise) {
    const double pixel = noise.pixels > 0.0 ? noise.minPixels / noise.pixels : 0.0;
    return std::abs(a - b) < std::max(noise.relative * std::max(a, b), pixel) || a == b;
}

bool noWorse(double a, double b, const Noise& noise) {
    return a <= b || errorsTie(a, b, noise);
}

bool fitsBudget(double ms, double budgetMs, const Noise& noise) {
    return ms <= budgetMs * (1.0 + noise.budgetSlack);
}

bool preferred(const Evaluation& a, const Evaluation& b, const Noise& noise) {
    if (errorsTie(a.error, b.error, noise)) return a.ms < b.ms;
    return a.error < b.error;
}

// The least error is found first, then the cheapest of its ties: ties do not chain (a trial
// tying a tie of the least error may be clearly worse than it).
int chooseBest(const std::vector<Trial>& trials, double budgetMs, const Noise& noise) {
    int least = -1;
    for (std::size_t i = 0; i < trials.size(); ++i) {
        if (!fitsBudget(trials[i].eval.ms, budgetMs, noise)) continue;
        if (least < 0 || trials[i].eval.error < trials[std::size_t(least)].eval.error)
            least = int(i);
    }
    if (least < 0) return -1;
    int best = least;
    for (std::size_t i = 0; i < trials.size(); ++i) {
        const Evaluation& e = trials[i].eval;
        if (fitsBudget(e.ms, budgetMs, noise) &&
            errorsTie(e.error, trials[std::size_t(least)].eval.error, noise) &&
            e.ms < trials[std::size_t(best)].eval.ms)
            best = int(i);
    }
    return best;
}

int beatsFirst(const std::vector<Trial>& trials, const Noise& noise) {
    if (trials.empty()) return -1;
    const Evaluation& s = trials.front().eval;
    for (std::size_t i = 1; i < trials.size(); ++i) {
        const Evaluation& t = trials[i].eval;
        const bool tie = errorsTie(t.error, s.error, noise);
        if ((!tie && t.error < s.error && fitsBudget(t.ms, s.ms, noise)) ||
            (tie && t.ms * (1.0 + noise.budgetSlack) < s.ms))
            return int(i);
    }
    return -1;
}

SearchResult coordinateDescent(const std::vector<Parameter>& parameters, const Point& start,
                               double budgetMs,
                               const std::function<Evaluation(const Point&)>& evaluate,
                               int maxSweeps, const std::function<bool()>& stop,
                               const Noise& noise) {
    SearchResult result;
    Descent descent(parameters, budgetMs, evaluate, stop, noise, result);
    descent.start(start);
    for (int sweep = 0; sweep < maxSweeps; ++sweep) {
        const std::optional<bool> moved = descent.sweep();
        if (!moved) break;
        result.sweeps = sweep + 1;
        if (*moved) continue;
        const std::optional<bool> traded = descent.trade();
        if (!traded) break;
        if (!*traded) break;
        ++result.trades;
    }
    result.best = chooseBest(result.trials, budgetMs, noise);
    return result;
}

std::vector<int> paretoFront(const std::vector<Trial>& trials) {
    std::vector<int> order(trials.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = int(i);
    // Fastest first, then lowest error: a trial is on the front when it has a lower error
    // than every faster one.
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        const Evaluation &x = trials[std::size_t(a)].eval, &y = trials[std::size_t(b)].eval;
        return x.ms != y.ms ? x.ms < y.ms : x.error < y.error;
    });
    std::vector<int> front;
    for (int i : order) {
        if (front.empty() ||
            trials[std::size_t(i)].eval.error < trials[std::size_t(front.back())].eval.error) {
            front.push_back(i);
        }
    }
    return front;
}

}  // namespace gnomon::search
