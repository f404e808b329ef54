#include "core/TuneSearch.h"

#include <algorithm>
#include <map>

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

}  // namespace

SearchResult coordinateDescent(const std::vector<Parameter>& parameters, const Point& start,
                               double budgetMs,
                               const std::function<Evaluation(const Point&)>& evaluate,
                               int maxSweeps, const std::function<bool()>& stop) {
    SearchResult result;
    Memo memo(result, evaluate);
    auto stopping = [&] { return stop && (result.stopped = stop()); };
    auto feasible = [&](int t) { return result.trials[std::size_t(t)].eval.ms <= budgetMs; };
    auto error = [&](int t) { return result.trials[std::size_t(t)].eval.error; };
    auto consider = [&](int t) {
        if (feasible(t) && (result.best < 0 || error(t) < error(result.best))) result.best = t;
    };
    if (stopping()) return result;
    int current = memo.trial(start);
    consider(current);
    for (int sweep = 0; sweep < maxSweeps; ++sweep) {
        bool moved = false;
        for (std::size_t p = 0; p < parameters.size(); ++p) {
            int bestHere = current;
            for (int v = 0; v < int(parameters[p].values.size()); ++v) {
                if (v == result.trials[std::size_t(current)].point[p]) continue;
                if (stopping()) return result;
                Point next = result.trials[std::size_t(current)].point;
                next[p] = v;
                const int t = memo.trial(next);
                consider(t);
                // Within the budget and lower than what this parameter has found so far (an
                // over-budget current point gives way to any feasible one).
                const bool better =
                    feasible(t) && (!feasible(bestHere) || error(t) < error(bestHere));
                if (better) bestHere = t;
            }
            if (bestHere != current) {
                current = bestHere;
                moved = true;
            }
        }
        result.sweeps = sweep + 1;
        if (!moved) break;
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
