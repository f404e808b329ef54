// Shadow maps sized by need (shadow/MapSizing.h) and held to a budget (FramePlan): a ranged
// local light gets the texels its reach on screen can use, lights without a range or naming a
// size keep theirs, and a frame whose maps overflow an array's budget gets smaller maps, or a
// sentence when even the smallest do not fit.
#include <gtest/gtest.h>

#include "scene/SceneUtil.h"
#include "shadow/FramePlan.h"
#include "shadow/MapSizing.h"

namespace gnomon {
namespace {

using shadow::neededMapSize;

Camera lookingDownZ() {
    Camera c;
    c.eye = {0.0f, 0.0f, 0.0f};
    c.centre = {0.0f, 0.0f, -1.0f};
    c.fovyDegrees = 60.0f;
    return c;
}

Light spotAt(float distance, float range) {
    Light l;
    l.type = LightType::Spot;
    l.position = {0.0f, 0.0f, -distance};
    l.direction = {0.0f, -1.0f, 0.0f};
    l.range = range;
    return l;
}

TEST(MapSizing, LightsWithoutARangeKeepTheirSize) {
    Light sun;
    sun.type = LightType::Directional;
    sun.range = 5.0f;
    EXPECT_EQ(neededMapSize(sun, lookingDownZ(), 512, 512, 2048), 0);
    EXPECT_EQ(neededMapSize(spotAt(10.0f, 0.0f), lookingDownZ(), 512, 512, 2048), 0);
}

TEST(MapSizing, SizeFollowsTheReachOnScreen) {
    const Camera c = lookingDownZ();
    // Inside the range: all of the picture.
    EXPECT_EQ(neededMapSize(spotAt(1.0f, 2.0f), c, 512, 512, 2048), 1024);
    EXPECT_EQ(neededMapSize(spotAt(1.0f, 2.0f), c, 2048, 2048, 2048), 2048);
    // A sphere of radius 1 at distance 100 spans about 2 / (100 tan 30) * 256 = 8.9 pixels.
    EXPECT_EQ(neededMapSize(spotAt(100.0f, 1.0f), c, 512, 512, 2048), shadow::kMinNeededMapSize);
    // At distance 10, about 89 pixels: 178 texels wanted, 180 given (half an octave above 128).
    EXPECT_EQ(neededMapSize(spotAt(10.0f, 1.0f), c, 512, 512, 2048), 180);
    // At distance 6, about 148 pixels: 296 texels wanted, 360 given.
    EXPECT_EQ(neededMapSize(spotAt(6.0f, 1.0f), c, 512, 512, 2048), 360);
    int previous = 1 << 30;
    for (float d = 2.0f; d < 200.0f; d *= 1.3f) {
        const int size = neededMapSize(spotAt(d, 1.0f), c, 512, 512, 2048);
        EXPECT_LE(size, previous) << "farther never needs more, at " << d;
        bool step = false;
        for (int k = 0; k < 12; ++k)
            step = step || size == shadow::neededSizeStep(k);
        EXPECT_TRUE(step) << "a step of half an octave, at " << d;
        previous = size;
    }
    EXPECT_LE(neededMapSize(spotAt(1.5f, 1.0f), c, 4096, 4096, 512), 512) << "capped";
}

TEST(MapSizing, SizesGoUpInHalfOctavesThatPackIntoLayersTwiceTheirSize) {
    const int steps[] = {128, 180, 256, 360, 512, 724, 1024, 1448, 2048};
    for (int k = 0; k < 9; ++k)
        EXPECT_EQ(shadow::neededSizeStep(k), steps[k]) << k;
    // Two maps between powers of two fit across a layer two steps larger (its halves' slots).
    for (int k = 1; k < 7; k += 2)
        EXPECT_LE(2 * shadow::neededSizeStep(k), shadow::neededSizeStep(k + 2)) << k;
}

TEST(MapSizing, AFittedWindowKeepsTheWholeConesDensityWithFewerTexels) {
    using shadow::windowMapSize;
    const float whole = 2.0f / 1024.0f;                           // a whole face's texel at 1024
    EXPECT_EQ(windowMapSize(whole, whole, 1024, 0), 1024);        // the whole face
    EXPECT_EQ(windowMapSize(0.5f * whole, whole, 1024, 0), 512);  // half of it
    EXPECT_EQ(windowMapSize(0.3f * whole, whole, 1024, 0), 512);  // 307 texels: 512
    EXPECT_EQ(windowMapSize(0.2f * whole, whole, 1024, 0), 256);  // 205 texels: 256
    EXPECT_EQ(windowMapSize(0.01f * whole, whole, 1024, 0), shadow::kMinNeededMapSize);
    EXPECT_EQ(windowMapSize(0.0f, whole, 1024, 0), 1024);  // no frame: the size asked
    // A size held from an earlier frame stays while it is fine enough and no larger.
    EXPECT_EQ(windowMapSize(0.2f * whole, whole, 1024, 512), 512);
    EXPECT_EQ(windowMapSize(0.5f * whole, whole, 1024, 256), 512);  // too coarse now
    EXPECT_EQ(windowMapSize(0.2f * whole, whole, 512, 1024), 128);  // held over the size asked
    EXPECT_EQ(windowMapSize(0.4f * whole, whole, 724, 0), 362);     // halves of a half octave
}

// Ranged spots over a floor, as in gnomon bench's local-lights sweep.
Scene rangedSpots(int n) {
    Scene s = builtinScene("tutorial-room");
    s.lights.clear();
    for (int i = 0; i < n; ++i) {
        Light l = spotAt(0.0f, 3.0f);
        l.position = {-4.0f + 8.0f * float(i % 8) / 7.0f, 2.5f, -4.0f + float(i / 8)};
        l.outerConeDegrees = 40.0f;
        l.innerConeDegrees = 30.0f;
        s.lights.push_back(l);
    }
    return s;
}

std::vector<shadow::SceneItem> itemsOf(const Scene& s) {
    const std::vector<Aabb> boxes = meshBounds(s);
    std::vector<shadow::SceneItem> items;
    for (std::uint32_t i = 0; i < s.objects.size(); ++i) {
        shadow::SceneItem item;
        item.bounds = boxes[s.objects[i].mesh].transformed(s.objects[i].worldFromModelAt(0.0));
        item.dataHash = 1000 + i;
        item.object = i;
        item.drawable = true;
        item.casts = s.objects[i].castsShadows;
        item.receives = s.objects[i].receivesShadows;
        items.push_back(item);
    }
    return items;
}

int largestMap(const shadow::FramePlan& plan) {
    int largest = 0;
    for (const shadow::ShadowedLight& sl : plan.shadowed())
        largest = std::max(largest, sl.mapSize);
    return largest;
}

TEST(MapSizing, PlanHoldsTheMapsToTheBudget) {
    const Scene s = rangedSpots(32);
    const std::vector<shadow::SceneItem> items = itemsOf(s);
    shadow::PlanScene scene{&items, Aabb(), 1, 7};
    for (const shadow::SceneItem& item : items)
        scene.bounds.extend(item.bounds);
    shadow::FramePlan free;
    free.plan(s, s.options, scene, nullptr, nullptr, {});
    ASSERT_EQ(free.shadowed().size(), 32u);
    EXPECT_TRUE(free.budgetNote().empty());
    const int unbudgeted = largestMap(free);
    EXPECT_LT(unbudgeted, kDefaultShadowMapSize) << "sized by need, under the default";

    // A quarter of what they took: smaller maps, every light still shadowed, no note.
    shadow::FramePlan held;
    held.setMapBudget(shadow::largestArrayBytes(free.layout()) / 4, 2048);
    held.plan(s, s.options, scene, nullptr, nullptr, {});
    EXPECT_EQ(held.shadowed().size(), 32u);
    EXPECT_LT(largestMap(held), unbudgeted);
    EXPECT_LE(shadow::largestArrayBytes(held.layout()),
              shadow::largestArrayBytes(free.layout()) / 4);
    EXPECT_TRUE(held.budgetNote().empty());

    // Not even 128² each fits: one sentence says so.
    shadow::FramePlan tiny;
    tiny.setMapBudget(1024, 2048);
    tiny.plan(s, s.options, scene, nullptr, nullptr, {});
    EXPECT_NE(tiny.budgetNote().find("32 shadow maps"), std::string::npos) << tiny.budgetNote();

    // A size the options name is kept whatever the budget.
    RenderOptions named = s.options;
    named.shadow.mapSize = 1024;
    shadow::FramePlan fixed;
    fixed.setMapBudget(shadow::largestArrayBytes(free.layout()) / 4, 2048);
    fixed.plan(s, named, scene, nullptr, nullptr, {});
    EXPECT_EQ(largestMap(fixed), 1024);
}

}  // namespace
}  // namespace gnomon
