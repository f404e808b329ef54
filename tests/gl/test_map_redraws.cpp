// The redraw budget (--map-redraws): when moving lights change many maps in a frame, at most
// the budget's number are drawn again, the others keep the map drawn earlier and are read
// through the camera it was drawn with; every map gets its turn, and once the lights stop the
// picture becomes the one drawn without a budget.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "GlTest.h"

namespace gnomon::test {
namespace {

// mixed-lights with every spot and point light moved `by` along x.
Scene movedBy(const Scene& base, float by) {
    Scene s = base;
    for (Light& l : s.lights) {
        if (l.type == LightType::Spot || l.type == LightType::Point) l.position.x += by;
    }
    return s;
}

// The share of pixels whose colours differ by more than `tolerance` in some channel.
double differing(const Image& a, const Image& b, int tolerance) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        n += std::abs(int(a.pixels[i]) - int(b.pixels[i])) > tolerance ? 1 : 0;
    return double(n) / double(a.pixels.size());
}

int localMaps(const Scene& s, Renderer& r) {
    int n = 0;
    for (const MapUsage& u : r.mapUsage()) {
        const LightType t = s.lights[std::size_t(u.light)].type;
        n += t == LightType::Spot || t == LightType::Point ? 1 : 0;
    }
    return n;
}

// Point lights' maps as faces of their own, and as cubes (whose lookups start from where the
// cube was drawn).
class MapRedraws : public testing::TestWithParam<PointMaps> {};

TEST_P(MapRedraws, MovingLightsRedrawAtMostTheBudgetAndCatchUp) {
    const Scene base = builtinScene("mixed-lights");
    RenderOptions o = base.options;
    o.width = o.height = 96;
    o.shadow.pointMaps = GetParam();
    o.shadow.mapRedraws = 3;
    Renderer& r = sharedRenderer();
    r.invalidateShadowMaps();
    r.render(base, o);  // nothing held: every map is drawn, whatever the budget
    const int maps = r.lastFrameStats().shadowMaps, local = localMaps(base, r);
    EXPECT_EQ(r.lastFrameStats().shadowPasses, maps);
    EXPECT_EQ(r.lastFrameStats().shadowMapsWaiting, 0);
    ASSERT_GT(local, 6);

    const Scene moved = movedBy(base, 0.05f);
    RenderOptions unbudgeted = o;
    unbudgeted.shadow.mapRedraws = 0;
    const Image first = r.render(moved, o);
    EXPECT_EQ(r.lastFrameStats().shadowPasses, 3);
    EXPECT_EQ(r.lastFrameStats().shadowMapsWaiting, local - 3);
    // The maps that wait show where their lights were: nearly the picture of where they are.
    const Image wanted = [&] {
        Renderer& other = r;
        other.invalidateShadowMaps();
        const Image img = other.render(moved, unbudgeted);
        return img;
    }();
    EXPECT_LT(differing(first, wanted, 24), 0.03);

    // Lights moving on: each frame draws three, and no map waits longer than the turns it
    // takes to draw them all, and the head start of larger maps (a frame per doubling).
    r.invalidateShadowMaps();
    r.render(base, o);
    std::vector<int> waited(std::size_t(maps), 0);
    int longest = 0;
    for (int frame = 1; frame <= 12; ++frame) {
        r.render(movedBy(base, 0.02f * float(frame)), o);
        EXPECT_LE(r.lastFrameStats().shadowPasses, 3);
        const std::vector<MapUsage> usage = r.mapUsage();
        ASSERT_EQ(usage.size(), waited.size());
        for (std::size_t i = 0; i < usage.size(); ++i) {
            waited[i] = usage[i].waiting ? waited[i] + 1 : 0;
            longest = std::max(longest, waited[i]);
        }
    }
    EXPECT_LE(longest, (local + 2) / 3 + 4);

    // The lights stop: within that many frames every map has caught up, and the picture is
    // the one drawn without a budget.
    const Scene still = movedBy(base, 0.24f);
    Image last;
    for (int frame = 0; frame <= (local + 2) / 3; ++frame)
        last = r.render(still, o);
    EXPECT_EQ(r.lastFrameStats().shadowMapsWaiting, 0);
    EXPECT_EQ(r.lastFrameStats().shadowPasses, 0);
    r.invalidateShadowMaps();
    const Image fresh = r.render(still, unbudgeted);
    EXPECT_EQ(differing(last, fresh, 0), 0.0);
}

INSTANTIATE_TEST_SUITE_P(PointMaps, MapRedraws, testing::Values(PointMaps::Faces, PointMaps::Cube),
                         [](const testing::TestParamInfo<PointMaps>& p) {
                             return p.param == PointMaps::Faces ? "Faces" : "Cube";
                         });

}  // namespace
}  // namespace gnomon::test
