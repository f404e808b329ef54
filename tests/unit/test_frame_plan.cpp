// shadow::FramePlan without GL: every decision the passes consume is in the plan when it is
// made (records' map fields, map places, casters per map), and which maps are drawn again
// follows what the arrays hold.
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "scene/SceneUtil.h"
#include "shadow/FramePlan.h"

namespace gnomon {
namespace {

using shadow::FramePlan;
using shadow::ShadowedLight;

// The scene's objects as the plan sees them: one item per object, at time 0.
std::vector<shadow::SceneItem> itemsOf(const Scene& s) {
    const std::vector<Aabb> boxes = meshBounds(s);
    std::vector<shadow::SceneItem> items;
    for (std::uint32_t i = 0; i < s.objects.size(); ++i) {
        const Object& o = s.objects[i];
        shadow::SceneItem item;
        item.bounds = boxes[o.mesh].transformed(o.worldFromModelAt(0.0));
        item.dataHash = 1000 + i;
        item.object = i;
        item.drawable = !s.meshes[o.mesh].indices.empty();
        item.casts = o.castsShadows;
        item.receives = o.receivesShadows;
        items.push_back(item);
    }
    return items;
}

shadow::PlanScene planSceneOf(const std::vector<shadow::SceneItem>& items, std::uint64_t revision) {
    shadow::PlanScene p{&items, Aabb(), revision, 7};
    for (const shadow::SceneItem& item : items)
        p.bounds.extend(item.bounds);
    return p;
}

// What the arrays hold once every map of `plan` was drawn.
shadow::HeldMaps heldAfterDrawing(const FramePlan& plan) {
    shadow::HeldMaps held;
    held.layout = plan.layout();
    held.cubes.resize(std::size_t(plan.layout().cubes));
    for (const ShadowedLight& sl : plan.shadowed()) {
        if (sl.frame.kind == shadow::FrameKind::Cube) {
            held.cubes[std::size_t(sl.layer)] = sl.key;
        } else {
            held.maps2D.push_back(sl.key);
        }
    }
    return held;
}

TEST(FramePlan, RecordsKnowTheirMapsWhenPlanned) {
    const Scene s = builtinScene("mixed-lights");
    const std::vector<shadow::SceneItem> items = itemsOf(s);
    FramePlan plan;
    plan.plan(s, s.options, planSceneOf(items, 1), nullptr, nullptr, {});
    ASSERT_GE(plan.shadowed().size(), 10u);
    const shadow::MapLayout& layout = plan.layout();
    ASSERT_GT(layout.layers2D, 0);
    ASSERT_GT(layout.cubes, 0);
    std::vector<glm::ivec4> squares;  // 2D maps: x, y, layer, size
    for (const ShadowedLight& sl : plan.shadowed()) {
        const GpuLight& g = plan.records()[std::size_t(sl.record)];
        EXPECT_EQ(g.layer, sl.layer);
        EXPECT_EQ(g.texelWorldSize, sl.frame.texelWorldSize);
        if (sl.frame.kind == shadow::FrameKind::Cube) {
            EXPECT_EQ(sl.mapSize, layout.sizeCube) << "cubes share one size";
            EXPECT_LT(sl.layer, layout.cubes);
            EXPECT_FLOAT_EQ(g.texelUv, 1.0f / float(layout.sizeCube));
            continue;
        }
        EXPECT_LT(sl.layer, layout.layers2D);
        EXPECT_FLOAT_EQ(g.uvScale, float(sl.mapSize) / float(layout.size2D));
        EXPECT_EQ(g.mapCorner, glm::vec2(sl.origin) / float(layout.size2D));
        EXPECT_LE(sl.origin.x + sl.mapSize, layout.size2D);
        EXPECT_LE(sl.origin.y + sl.mapSize, layout.size2D);
        for (const glm::ivec4& q : squares) {
            const bool apart = q.z != sl.layer || q.x + q.w <= sl.origin.x ||
                               sl.origin.x + sl.mapSize <= q.x || q.y + q.w <= sl.origin.y ||
                               sl.origin.y + sl.mapSize <= q.y;
            EXPECT_TRUE(apart) << "two maps overlap in layer " << q.z;
        }
        squares.push_back({sl.origin.x, sl.origin.y, sl.layer, sl.mapSize});
    }
}

TEST(FramePlan, CastersOutsideALightsVolumeAreLeftOut) {
    const Scene s = builtinScene("mixed-lights");
    const std::vector<shadow::SceneItem> items = itemsOf(s);
    FramePlan plan;
    plan.plan(s, s.options, planSceneOf(items, 1), nullptr, nullptr, {});
    EXPECT_GT(plan.castersCulled(), 0) << "twelve narrow spots see only part of the scene";
    for (const ShadowedLight& sl : plan.shadowed()) {
        const shadow::LightVolume volume(sl);
        std::vector<std::uint32_t> expected;
        for (std::uint32_t i = 0; i < items.size(); ++i) {
            if (items[i].casts && items[i].drawable && !volume.outside(items[i].bounds))
                expected.push_back(i);
        }
        const auto first = plan.casters().begin() + sl.firstCaster;
        EXPECT_EQ(std::vector<std::uint32_t>(first, first + sl.casterCount), expected)
            << "light " << sl.light;
    }
}

TEST(FramePlan, DrawsAgainOnlyWhatTheHeldMapsCannotServe) {
    const Scene s = builtinScene("mixed-lights");
    std::vector<shadow::SceneItem> items = itemsOf(s);
    FramePlan plan;
    plan.plan(s, s.options, planSceneOf(items, 1), nullptr, nullptr, {});
    for (const ShadowedLight& sl : plan.shadowed())
        EXPECT_TRUE(sl.redraw) << "nothing is held yet";

    // The same frame over maps drawn from it: all kept, the plan itself reused.
    const shadow::HeldMaps held = heldAfterDrawing(plan);
    plan.plan(s, s.options, planSceneOf(items, 1), nullptr, nullptr, held);
    for (const ShadowedLight& sl : plan.shadowed())
        EXPECT_FALSE(sl.redraw) << "light " << sl.light;

    // One caster moves: exactly the maps whose volumes hold it are redrawn. The caster seen
    // by the fewest maps (but some).
    auto mapsSeeing = [&](std::uint32_t item) {
        std::vector<int> maps;
        for (std::size_t m = 0; m < plan.shadowed().size(); ++m) {
            const ShadowedLight& sl = plan.shadowed()[m];
            const auto first = plan.casters().begin() + sl.firstCaster;
            if (std::find(first, first + sl.casterCount, item) != first + sl.casterCount)
                maps.push_back(int(m));
        }
        return maps;
    };
    std::uint32_t moved = 0;
    std::vector<int> seeing(plan.shadowed().size() + 1);
    for (std::uint32_t i = 0; i < items.size(); ++i) {
        const std::vector<int> maps = mapsSeeing(i);
        if (!maps.empty() && maps.size() < seeing.size()) {
            moved = i;
            seeing = maps;
        }
    }
    ASSERT_LT(seeing.size(), plan.shadowed().size()) << "some map must not see the caster";
    items[moved].dataHash += 1;  // its record changed, its box did not
    plan.plan(s, s.options, planSceneOf(items, 2), nullptr, nullptr, held);
    for (std::size_t m = 0; m < plan.shadowed().size(); ++m) {
        const bool sees = std::find(seeing.begin(), seeing.end(), int(m)) != seeing.end();
        EXPECT_EQ(plan.shadowed()[m].redraw, sees) << "map " << m;
    }

    // Arrays remade at another size hold nothing.
    shadow::HeldMaps other = held;
    other.layout.size2D *= 2;
    plan.plan(s, s.options, planSceneOf(items, 2), nullptr, nullptr, other);
    for (const ShadowedLight& sl : plan.shadowed()) {
        if (sl.frame.kind != shadow::FrameKind::Cube) {
            EXPECT_TRUE(sl.redraw);
        }
    }
}

}  // namespace
}  // namespace gnomon
