// gnomon score on either tracer (truth/Tracer.h): one frame rendered, its reference traced
// on Embree and on the project's own BVH as score traces it (detail::traceForScore), and
// compared as score compares (detail::compareWithReference), with good settings and with
// bad ones. Every score agrees within 1e-4 of the scored pixels (a handful of pixels in a
// 256 x 256 view).
#include <gtest/gtest.h>

#include <cstdio>

#include "GlTest.h"
#include "lab/ScoreDetail.h"

namespace gnomon::test {
namespace {

void expectSameScore(const std::string& name, const Scene& s, const RenderOptions& o) {
    const ScoreOptions so;
    const ScoreFrame drawn = renderForScore(sharedRenderer(), s, o, so);
    double seconds = 0.0;
    auto scoreOn = [&](truth::TracerKind kind) {
        const truth::Reference ref = detail::traceForScore(s, o, so, nullptr, seconds, kind);
        ScoreFrame copy = drawn;
        return detail::compareWithReference(copy, ref, s, o, so);
    };
    const ScoreResult e = scoreOn(truth::TracerKind::Embree);
    const ScoreResult b = scoreOn(truth::TracerKind::Bvh);
    std::printf(
        "%-22s pixels %ld / %ld, misclassified %.6f / %.6f, outside the band: false "
        "shadow %.6f / %.6f, leak %.6f / %.6f (Embree / BVH)\n",
        name.c_str(), e.overall.pixels, b.overall.pixels, e.overall.misclassified,
        b.overall.misclassified, e.overall.falseShadowOutsideBand, b.overall.falseShadowOutsideBand,
        e.overall.leakOutsideBand, b.overall.leakOutsideBand);
    ASSERT_GT(e.overall.pixels, 1000) << name;
    EXPECT_NEAR(double(b.overall.pixels), double(e.overall.pixels), 1e-4 * double(e.overall.pixels))
        << name;
    EXPECT_NEAR(b.overall.misclassified, e.overall.misclassified, 1e-4) << name;
    EXPECT_NEAR(b.overall.falseShadow, e.overall.falseShadow, 1e-4) << name;
    EXPECT_NEAR(b.overall.leak, e.overall.leak, 1e-4) << name;
    EXPECT_NEAR(b.overall.falseShadowOutsideBand, e.overall.falseShadowOutsideBand, 1e-4) << name;
    EXPECT_NEAR(b.overall.leakOutsideBand, e.overall.leakOutsideBand, 1e-4) << name;
    EXPECT_NEAR(b.overall.meanAbsError, e.overall.meanAbsError, 1e-4) << name;
    EXPECT_EQ(b.otherSurfacePixels, e.otherSurfacePixels) << name;
}

TEST(ScoreTracers, BvhScoresAsEmbreeDoes) {
    for (const char* name : {"tutorial-room", "mixed-lights", "book-triangle"}) {
        const Scene s = builtinScene(name);
        RenderOptions o = s.options;
        o.width = o.height = 256;
        expectSameScore(name, s, o);
    }
    // The soft reference (PCSS) and the contacts.
    const Scene s = builtinScene("tutorial-room");
    RenderOptions o = s.options;
    o.width = o.height = 256;
    o.shadow.filter = ShadowFilter::Pcss;
    o.shadow.contactLength = 0.3f;
    expectSameScore("tutorial-room pcss", s, o);
    // Errors worth the name: no bias (acne, false shadow), a huge one (leaks).
    RenderOptions acne = s.options;
    acne.width = acne.height = 256;
    acne.shadow.biasConstant = acne.shadow.biasDepthAware = 0.0f;
    acne.shadow.biasSlope = acne.shadow.biasUnits = acne.shadow.normalOffset = 0.0f;
    acne.shadow.cull = CullMode::None;
    acne.shadow.receiverPlane = false;
    expectSameScore("tutorial-room no bias", s, acne);
    const Scene thin = builtinScene("tutorial-room-thin");
    RenderOptions leak = thin.options;
    leak.width = leak.height = 256;
    leak.shadow.biasConstant = 0.2f;
    expectSameScore("tutorial-room-thin leak", thin, leak);
}

}  // namespace
}  // namespace gnomon::test
