// The filterable maps (--filter evsm2, evsm4, msm): scored against the ray-traced reference
// they stay near PCF on the built-in room; their moments are made only for maps drawn (two
// blur passes each) and kept with them; on the layered scene, where a shadow edge of one
// caster crosses another's shadow, the four-moment map bleeds far less light than the two-
// moment one; and an encoded 8-bit map is refused.
#include <gtest/gtest.h>

#include "GlTest.h"
#include "gnomon/SceneFile.h"

namespace gnomon::test {
namespace {

RenderOptions small(const Scene& s, ShadowFilter f) {
    RenderOptions o = s.options;
    o.width = o.height = 192;
    o.shadow.filter = f;
    o.shadow.shadowRays = ShadowRayMode::Off;  // the filters' own answers, PCF's included
    return o;
}

class MomentFilter : public ::testing::TestWithParam<ShadowFilter> {};

TEST_P(MomentFilter, ScoresNearPcfOnTheRoom) {
    const Scene s = builtinScene("tutorial-room");
    const ScoreResult pcf = score(sharedRenderer(), s, small(s, ShadowFilter::Pcf));
    const ScoreResult moments = score(sharedRenderer(), s, small(s, GetParam()));
    // A few pixels more along the edges (their bilinear lookup is a texel wider): bounded by
    // a multiple of PCF's error plus a few edge pixels.
    EXPECT_LT(moments.overall.misclassified, 1.5 * pcf.overall.misclassified + 0.0003)
        << toString(GetParam()) << " " << moments.overall.misclassified << " against pcf "
        << pcf.overall.misclassified;
    EXPECT_EQ(moments.overall.falseShadowOutsideBand, 0.0);
    EXPECT_EQ(moments.overall.leakOutsideBand, 0.0);
}

TEST_P(MomentFilter, MomentsAreMadeOnlyForMapsDrawn) {
    const Scene s = builtinScene("tutorial-room");
    Renderer& r = sharedRenderer();
    r.invalidateShadowMaps();
    const RenderOptions o = small(s, GetParam());
    (void)r.render(s, o);
    const FrameStats first = r.lastFrameStats();
    ASSERT_GE(first.shadowPasses, 1);
    EXPECT_EQ(first.momentPasses, first.shadowPasses) << "one pass a map without a blur";
    (void)r.render(s, o);
    EXPECT_EQ(r.lastFrameStats().shadowPasses, 0);
    EXPECT_EQ(r.lastFrameStats().momentPasses, 0) << "kept maps keep their moments";
    // A blur remakes the moments of the kept maps, in two passes a map.
    RenderOptions wider = o;
    wider.shadow.momentBlur = 2;
    (void)r.render(s, wider);
    EXPECT_EQ(r.lastFrameStats().momentPasses, 2 * first.shadowPasses);
}

INSTANTIATE_TEST_SUITE_P(Filters, MomentFilter,
                         ::testing::Values(ShadowFilter::Evsm2, ShadowFilter::Evsm4,
                                           ShadowFilter::Msm),
                         [](const auto& info) { return std::string(toString(info.param)); });

// Light bleeding: with its reduction off, the two-moment bound lets light into the edge of
// the high plate's shadow, where a footprint mixes the plate's depth with the ground's far
// below; four moments (EVSM4, MSM) bound it far tighter. Counted beyond what PCF leaks at the
// same edges (it compares each texel, so it cannot bleed).
TEST(MomentFilters, FourMomentsBleedLessThanTwo) {
    const Scene s = loadSceneFile(GNOMON_EXAMPLES_DIR "/layered-casters.json");
    auto leak = [&](ShadowFilter f) {
        RenderOptions o = small(s, f);
        o.shadow.lightBleed = 0.0f;
        return score(sharedRenderer(), s, o).overall.leak;
    };
    const double pcf = leak(ShadowFilter::Pcf);
    const double two = leak(ShadowFilter::Evsm2) - pcf;
    EXPECT_GT(two, 0.0003) << "the scene no longer shows light bleeding";
    EXPECT_LT(leak(ShadowFilter::Evsm4) - pcf, 0.6 * two);
    EXPECT_LT(leak(ShadowFilter::Msm) - pcf, 0.6 * two);
}

// Point lights' cubes have no moments: with the moment filters their lookups are the default
// 3 x 3 PCF, so a scene lit by a cube alone sees exactly what PCF sees.
TEST(MomentFilters, CubesKeepTheDefaultPcf) {
    const Scene s = builtinScene("tutorial-point");
    ShadowVisibility pcf, msm;
    RenderOptions o = small(s, ShadowFilter::Pcf);
    o.shadow.pointMaps = PointMaps::Cube;
    (void)sharedRenderer().render(s, o, pcf);
    ASSERT_GT(sharedRenderer().lastFrameStats().shadowPasses, 0);
    o.shadow.filter = ShadowFilter::Msm;
    (void)sharedRenderer().render(s, o, msm);
    EXPECT_EQ(sharedRenderer().lastFrameStats().momentPasses, 0) << "the light has a cube";
    ASSERT_EQ(pcf.visibility.size(), msm.visibility.size());
    int partial = 0;
    for (std::size_t i = 0; i < pcf.visibility.size(); ++i) {
        ASSERT_EQ(pcf.visibility[i], msm.visibility[i]) << "cell " << i;
        partial += pcf.visibility[i] > 0.0f && pcf.visibility[i] < 1.0f;
    }
    EXPECT_GT(partial, 10) << "filtered edges, not one comparison";
}

TEST(MomentFilters, EncodedMapsAreRefused) {
    RenderOptions o;
    o.shadow.filter = ShadowFilter::Msm;
    o.shadow.depthFormat = DepthFormat::R8;
    const std::vector<std::string> problems = o.validate();
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_NE(problems[0].find("needs a native --depth-format"), std::string::npos) << problems[0];
}

}  // namespace
}  // namespace gnomon::test
