#include "shadow/MapAtlas.h"

#include <algorithm>
#include <numeric>

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
    std::vector<std::size_t> order(sizes.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return sizes[a] > sizes[b]; });
    int layer = 0, level = 0, cursor = 0;  // cursor: the next free slot of this level
    for (std::size_t i : order) {
        int k = 0;
        while (k < kMaxSplit && (layerSize >> (k + 1)) >= sizes[i])
            ++k;
        for (; level < k; ++level)
            cursor *= 4;  // the same position in slots a quarter the area
        if (cursor >= (1 << (2 * level))) {
            ++layer;
            cursor = 0;
        }
        // Slot c of a level spans [c * size / 2^level, (c + 1) * size / 2^level) rounded
        // down: every slot is at least size >> level wide, and a slot's four quarters lie
        // exactly inside it even when the layer's size is not a power of two.
        slots[i] = {layer, zOrder(cursor) * layerSize / (1 << level)};
        ++cursor;
    }
    return layer + 1;
}

}  // namespace gnomon::shadow
