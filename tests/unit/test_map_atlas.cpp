// shadow::MapPacker: maps share layers, no two maps overlap, every map lies inside its layer,
// the layer size chosen takes the fewest texels, and maps keep their places from one packing
// to the next while their sizes do.
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
    shadow::MapPacker packer;
    const std::vector<int> sizes = {512, 4096, 512, 1024, 512, 512, 2048, 1024};
    // 4096: a layer; 2048, 1024, 1024 and four 512s fit beside each other in a second.
    EXPECT_EQ(packer.pack(sizes, 4096), 2);
    expectDisjointInside(sizes, 4096, packer.slots());
    EXPECT_EQ(packer.slots()[1].layer, 0);
    EXPECT_EQ(packer.slots()[1].origin, glm::ivec2(0));
}

TEST(MapAtlas, EqualSizesTakeALayerEach) {
    shadow::MapPacker packer;
    const std::vector<int> sizes(5, 1024);
    EXPECT_EQ(packer.pack(sizes, 1024), 5);
    for (int i = 0; i < 5; ++i)
        EXPECT_EQ(packer.slots()[std::size_t(i)].layer, i);
}

TEST(MapAtlas, SizesThatAreNotPowersOfTwo) {
    shadow::MapPacker packer;
    const std::vector<int> sizes = {1386, 693, 692, 600, 100, 100, 100, 100, 100, 64, 1000};
    packer.pack(sizes, 1386);
    expectDisjointInside(sizes, 1386, packer.slots());
    const std::vector<int> steps = {724, 360, 512, 180, 724, 360, 360, 128, 256, 512, 1024};
    packer.pack(steps, 2048);
    expectDisjointInside(steps, 2048, packer.slots());
    // Maps start on tile corners.
    for (const shadow::MapSlot& slot : packer.slots()) {
        EXPECT_EQ(slot.origin.x % shadow::kMapAlignment, 0);
        EXPECT_EQ(slot.origin.y % shadow::kMapAlignment, 0);
    }
    // 257 maps of 64² in layers of 1024²: 16 x 16 per layer, so two layers.
    const std::vector<int> many(257, 64);
    EXPECT_EQ(packer.pack(many, 1024), 2);
    expectDisjointInside(many, 1024, packer.slots());
    EXPECT_TRUE(packer.pack({}, 1024) == 0 && packer.slots().empty());
    // Outside the contract (a map larger than the layer): a layer of its own, no endless search.
    EXPECT_EQ(packer.pack({512, 2048, 0}, 1024), 2);
    EXPECT_NE(packer.slots()[1].layer, packer.slots()[0].layer);
    EXPECT_NE(packer.slots()[1].layer, packer.slots()[2].layer);
}

// One map's new size moves no other map: the others keep their places, the changed one
// goes where there is room.
TEST(MapAtlas, MapsKeepTheirPlacesWhileTheirSizesDo) {
    shadow::MapPacker packer;
    std::vector<int> sizes = {360, 512, 360, 724, 180, 512, 360, 256};
    packer.pack(sizes, 2048);
    const std::vector<shadow::MapSlot> before = packer.slots();
    packer.keep();
    sizes[1] = 724;  // a light came closer
    packer.pack(sizes, 2048, true);
    expectDisjointInside(sizes, 2048, packer.slots());
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        if (i == 1) continue;
        EXPECT_EQ(packer.slots()[i].layer, before[i].layer) << i;
        EXPECT_EQ(packer.slots()[i].origin, before[i].origin) << i;
    }
    // Without keeping, the larger map goes first and others move.
    packer.pack(sizes, 2048);
    expectDisjointInside(sizes, 2048, packer.slots());
    bool moved = false;
    for (std::size_t i = 0; i < sizes.size(); ++i)
        moved = moved || packer.slots()[i].origin != before[i].origin;
    EXPECT_TRUE(moved);
    // Kept places are for the kept layer size only.
    packer.pack(sizes, 4096, true);
    expectDisjointInside(sizes, 4096, packer.slots());
}

// Maps between powers of two: 25 of 360² fill one 2048² layer five by five, where slots of
// 512² would take two; 724² maps leave room beside them for 512² maps.
TEST(MapAtlas, LayerSizeWithTheFewestTexels) {
    shadow::MapPacker packer;
    const std::vector<int> threeSixty(25, 360);
    EXPECT_EQ(packer.packLeast(threeSixty), 2048);
    EXPECT_EQ(packer.layers(), 1);
    expectDisjointInside(threeSixty, 2048, packer.slots());
    std::vector<int> mixed(4, 724);
    mixed.insert(mixed.end(), 3, 512);
    EXPECT_EQ(packer.packLeast(mixed), 2048);
    EXPECT_EQ(packer.layers(), 1);
    expectDisjointInside(mixed, 2048, packer.slots());
    // Few small maps keep small layers: three 512² maps take three 512² layers, not a 1024²
    // one; on a tie (four) the smaller size too.
    EXPECT_EQ(packer.packLeast(std::vector<int>(3, 512)), 512);
    EXPECT_EQ(packer.layers(), 3);
    EXPECT_EQ(packer.packLeast(std::vector<int>(4, 512)), 512);
    // A map larger than the largest chosen layer gets its own size, the small one a layer of
    // that size too.
    EXPECT_EQ(packer.packLeast({4096, 512}), 4096);
    EXPECT_EQ(packer.layers(), 2);
    EXPECT_EQ(packer.packLeast({}), 0);
    EXPECT_EQ(packer.layers(), 0);
}

}  // namespace
}  // namespace gnomon
