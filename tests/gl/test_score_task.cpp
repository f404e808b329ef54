// gnomon::ScoreTask, the score in slices a web page steps between frames: stepped a row at a
// time it gives scoreFrame's result number for number and pixel for pixel (hard and soft
// references, the explained errors), its progress rises a row per step to every row, the
// comparison waits for a step of its own once the slice's time is up, a cancelled task
// throws, and the task keeps its own copy of the scene.
#include <gtest/gtest.h>

#include "GlTest.h"

namespace gnomon::test {
namespace {

void expectSame(const ShadowScore& a, const ShadowScore& b) {
    EXPECT_EQ(a.light, b.light);
    EXPECT_EQ(a.type, b.type);
    EXPECT_EQ(a.pixels, b.pixels);
    EXPECT_EQ(a.bandPixels, b.bandPixels);
    EXPECT_EQ(a.misclassified, b.misclassified);
    EXPECT_EQ(a.falseShadow, b.falseShadow);
    EXPECT_EQ(a.leak, b.leak);
    EXPECT_EQ(a.falseShadowOutsideBand, b.falseShadowOutsideBand);
    EXPECT_EQ(a.leakOutsideBand, b.leakOutsideBand);
    EXPECT_EQ(a.meanAbsError, b.meanAbsError);
    EXPECT_EQ(a.contactPixels, b.contactPixels);
    EXPECT_EQ(a.contactLeak, b.contactLeak);
}

void expectSame(const ScoreResult& a, const ScoreResult& b) {
    expectSame(a.overall, b.overall);
    ASSERT_EQ(a.lights.size(), b.lights.size());
    for (std::size_t i = 0; i < a.lights.size(); ++i)
        expectSame(a.lights[i], b.lights[i]);
    EXPECT_EQ(a.tint.cells, b.tint.cells);
    EXPECT_EQ(a.tint.meanError, b.tint.meanError);
    EXPECT_EQ(a.softReference, b.softReference);
    EXPECT_EQ(a.otherSurfacePixels, b.otherSurfacePixels);
    EXPECT_EQ(a.contactRange, b.contactRange);
    EXPECT_EQ(a.render.pixels, b.render.pixels);
    EXPECT_EQ(a.errors.pixels, b.errors.pixels);
    EXPECT_EQ(a.tintErrors.pixels, b.tintErrors.pixels);
    ASSERT_EQ(a.errorCells.size(), b.errorCells.size());
    for (std::size_t i = 0; i < a.errorCells.size(); ++i) {
        const ErrorCell &x = a.errorCells[i], &y = b.errorCells[i];
        EXPECT_TRUE(x.x == y.x && x.y == y.y && x.light == y.light && x.leak == y.leak &&
                    x.inBand == y.inBand && x.occluderDistance == y.occluderDistance &&
                    x.visibility == y.visibility)
            << "error cell " << i;
    }
    EXPECT_EQ(a.causes.falseShadowOther, b.causes.falseShadowOther);
    EXPECT_EQ(a.causes.leakOther, b.causes.leakOther);
}

struct Case {
    Scene scene;
    RenderOptions options;
};

// tutorial-room with acne (no slope offset, no receiver plane, maps alone), and tutorial-spot with
// PCSS and a small map (the soft reference): both with errors to count and explain.
std::vector<Case> cases() {
    Case acne{builtinScene("tutorial-room"), {}};
    acne.options = acne.scene.options;
    acne.options.shadow.biasSlope = 0.0f;
    acne.options.shadow.receiverPlane = false;
    acne.options.shadow.shadowRays = ShadowRayMode::Off;  // rays where unsure mend acne
    Case soft{builtinScene("tutorial-spot"), {}};
    soft.options = soft.scene.options;
    soft.options.shadow.filter = ShadowFilter::Pcss;
    soft.options.shadow.mapSize = 64;  // blocky: errors to count
    std::vector<Case> out = {acne, soft};
    for (Case& c : out) {
        c.options.width = 72;
        c.options.height = 54;
    }
    return out;
}

TEST(ScoreTask, RowBySliceIsScoreFrame) {
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.scene.name);
        ScoreOptions so;
        so.explain = true;
        so.softSamples = 16;
        const ScoreFrame frame = renderForScore(sharedRenderer(), c.scene, c.options, so);
        const ScoreResult whole = scoreFrame(frame, c.scene, c.options, so);
        EXPECT_GT(whole.overall.misclassified, 0.0);
        EXPECT_GT(whole.errorCells.size(), 10u);

