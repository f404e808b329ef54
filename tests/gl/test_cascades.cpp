// Cascaded shadow maps on the GPU: with 2 to 4 cascades the room's shadows are
// still exactly where its geometry says (selection, blend band and depth reach are right),
// and the debug view shows each visible cascade in its own tint.
#include <gtest/gtest.h>

#include <set>

#include "GlTest.h"
#include "ShadowCheck.h"

namespace gnomon::test {
namespace {

class Cascaded : public testing::TestWithParam<int> {};

TEST_P(Cascaded, ShadowsWhereGeometrySays) {
    const Scene s = builtinScene("tutorial-room");
    RenderOptions o = s.options;
    o.shadow.cascades = GetParam();
    o.shadow.cascadeLambda = 0.5f;
    expectShadowsMatchGeometry(s, o);
    sharedRenderer().render(s, o);  // the check's last render had shadows off
    EXPECT_EQ(sharedRenderer().lastFrameStats().shadowMaps, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Counts, Cascaded, testing::Values(2, 3, 4));

TEST(Cascaded, DebugViewTintsEachVisibleCascade) {
    const Scene s = builtinScene("tutorial-room");
    RenderOptions o = s.options;
    o.width = o.height = 128;
    o.shadow.cascades = 4;
    o.shadow.cascadeLambda = 0.0f;  // uniform splits: several cascades on the floor
    o.shadow.cascadeBlend = 0.0f;
    const Image plain = sharedRenderer().render(s, o);
    o.debugView = DebugView::Cascades;
    const Image tinted = sharedRenderer().render(s, o);
    // Classify tinted floor pixels by which channel the tint raised most.
    std::set<int> dominant;
    for (int y = 64; y < 128; ++y) {
        for (int x = 0; x < 128; ++x) {
            int gain[3];
            for (int c = 0; c < 3; ++c)
                gain[c] = tinted.at(x, y)[c] - plain.at(x, y)[c];
            if (std::max({gain[0], gain[1], gain[2]}) < 10) continue;
            dominant.insert(int(std::max_element(gain, gain + 3) - gain));
        }
    }
    EXPECT_GE(dominant.size(), 2u) << "expected at least two cascades' tints on the floor";
}

}  // namespace
}  // namespace gnomon::test
