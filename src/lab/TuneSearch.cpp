#include "lab/TuneSearch.h"

#include <algorithm>
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
            const std::function<bool()>& stop, SearchResult& result)
        : mParameters(parameters),
          mBudget(budgetMs),
          mStop(stop),
          mResult(result),
          mMemo(result, evaluate) {}

    // The start is always evaluated, asked to stop or not: it is the point every result
    // holds (and, in gnomon tune, the budget).
    void start(const Point& p) {
        mCurrent = mMemo.trial(p);
        consider(mCurrent);
    }

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
                if (!feasible(t) && error(t) < error(mCurrent)) over.push_back({p, t});
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
    bool feasible(int t) const { return ms(t) <= mBudget; }
    bool stopping() { return mStop && (mResult.stopped = mStop()); }
    void consider(int t) {
        if (feasible(t) && (mResult.best < 0 || error(t) < error(mResult.best))) mResult.best = t;
    }
    // `t` (just evaluated) or `incumbent`, whichever the current point should move to.
    int better(int t, int incumbent) {
        consider(t);
        const bool wins = feasible(t) && (!feasible(incumbent) || error(t) < error(incumbent));
        return wins ? t : incumbent;
    }

    const std::vector<Parameter>& mParameters;
    double mBudget;
    const std::function<bool()>& mStop;
    SearchResult& mResult;
    Memo mMemo;
    int mCurrent = -1;
};

}  // namespace

SearchResult coordinateDescent(const std::vector<Parameter>& parameters, const Point& start,
                               double budgetMs,
                               const std::function<Evaluation(const Point&)>& evaluate,
                               int maxSweeps, const std::function<bool()>& stop) {
    SearchResult result;
    Descent descent(parameters, budgetMs, evaluate, stop, result);
    descent.start(start);
    for (int sweep = 0; sweep < maxSweeps; ++sweep) {
        const std::optional<bool> moved = descent.sweep();
        if (!moved) return result;
        result.sweeps = sweep + 1;
        if (*moved) continue;
        const std::optional<bool> traded = descent.trade();
        if (!traded) return result;
        if (!*traded) break;
        ++result.trades;
    }
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