        ScoreOptions one = so;
        one.threads = 1;
        ScoreTask task(frame, c.scene, c.options, one);
        EXPECT_EQ(task.rows(), 54);
        EXPECT_EQ(task.rowsDone(), 0);
        EXPECT_THROW(task.result(), Error);  // not ready
        // Slices too short for more than one row: a row per step, then the comparison in a
        // step of its own.
        int steps = 0;
        bool ready = false;
        while (!ready) {
            const int before = task.rowsDone();
            ready = task.step(1e-6);
            ++steps;
            if (!ready) {
                EXPECT_EQ(task.rowsDone(), std::min(before + 1, 54));
            }
            ASSERT_LE(steps, 55);
        }
        EXPECT_EQ(steps, 55);
        EXPECT_EQ(task.rowsDone(), 54);
        EXPECT_TRUE(task.step(1e-6));  // stays ready
        const ScoreResult sliced = task.result();
        expectSame(whole, sliced);
        EXPECT_EQ(sliced.softReference, c.options.shadow.filter == ShadowFilter::Pcss);
        EXPECT_GT(sliced.traceSeconds, 0.0);
    }
}

// Steps of ample time: the first traces every row and compares at once.
TEST(ScoreTask, OneLongStepIsEnough) {
    const Case c = cases().front();
    const ScoreFrame frame = renderForScore(sharedRenderer(), c.scene, c.options);
    ScoreTask task(frame, c.scene, c.options);
    EXPECT_TRUE(task.step(3600.0));
    expectSame(scoreFrame(frame, c.scene, c.options), task.result());
}

// The task scores the scene as it was given: edits after it was made change nothing.
TEST(ScoreTask, KeepsItsOwnScene) {
    const Case c = cases().front();
    Scene scene = c.scene;
    const ScoreFrame frame = renderForScore(sharedRenderer(), scene, c.options);
    ScoreTask task(frame, scene, c.options);
    ASSERT_FALSE(task.step(1e-6));
    scene.lights.front().direction = -scene.lights.front().direction;  // the sun from below
    scene.objects.pop_back();
    while (!task.step(1e-3)) {
    }
    expectSame(scoreFrame(frame, c.scene, c.options), task.result());
}

TEST(ScoreTask, CancelledTaskThrows) {
    const Case c = cases().front();
    ScoreOptions so;
    so.threads = 1;
    ScoreTask task(renderForScore(sharedRenderer(), c.scene, c.options), c.scene, c.options, so);
    ASSERT_FALSE(task.step(1e-6));
    task.cancel();
    EXPECT_THROW(task.step(1e-6), Error);
    EXPECT_EQ(task.rowsDone(), 1);
    EXPECT_THROW(task.step(1.0), Error);  // and so does every later step
    // Cancelled with every row traced, before the comparison.
    ScoreTask traced(renderForScore(sharedRenderer(), c.scene, c.options), c.scene, c.options, so);
    while (traced.rowsDone() < traced.rows())
        ASSERT_FALSE(traced.step(1e-6));
    traced.cancel();
    EXPECT_THROW(traced.step(1.0), Error);
    // Bad score options fail at once, as scoreFrame's do.
    ScoreOptions bad;
    bad.softSamples = 0;
    EXPECT_THROW(ScoreTask(ScoreFrame{}, c.scene, c.options, bad), Error);
}

// scoreFrame, the task stepped to the end, still counts its rows in a ScoreProgress.
TEST(ScoreTask, ScoreFrameCountsItsRows) {
    const Case c = cases().front();
    ScoreProgress progress;
    progress.rowsDone = 7;
    scoreFrame(renderForScore(sharedRenderer(), c.scene, c.options), c.scene, c.options, {},
               &progress);
    EXPECT_EQ(progress.rows.load(), 54);
    EXPECT_EQ(progress.rowsDone.load(), 54);
    progress.cancel = true;
    EXPECT_THROW(scoreFrame(renderForScore(sharedRenderer(), c.scene, c.options), c.scene,
                            c.options, {}, &progress),
                 Error);
}

}  // namespace
}  // namespace gnomon::test
