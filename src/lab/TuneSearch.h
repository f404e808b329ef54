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
// What counts as the same: a shadow score moves by a few pixels with the pixel grid, and a
// frame time by a few percent from run to run, so differences within these are noise.
struct Noise {
    double pixels = 0.0;        // the pixels an error of 1 stands for (0: no pixel floor)
    double relative = 0.02;     // errors within this fraction of the larger one tie...
    double minPixels = 2.0;     // ...or within this many pixels, whichever is more
    double budgetSlack = 0.05;  // a frame time this fraction over the budget still fits it
};
bool errorsTie(double a, double b, const Noise& noise);
// `a` is lower than `b` or ties it.
bool noWorse(double a, double b, const Noise& noise);
bool fitsBudget(double ms, double budgetMs, const Noise& noise);
// `a` is the better trial: a lower error that does not tie, or a tie at less time.
bool preferred(const Evaluation& a, const Evaluation& b, const Noise& noise);
// The least error within the budget and, among the trials whose error ties it, the cheapest;
// -1 when none fits.
int chooseBest(const std::vector<Trial>& trials, double budgetMs, const Noise& noise);
// The first trial after trials[0] that beats it: a lower error (not a tie) at no more time
// (within the slack), or a tied error cheaper by more than the slack; -1 when none does.
int beatsFirst(const std::vector<Trial>& trials, const Noise& noise);

struct SearchResult {
    std::vector<Trial> trials;  // every point evaluated, once each, in order
    int best = -1;              // chooseBest over `trials` (-1: none fits the budget)
    int sweeps = 0;             // sweeps over the parameters done
    int trades = 0;             // pairs of changes the search moved to (coordinateDescent)
    bool stopped = false;       // `stop` ended it early: `trials` and `best` hold what was found
};

// Starts at `start` (evaluated first; it is the current point even over the budget) and
// sweeps the parameters in order: each of its other values is tried with the rest held, and
// the current point moves to the one within `budgetMs` (fitsBudget) it prefers (preferred:
// a lower error, or the same error for less time). After a sweep that moved nothing it tries
// trades: the two best single changes that lower the error but break the budget, each paired with
// every single change of another parameter that is faster than the current point; a winning pair
// starts another sweep. Stops when no trade wins, after `maxSweeps` sweeps, or when `stop` returns
// true (checked before each trial after the start's, which always runs). `evaluate` may throw; the
// search does not catch.
SearchResult coordinateDescent(const std::vector<Parameter>& parameters, const Point& start,
                               double budgetMs,
                               const std::function<Evaluation(const Point&)>& evaluate,
                               int maxSweeps = 3, const std::function<bool()>& stop = {},
                               const Noise& noise = {});

// The trials no other trial beats in both error and time (lower or equal in both, lower in
// one), as indices into `trials`, fastest first.
std::vector<int> paretoFront(const std::vector<Trial>& trials);

}  // namespace gnomon::search
