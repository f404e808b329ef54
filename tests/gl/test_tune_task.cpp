// gnomon::TuneTask, the search in steps a web page runs between frames: stepped in slices too
// short for more than one row it makes the same trials, best, choice and shifted-view check
// as tune() does in one go, each step doing one piece of work (a reference row, a trial or a
// scoring); between steps the scene's view and lights are as given; cancelled, it gives up
// the trial whose references it is tracing and ends with what it found.
//
// Frame times differ from run to run and decide between tying errors, so the two searches
// compared here take theirs from a function of the setting (detail::FrameTimer).
#include <gtest/gtest.h>

#include "GlTest.h"
#include "lab/TuneDetail.h"

namespace gnomon::test {
namespace {

// A made-up frame time that grows with what costs time (filter, kernel, map sizes) and
// tells every setting apart, so ties in error go the same way in every run.
double madeUpMs(const RenderOptions& o, const std::vector<int>& mapSizes) {
    const ShadowOptions& s = o.shadow;
    double ms = 10.0 + 1.3 * int(s.filter) + 0.7 * s.pcfSize + 0.9 * s.mapSize / 512.0 +
                0.11 * s.normalOffset + 0.05 * s.biasDepthAware + 0.03 * s.biasSlope +
                1000.0 * s.biasConstant + 0.2 * s.receiverPlane + 0.25 * s.cascades;
    for (int size : mapSizes)
        ms += 0.3 * size / 512.0;
    return ms;
}

// tutorial-room at 48x48 with acne (no slope offset, no receiver plane), from its camera and
// a second view: a search that moves, and a best the shifted views check. The budget: the
// start's own (made-up) time, so the budget and the pairs that trade time take part.
struct Case {
    Scene scene = builtinScene("tutorial-room");
    RenderOptions start;
    TuneOptions options;
    Case() {
        start = scene.options;
        start.width = start.height = 48;
        start.shadow.biasSlope = 0.0f;
        start.shadow.receiverPlane = false;
        options.budgetMs = 0.0;
        options.maxSweeps = 3;
        options.checkShifted = true;
        options.score.threads = 1;  // a row per slice
        Camera aside = scene.camera;
        aside.eye.x += 1.5f;
        options.extraViews.push_back(aside);
    }
};

void expectSameSearch(const TuneResult& a, const TuneResult& b) {
    ASSERT_EQ(a.trials.size(), b.trials.size());
    for (std::size_t i = 0; i < a.trials.size(); ++i) {
        SCOPED_TRACE("trial " + std::to_string(i) + ": " + a.trials[i].flags);
        EXPECT_EQ(a.trials[i].flags, b.trials[i].flags);
        EXPECT_EQ(a.trials[i].mapSizes, b.trials[i].mapSizes);
        EXPECT_EQ(a.trials[i].misclassified, b.trials[i].misclassified);
        EXPECT_EQ(a.trials[i].awayFromEdges, b.trials[i].awayFromEdges);
        EXPECT_EQ(a.trials[i].error, b.trials[i].error);
        EXPECT_EQ(a.trials[i].frameMs, b.trials[i].frameMs);
        EXPECT_EQ(a.trials[i].failure, b.trials[i].failure);
    }
    EXPECT_EQ(a.best, b.best);
    EXPECT_EQ(a.chosen, b.chosen);
    EXPECT_EQ(a.front, b.front);
    EXPECT_EQ(a.beatsStart, b.beatsStart);
    EXPECT_EQ(a.sameQuality, b.sameQuality);
    EXPECT_EQ(a.budgetMs, b.budgetMs);
    EXPECT_EQ(a.sweeps, b.sweeps);
    EXPECT_EQ(a.trades, b.trades);
    EXPECT_EQ(a.interrupted, b.interrupted);
    EXPECT_EQ(a.timedOut, b.timedOut);
    EXPECT_EQ(a.shifted.done, b.shifted.done);
    EXPECT_EQ(a.shifted.holds, b.shifted.holds);
    EXPECT_EQ(a.shifted.startErrors, b.shifted.startErrors);
    EXPECT_EQ(a.shifted.bestErrors, b.shifted.bestErrors);
}

std::unique_ptr<detail::TuneTaskState> madeUpTimes(Case& c,
                                                   std::function<void(const TuneTrial&)> onTrial) {
    return std::make_unique<detail::TuneTaskState>(sharedRenderer(), c.scene, c.start, c.options,
                                                   std::move(onTrial), nullptr, madeUpMs);
}

TEST(TuneTask, SlicedIsTheSameSearchAsTune) {
    Case whole;
    std::vector<std::string> called;
    const TuneResult expected =
        detail::tuneWith(madeUpMs, sharedRenderer(), whole.scene, whole.start, whole.options,
                         nullptr, [&](const TuneTrial& t) { called.push_back(t.flags); });
    ASSERT_GE(expected.best, 1);         // the search moved off the acne...
    ASSERT_TRUE(expected.shifted.done);  // ...and checked its best on the shifted views
    EXPECT_EQ(expected.chosen, expected.best);

    Case c;
    const Camera camera = c.scene.camera;
    const std::vector<Light> lights = c.scene.lights;
    std::vector<std::string> calledSliced;
    TuneTask task(madeUpTimes(c, [&](const TuneTrial& t) { calledSliced.push_back(t.flags); }));
    EXPECT_THROW(task.result(), Error);  // not ready
    int steps = 0;
    bool done = false;
    while (!done) {
        const int trials = task.trialsDone(), checks = task.checksDone(), rows = task.rowsTraced();
        done = task.step(1e-6);
        ++steps;
        // One piece of work a step: a reference row, a trial or a scoring of the check; the
        // last step may only wrap up.
        const int pieces = (task.trialsDone() - trials) + (task.checksDone() - checks) +
                           (task.rowsTraced() - rows);
        if (done) {
            EXPECT_LE(pieces, 1) << "step " << steps;
        } else {
            EXPECT_EQ(pieces, 1) << "step " << steps;
        }
        EXPECT_EQ(c.scene.camera.eye, camera.eye);  // the view and map sizes are the scene's
        ASSERT_EQ(c.scene.lights.size(), lights.size());
        EXPECT_EQ(c.scene.lights[0].shadowMapSize, lights[0].shadowMapSize);
        ASSERT_LT(steps, 100000);
    }
    EXPECT_TRUE(task.step(1e-6));  // stays done
    const TuneResult sliced = task.result();
    expectSameSearch(expected, sliced);
    // The references traced in slices are each view's own: the start's and the best's
    // errors are gnomon::score's over the two views.
    for (const int i : {0, sliced.best}) {
        const TuneTrial& t = sliced.trials[std::size_t(i)];
        Scene s = c.scene;
        applyMapSizes(t.mapSizes, s);
        double misclassified = 0.0, away = 0.0;
        for (const Camera& view : {camera, c.options.extraViews.front()}) {
            s.camera = view;
            const ShadowScore o = score(sharedRenderer(), s, t.options, c.options.score).overall;
            misclassified += o.misclassified / 2.0;
            away += (o.falseShadowOutsideBand + o.leakOutsideBand) / 2.0;
        }
        EXPECT_DOUBLE_EQ(t.misclassified, misclassified) << t.flags;
        EXPECT_DOUBLE_EQ(t.awayFromEdges, away) << t.flags;
    }
    EXPECT_EQ(calledSliced, called);
    EXPECT_EQ(task.trialsDone(), int(sliced.trials.size()));
    EXPECT_EQ(task.checksDone(), 8);
    // Every row of the references the trials and the check used, two views each: hard, maybe
    // soft (pcss), and each of the four shifts once or twice.
    EXPECT_GE(task.rowsTraced(), (1 + 4) * 2 * 48);
    EXPECT_GT(steps, task.rowsTraced());
}

// Cancelled while it traces the references a trial needs: that trial is given up, the
// search ends at once with the trials it made, and no shifted views are checked.
TEST(TuneTask, CancelGivesUpTheTrialBeingTraced) {
    Case c;
    TuneTask task(madeUpTimes(c, {}));
    int trials = -1;
    for (int steps = 0; steps < 100000 && trials < 0; ++steps) {
        const int before = task.trialsDone(), rows = task.rowsTraced();
        ASSERT_FALSE(task.step(1e-6));
        // A row traced after the start's trial, for the next: another kind of reference.
        if (before >= 1 && task.trialsDone() == before && task.rowsTraced() > rows) {
            trials = before;
            task.cancel();
        }
    }
    ASSERT_GE(trials, 1);
    EXPECT_TRUE(task.step(1e-6));
    const TuneResult r = task.result();
    EXPECT_TRUE(r.interrupted);
    EXPECT_FALSE(r.timedOut);
    EXPECT_EQ(int(r.trials.size()), trials);
    EXPECT_FALSE(r.shifted.done);
    EXPECT_EQ(r.chosen, r.best);
}

// The public task with live timings: cancelled before its first step it still makes the
// starting settings' trial (the budget), then stops; bad options fail at once.
TEST(TuneTask, StartingTrialAlwaysFinishes) {
    Case c;
    c.options.budgetMs = 1e5;
    c.options.timedFrames = 1;
    TuneTask task(sharedRenderer(), c.scene, c.start, c.options);
    task.cancel();
    int steps = 0;
    while (!task.step(0.01))
        ASSERT_LT(++steps, 100000);
    const TuneResult r = task.result();
    ASSERT_EQ(r.trials.size(), 1u);
    EXPECT_TRUE(r.interrupted);
    EXPECT_GT(r.trials[0].frameMs, 0.0);
    EXPECT_EQ(r.best, 0);
    TuneOptions bad = c.options;
    bad.maxSweeps = 0;
    EXPECT_THROW(TuneTask(sharedRenderer(), c.scene, c.start, bad), Error);
}

}  // namespace
}  // namespace gnomon::test
