// gnomon tune's search without GL: coordinate descent finds the known optimum of a space
// whose best point is known (found here by trying every point), respects the budget, finds
// a pair of changes that trades time, stops when asked, and the front keeps exactly the
// trials nothing beats; its choice counts errors within the score's noise as equal (the cheaper
// wins) and times a few percent over the budget as within it.
#include <gtest/gtest.h>

#include <limits>

#include "lab/TuneSearch.h"

namespace gnomon::search {
namespace {

std::vector<Parameter> space() {
    return {{"a", {"0", "1", "2", "3", "4"}}, {"b", {"0", "1", "2", "3"}}, {"c", {"0", "1", "2"}}};
}

// Separable error with its minimum at (3, 1, 2); time grows with a and c.
Evaluation model(const Point& p) {
    const double a = p[0] - 3.0, b = p[1] - 1.0, c = p[2] - 2.0;
    return {a * a + 2.0 * b * b + 0.5 * c * c, 10.0 + 4.0 * p[0] + 3.0 * p[2]};
}

// The best point within `budget` by trying all 60.
Point bruteForce(double budget) {
    Point best;
    double bestError = 1e300;
    for (int a = 0; a < 5; ++a)
        for (int b = 0; b < 4; ++b)
            for (int c = 0; c < 3; ++c) {
                const Evaluation e = model({a, b, c});
                if (e.ms <= budget && e.error < bestError) {
                    bestError = e.error;
                    best = {a, b, c};
                }
            }
    return best;
}

TEST(TuneSearch, FindsTheKnownOptimum) {
    int calls = 0;
    const SearchResult r = coordinateDescent(space(), {0, 3, 0}, 1e9, [&](const Point& p) {
        ++calls;
        return model(p);
    });
    ASSERT_GE(r.best, 0);
    EXPECT_EQ(r.trials[std::size_t(r.best)].point, (Point{3, 1, 2}));
    EXPECT_EQ(calls, int(r.trials.size()));  // each point once
    EXPECT_LT(calls, 60);                    // fewer than trying every point
    EXPECT_FALSE(r.stopped);
}

TEST(TuneSearch, StaysWithinTheBudget) {
    for (double budget : {10.0, 16.0, 20.0, 25.0}) {
        SCOPED_TRACE(budget);
        // Exact comparisons: no slack on the budget, no ties (TuneChoice tests those).
        const Noise exact{0.0, 0.0, 0.0, 0.0};
        const SearchResult r = coordinateDescent(space(), {0, 0, 0}, budget, model, 3, {}, exact);
        ASSERT_GE(r.best, 0);
        const Trial& best = r.trials[std::size_t(r.best)];
        EXPECT_LE(best.eval.ms, budget);
        EXPECT_EQ(best.point, bruteForce(budget));
    }
}

TEST(TuneSearch, AStartOverBudgetGivesWay) {
    const SearchResult r = coordinateDescent(space(), {4, 3, 2}, 16.0, model);
    ASSERT_GE(r.best, 0);
    EXPECT_LE(r.trials[std::size_t(r.best)].eval.ms, 16.0);
}

// A larger map (a = 1) halves the error but costs 10 ms over the budget; a smaller filter
// (b = 1) saves 10 ms for a little error. Neither alone improves on the start within the
// budget, so one change at a time stops there; the pair is the optimum.
TEST(TuneSearch, FindsAPairThatTradesTime) {
    const std::vector<Parameter> two = {{"a", {"0", "1"}}, {"b", {"0", "1"}}, {"c", {"0", "1"}}};
    auto cost = [](const Point& p) {
        return Evaluation{1.0 - 0.5 * p[0] + 0.05 * p[1] + 0.1 * p[2],
                          100.0 + 10.0 * p[0] - 10.0 * p[1] + 1.0 * p[2]};
    };
    const SearchResult r = coordinateDescent(two, {0, 0, 0}, 100.0, cost);
    ASSERT_GE(r.best, 0);
    EXPECT_EQ(r.trials[std::size_t(r.best)].point, (Point{1, 1, 0}));
    EXPECT_EQ(r.trades, 1);
    // With no budget to speak of the pair is not needed: the larger map alone.
    const SearchResult free = coordinateDescent(two, {0, 0, 0}, 1e9, cost);
    EXPECT_EQ(free.trials[std::size_t(free.best)].point, (Point{1, 0, 0}));
    EXPECT_EQ(free.trades, 0);
}

// gnomon tune records a setting the driver cannot hold as infinite error and time: the search
// goes past it to the optimum, and the front leaves it out.
TEST(TuneSearch, PointsThatCannotBeRenderedAreNeverChosen) {
    const double inf = std::numeric_limits<double>::infinity();
    auto failing = [&](const Point& p) { return p[0] == 4 ? Evaluation{inf, inf} : model(p); };
    const SearchResult r = coordinateDescent(space(), {0, 3, 0}, 1e9, failing);
    ASSERT_GE(r.best, 0);
    EXPECT_EQ(r.trials[std::size_t(r.best)].point, (Point{3, 1, 2}));
    bool triedIt = false;
    for (const Trial& t : r.trials)
        triedIt |= t.point[0] == 4;
    EXPECT_TRUE(triedIt);
    for (int i : paretoFront(r.trials))
        EXPECT_NE(r.trials[std::size_t(i)].point[0], 4);
}

TEST(TuneSearch, StopsWhenAskedAndKeepsWhatItFound) {
    int calls = 0;
    const SearchResult r = coordinateDescent(
        space(), {0, 0, 0}, 1e9,
        [&](const Point& p) {
            ++calls;
            return model(p);
        },
        3, [&] { return calls >= 4; });
    EXPECT_TRUE(r.stopped);
    EXPECT_EQ(r.trials.size(), 4u);
    EXPECT_GE(r.best, 0);
    // Asked to stop from the outset, it still has its starting point.
    const SearchResult first = coordinateDescent(
        space(), {0, 0, 0}, 1e9, [&](const Point& p) { return model(p); }, 3, [] { return true; });
    EXPECT_TRUE(first.stopped);
    ASSERT_EQ(first.trials.size(), 1u);
    EXPECT_EQ(first.best, 0);
}

TEST(TuneSearch, FrontHoldsWhatNothingBeats) {
    std::vector<Trial> t = {{{0}, {5.0, 10.0}}, {{1}, {3.0, 20.0}}, {{2}, {4.0, 25.0}},
                            {{3}, {1.0, 30.0}}, {{4}, {6.0, 5.0}},  {{5}, {3.0, 20.0}}};
    EXPECT_EQ(paretoFront(t), (std::vector<int>{4, 0, 1, 3}));
}

// ---- Choosing with the score's and the clock's noise in mind (made-up trial results)

Trial made(double error, double ms) {
    return {{}, {error, ms}};
}

// The score's noise at 512x512 pixels: what two pixels are as a share of the image.
Noise noise512() {
    Noise n;
    n.pixels = 512.0 * 512.0;
    return n;
}

TEST(TuneChoice, AnEqualErrorFoundCheaperWins) {
    // A cheaper setting (--cascades 1) with exactly the starting error: it wins.
    const std::vector<Parameter> cascades = {{"cascades", {"4", "1"}}};
    const SearchResult r = coordinateDescent(
        cascades, {0}, 25.0,
        [](const Point& p) {
            return Evaluation{0.0012, p[0] == 0 ? 25.0 : 18.9};
        },
        3, {}, noise512());
    ASSERT_GE(r.best, 0);
    EXPECT_EQ(r.trials[std::size_t(r.best)].point, (Point{1}));
    EXPECT_EQ(beatsFirst(r.trials, noise512()), 1);
}

TEST(TuneChoice, ErrorsWithinTwoPercentTieAndTheCheaperWins) {
    // From acne settings: a cheaper setting whose error ties the best one's wins.
    const std::vector<Trial> trials = {made(0.00171, 11.65), made(0.001705, 9.3)};
    EXPECT_TRUE(errorsTie(0.00171, 0.001705, noise512()));
    EXPECT_EQ(chooseBest(trials, 11.65, noise512()), 1);
    // A lower error that is not a tie still beats a cheaper one.
    const std::vector<Trial> clear = {made(0.00171, 11.65), made(0.0015, 11.6)};
    EXPECT_FALSE(errorsTie(0.00171, 0.0015, noise512()));
    EXPECT_EQ(chooseBest(clear, 11.65, noise512()), 1);
    EXPECT_EQ(chooseBest({made(0.0015, 11.6), made(0.00171, 9.0)}, 11.65, noise512()), 0);
}

TEST(TuneChoice, TwoPixelsTieWhenTheyAreMoreThanTwoPercent) {
    const Noise n = noise512();
    const double pixel = 1.0 / n.pixels;
    EXPECT_TRUE(errorsTie(10.0 * pixel, 11.5 * pixel, n));   // 1.5 pixels apart
    EXPECT_FALSE(errorsTie(10.0 * pixel, 12.5 * pixel, n));  // 2.5 pixels
    EXPECT_TRUE(errorsTie(0.0, 1.0 * pixel, n));
    EXPECT_TRUE(errorsTie(0.5, 0.509, n));  // 1.8 % of the larger, thousands of pixels
    EXPECT_FALSE(errorsTie(0.5, 0.52, n));
}

TEST(TuneChoice, AFewPercentOverTheBudgetFitsIt) {
    // A better setting a little over the budget, within the timing noise, fits it.
    const std::vector<Trial> trials = {made(0.00171, 11.68), made(0.00165, 12.08)};
    EXPECT_EQ(chooseBest(trials, 11.68, noise512()), 1);
    EXPECT_TRUE(fitsBudget(12.2, 11.68, noise512()));
    EXPECT_FALSE(fitsBudget(12.3, 11.68, noise512()));  // over 5 %
    EXPECT_EQ(chooseBest({made(0.00171, 11.68), made(0.00165, 12.5)}, 11.68, noise512()), 0);
}

TEST(TuneChoice, TiesDoNotChain) {
    // 1.019 ties 1.0 and 1.038 ties 1.019, but 1.038 is clearly worse than the least error.
    const std::vector<Trial> trials = {made(1.0, 10.0), made(1.019, 9.0), made(1.038, 8.0)};
    EXPECT_EQ(chooseBest(trials, 10.0, noise512()), 1);
}

TEST(TuneChoice, BeatingTheStartNeedsMoreThanTimingNoise) {
    const Noise n = noise512();
    EXPECT_EQ(beatsFirst({made(0.002, 10.0), made(0.002, 9.7)}, n), -1);  // 3 % faster
    EXPECT_EQ(beatsFirst({made(0.002, 10.0), made(0.002, 9.7), made(0.002, 7.5)}, n), 2);
    EXPECT_EQ(beatsFirst({made(0.002, 10.0), made(0.0015, 10.3)}, n), 1);  // better, as fast
    EXPECT_EQ(beatsFirst({made(0.002, 10.0), made(0.0015, 11.0)}, n), -1);
}

TEST(TuneChoice, TheShiftCheckAsksNoWorse) {
    const Noise n = noise512();
    EXPECT_TRUE(noWorse(0.0010, 0.0010, n));
    EXPECT_TRUE(noWorse(0.00101, 0.0010, n));  // a tie
    EXPECT_TRUE(noWorse(0.0008, 0.0010, n));
    EXPECT_FALSE(noWorse(0.0011, 0.0010, n));
}

}  // namespace
}  // namespace gnomon::search
