// The search behind gnomon tune (no GL): coordinate descent over a few discrete settings for
// the lowest error within a frame-time budget, and the error-versus-time front of everything
// it tried.
//
// Why coordinate descent: the settings are few (under ten), each takes a handful of values,
// and they act mostly apart from each other (tolerances, filter, resolution, cascades), so
// trying every value of one setting with the others held, keeping the best, and sweeping
// again until nothing improves finds the optimum of such a space in two or three sweeps of
// some thirty trials each. Every trial is a full render and score of each view, so
// exhaustive search (thousands of points) is out; successive halving pays off when a cheap,
// noisy early estimate exists, and a shadow score has none (a smaller image scores
// differently, not roughly the same). One setting at a time cannot see a pair that trades
// time (a larger map paid for by a smaller filter), so the descent also tries such pairs
// where it would otherwise stop.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace gnomon::search {

struct Parameter {
    std::string name;                 // an option name ("pcf-size")
    std::vector<std::string> values;  // as the CLI spells them ("3", "auto", "on")
};
using Point = std::vector<int>;  // per parameter: the index of its value

struct Evaluation {
    double error = 0.0;  // what to minimise (gnomon tune: misclassified + away from edges)
    double ms = 0.0;     // frame time
};
struct Trial {
    Point point;
    Evaluation eval;
};
struct SearchResult {
    std::vector<Trial> trials;  // every point evaluated, once each, in order
    int best = -1;              // the trial with the lowest error within the budget (-1: none)
    int sweeps = 0;             // sweeps over the parameters done
    int trades = 0;             // pairs of changes the search moved to (coordinateDescent)
    bool stopped = false;       // `stop` ended it early: `trials` and `best` hold what was found
};

// Starts at `start` (evaluated first; it is the current point even over the budget) and
// sweeps the parameters in order: each of its other values is tried with the rest held, and
// the current point moves to the best one within `budgetMs` (frame time <= budget) that
// lowers the error. After a sweep that moved nothing it tries trades: the two best single
// changes that lower the error but break the budget, each paired with every single change
// of another parameter that is faster than the current point; a winning pair starts another
// sweep. Stops when no trade wins, after `maxSweeps` sweeps, or when `stop` returns true
// (checked before each trial after the start's, which always runs). `evaluate` may throw; the
// search does not catch.
SearchResult coordinateDescent(const std::vector<Parameter>& parameters, const Point& start,
                               double budgetMs,
                               const std::function<Evaluation(const Point&)>& evaluate,
                               int maxSweeps = 3, const std::function<bool()>& stop = {});

// The trials no other trial beats in both error and time (lower or equal in both, lower in
// one), as indices into `trials`, fastest first.
std::vector<int> paretoFront(const std::vector<Trial>& trials);

}  // namespace gnomon::search
