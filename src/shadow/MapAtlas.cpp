#include "shadow/MapAtlas.h"

#include <algorithm>

namespace gnomon::shadow {

namespace {
constexpr int kMaxSplit = 6;  // slots down to 1/64 of a layer's side

// The k-th slot of a layer split 2^level times per side, in Z order: bits of k alternate
// between x and y, so slots of one level fill the same area as the larger slot they replace.
glm::ivec2 zOrder(int k) {
    glm::ivec2 p(0);
    for (int bit = 0; bit < kMaxSplit; ++bit) {
        p.x |= ((k >> (2 * bit)) & 1) << bit;
        p.y |= ((k >> (2 * bit + 1)) & 1) << bit;
    }
    return p;
}
}  // namespace

int packMaps(const std::vector<int>& sizes, int layerSize, std::vector<MapSlot>& slots) {
    slots.assign(sizes.size(), MapSlot{});
    if (sizes.empty()) return 0;
    // Each map's level: the most times the layer's side halves and still holds it.
    auto levelOf = [&](int size) {
        int k = 0;
        while (k < kMaxSplit && (layerSize >> (k + 1)) >= size)
            ++k;
        return k;
    };
    // Largest slots first, maps of one level in their given order: one pass per level
    // instead of a sorted copy of the indices (this runs every frame; no allocation).
    int layer = 0, level = 0, cursor = 0;  // cursor: the next free slot of this level
    for (int k = 0; k <= kMaxSplit; ++k) {
        for (std::size_t i = 0; i < sizes.size(); ++i) {
            if (levelOf(sizes[i]) != k) continue;
            for (; level < k; ++level)
                cursor *= 4;  // the same position in slots a quarter the area
            if (cursor >= (1 << (2 * level))) {
                ++layer;
                cursor = 0;
            }
            // Slot c of a level spans [c * size / 2^level, (c + 1) * size / 2^level) rounded
            // down: every slot is at least size >> level wide, and a slot's four quarters
            // lie exactly inside it even when the layer's size is not a power of two.
            slots[i] = {layer, zOrder(cursor) * layerSize / (1 << level)};
            ++cursor;
        }
    }
    return layer + 1;
}

}  // namespace gnomon::shadow
