// gnomon score's explanation of its errors (src/truth/ErrorCauses.h): every misclassified
// pixel x light listed once, the ones away from edges counted by cause, and the facts each
// carries hold: a leak has an occluder along its shadow ray, a false shadow none, and a
// larger constant tolerance leaks past occluders as much farther.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "GlTest.h"

namespace gnomon::test {
namespace {

ScoreResult explained(const Scene& s, const RenderOptions& o) {
    ScoreOptions so;
    so.explain = true;
    return score(sharedRenderer(), s, o, so);
}

// The cells are the misclassified pixel x light pairs, and the causes split the ones away
// from edges without remainder.
void expectConsistent(const ScoreResult& r) {
    const double n = double(r.overall.pixels);
    long leaks = 0, falseShadows = 0, leaksOut = 0, falseOut = 0;
    for (const ErrorCell& e : r.errorCells) {
        (e.leak ? leaks : falseShadows) += 1;
        if (!e.inBand) (e.leak ? leaksOut : falseOut) += 1;
        if (e.leak) {
            EXPECT_GT(e.occluderDistance, 0.0f) << "a leak at " << e.x << "," << e.y;
            EXPECT_GE(e.visibility, 0.5f);
        } else {
            EXPECT_EQ(e.occluderDistance, -1.0f) << "a false shadow at " << e.x << "," << e.y;
            EXPECT_LT(e.visibility, 0.5f);
        }
    }
    EXPECT_NEAR(double(leaks), r.overall.leak * n, 0.5);
    EXPECT_NEAR(double(falseShadows), r.overall.falseShadow * n, 0.5);
    EXPECT_NEAR(double(leaksOut), r.overall.leakOutsideBand * n, 0.5);
    EXPECT_NEAR(double(falseOut), r.overall.falseShadowOutsideBand * n, 0.5);
    const ErrorCauses& k = r.causes;
    EXPECT_EQ(k.leakGrazing + k.leakContact + k.leakOther, leaksOut);
    EXPECT_EQ(k.falseShadowGrazing + k.falseShadowOther, falseOut);
}

// The farthest occluder a leak has along its shadow ray. tutorial-room-thin with a constant
// tolerance of a fraction of the sun map's depth: shadows detach from the thin walls and
// boxes that cast them (peter-panning), and the receivers whose occluder lies within that
// depth of them leak. None of them is grazed by the light (a sun high over a floor).
float farthestLeakOccluder(float tolerance) {
    const Scene s = builtinScene("tutorial-room-thin");
    RenderOptions o = s.options;
    o.width = o.height = 256;
    o.shadow.biasConstant = tolerance;
    const ScoreResult r = explained(s, o);
    EXPECT_GT(r.overall.leak, 0.002) << "tolerance " << tolerance;
    expectConsistent(r);
    EXPECT_EQ(r.causes.leakGrazing, 0);
    float farthest = 0.0f;
    for (const ErrorCell& e : r.errorCells)
        if (e.leak) farthest = std::max(farthest, e.occluderDistance);
    return farthest;
}

// A tolerance three times larger reaches occluders about as much farther.
TEST(ErrorCauses, DetachedShadowsLeakAsFarAsTheTolerance) {
    const float near = farthestLeakOccluder(0.1f), far = farthestLeakOccluder(0.3f);
    EXPECT_GT(far, 2.0f * near) << near << " at 0.1, " << far << " at 0.3";
    EXPECT_LT(far, 4.0f * near) << near << " at 0.1, " << far << " at 0.3";
}

// With no tolerance at all the floor shadows itself (acne): false shadow, no occluder.
TEST(ErrorCauses, AcneIsFalseShadowWithNoOccluder) {
    const Scene s = builtinScene("tutorial-room");
    RenderOptions o = s.options;
    o.width = o.height = 128;
    o.shadow.biasConstant = o.shadow.biasDepthAware = 0.0f;
    o.shadow.biasSlope = o.shadow.biasUnits = o.shadow.normalOffset = 0.0f;
    o.shadow.cull = CullMode::None;
    o.shadow.receiverPlane = false;
    o.shadow.shadowRays = ShadowRayMode::Off;  // the maps' acne
    const ScoreResult r = explained(s, o);
    ASSERT_GT(r.overall.falseShadowOutsideBand, 0.05);
    expectConsistent(r);
    EXPECT_GT(r.causes.falseShadowOther + r.causes.falseShadowGrazing, 0);
}

// A score without explain lists nothing (a search's trials do not pay for the rays); the CSV
// has a header and one row per cell, and score.json the counts.
TEST(ErrorCauses, OnlyWhenAskedAndCsvHasEveryCell) {
    const Scene s = builtinScene("tutorial-room-thin");
    RenderOptions o = s.options;
    o.width = o.height = 128;
    o.shadow.biasConstant = 0.2f;
    EXPECT_TRUE(score(sharedRenderer(), s, o).errorCells.empty());
    const ScoreResult r = explained(s, o);
    ASSERT_FALSE(r.errorCells.empty());
    std::istringstream csv(errorCellsCsv(r));
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line.rfind("x,y,light,kind,in_band,light_cosine,occluder_distance", 0), 0u);
    std::size_t rows = 0;
    while (std::getline(csv, line)) {
        ++rows;
        EXPECT_EQ(std::count(line.begin(), line.end(), ','), 9) << line;
    }
    EXPECT_EQ(rows, r.errorCells.size());
    const nlohmann::json j = nlohmann::json::parse(toJson(r, s.name, o));
    const ErrorCauses& k = r.causes;
    EXPECT_EQ(j["causes_outside_band"]["leak_other"], k.leakOther);
    EXPECT_EQ(j["causes_outside_band"]["leak_contact"], k.leakContact);
    EXPECT_EQ(j["causes_outside_band"]["false_shadow_other"], k.falseShadowOther);
}

}  // namespace
}  // namespace gnomon::test
