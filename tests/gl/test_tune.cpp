// gnomon tune on a scene whose optimum is known: tutorial-room started with one tolerance
// off (no slope-scaled offset and no receiver plane: acne over a third of the pixels) must
// find its way back to a setting that is right almost everywhere, within the budget, and
// report every trial on the front or behind it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "GlTest.h"

namespace gnomon::test {
namespace {

TEST(Tune, FindsTheKnownRemedyForAcne) {
    Scene s = builtinScene("tutorial-room");
    RenderOptions start = s.options;
    start.width = start.height = 96;
    start.shadow.biasSlope = 0.0f;
    start.shadow.receiverPlane = false;
    TuneOptions o;
    o.budgetMs = 1e5;  // the error alone decides here; the budget has its own unit test
    o.timedFrames = 1;
    o.maxSweeps = 1;
    const Camera camera = s.camera;
    const TuneResult r = tune(sharedRenderer(), s, start, o);
    EXPECT_EQ(s.camera.eye, camera.eye);  // the view is put back
    ASSERT_GE(r.best, 1);
    const TuneTrial& first = r.trials.front();
    const TuneTrial& best = r.trials[std::size_t(r.best)];
    EXPECT_TRUE(first.flags.empty());
    EXPECT_GT(first.misclassified, 0.2);  // the acne we started with
    EXPECT_LT(best.misclassified, 0.002);
    EXPECT_LT(best.awayFromEdges, 0.001);
    EXPECT_FALSE(best.flags.empty());
    // The front: fastest first, each better than every faster trial.
    ASSERT_FALSE(r.front.empty());
    for (std::size_t i = 1; i < r.front.size(); ++i) {
        const TuneTrial& a = r.trials[std::size_t(r.front[i - 1])];
        const TuneTrial& b = r.trials[std::size_t(r.front[i])];
        EXPECT_LE(a.frameMs, b.frameMs);
        EXPECT_LT(b.error, a.error);
    }
    const nlohmann::json j = nlohmann::json::parse(toJson(r, "tutorial-room"));
    EXPECT_EQ(j["trials"].size(), r.trials.size());
    EXPECT_EQ(j["best"].get<int>(), r.best);
}

}  // namespace
}  // namespace gnomon::test
