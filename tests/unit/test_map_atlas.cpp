// shadow::packMaps: smaller maps share layers, no two maps overlap, every map lies inside its
// layer, and a map's slot is the smallest power-of-two split that holds it.
#include <gtest/gtest.h>

#include "shadow/MapAtlas.h"

namespace gnomon {
namespace {

void expectDisjointInside(const std::vector<int>& sizes, int layerSize,
                          const std::vector<shadow::MapSlot>& slots) {
    ASSERT_EQ(slots.size(), sizes.size());
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        EXPECT_GE(slots[i].origin.x, 0);
        EXPECT_GE(slots[i].origin.y, 0);
        EXPECT_LE(slots[i].origin.x + sizes[i], layerSize) << i;
        EXPECT_LE(slots[i].origin.y + sizes[i], layerSize) << i;
        for (std::size_t j = 0; j < i; ++j) {
            if (slots[i].layer != slots[j].layer) continue;
            const bool apart = slots[i].origin.x + sizes[i] <= slots[j].origin.x ||
                               slots[j].origin.x + sizes[j] <= slots[i].origin.x ||
                               slots[i].origin.y + sizes[i] <= slots[j].origin.y ||
                               slots[j].origin.y + sizes[j] <= slots[i].origin.y;
            EXPECT_TRUE(apart) << i << " overlaps " << j;
        }
    }
}

TEST(MapAtlas, SmallerMapsShareLayers) {
    std::vector<shadow::MapSlot> slots;
    const std::vector<int> sizes = {512, 4096, 512, 1024, 512, 512, 2048, 1024};
    // 4096: a layer; 2048, 1024, 1024 and four 512s fit in a second (1/4 + 2/16 + 4/64).
    EXPECT_EQ(shadow::packMaps(sizes, 4096, slots), 2);
    expectDisjointInside(sizes, 4096, slots);
    EXPECT_EQ(slots[1].layer, 0);
    EXPECT_EQ(slots[1].origin, glm::ivec2(0));
}

TEST(MapAtlas, EqualSizesTakeALayerEach) {
    std::vector<shadow::MapSlot> slots;
    const std::vector<int> sizes(5, 1024);
    EXPECT_EQ(shadow::packMaps(sizes, 1024, slots), 5);
    for (int i = 0; i < 5; ++i)
        EXPECT_EQ(slots[std::size_t(i)].layer, i);
}

TEST(MapAtlas, SizesThatAreNotPowersOfTwo) {
    std::vector<shadow::MapSlot> slots;
    const std::vector<int> sizes = {1386, 693, 692, 600, 100, 100, 100, 100, 100, 64, 1000};
    const int layers = shadow::packMaps(sizes, 1386, slots);
    expectDisjointInside(sizes, 1386, slots);
    EXPECT_LE(layers, 3);
    // 257 maps of 64² in layers of 1024²: 16 x 16 per layer, so two layers.
    const std::vector<int> many(257, 64);
    EXPECT_EQ(shadow::packMaps(many, 1024, slots), 2);
    expectDisjointInside(many, 1024, slots);
    EXPECT_TRUE(shadow::packMaps({}, 1024, slots) == 0 && slots.empty());
}

}  // namespace
}  // namespace gnomon
