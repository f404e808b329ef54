// Where each 2D shadow map goes in the array of square layers they share. Maps lie on shelves
// (rows as tall as their first map), largest first, so maps of sizes between powers of two
// leave little of a layer empty; the layer's size is the power of two that takes the fewest
// texels in all, since every layer drawn is cleared whole (14 maps of 512² beside one of 4096²
// take 2 layers, not 15; 25 maps of 360² take one 2048² layer, not the 2048² of 512² slots).
// Pure: no GL.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace gnomon::shadow {

struct MapSlot {
    int layer = 0;
    glm::ivec2 origin{0};  // the map's lower-left texel in its layer
};

// The largest layer chosen for small maps' sake: WebGL2's least MAX_TEXTURE_SIZE. A map
// larger than it still gets a layer of its own size.
constexpr int kLargestChosenLayer = 2048;

// Places maps; its storage is reused from call to call (it runs whenever a plan changes).
class MapPacker {
public:
    // Places maps of `sizes` (texels per side, each at most layerSize) in layers of layerSize²:
    // largest first (equal sizes in their given order), each on the first shelf of any layer
    // with room beside its maps, else on a new shelf over the last of the first layer with room
    // above, else in a new layer. Maps never overlap and lie inside their layer. Fills slots()
    // (one per size, same order); returns the number of layers used.
    int pack(const std::vector<int>& sizes, int layerSize);
    // Packs at the layer size whose layers take the fewest texels: the least power of two that
    // holds the largest map, or twice or four times it while at most kLargestChosenLayer (the
    // smaller size on a tie). Returns that size; layers() is the count.
    int packLeast(const std::vector<int>& sizes);

    const std::vector<MapSlot>& slots() const { return mSlots; }
    int layers() const { return int(mTops.size()); }

private:
    struct Shelf {
        int layer = 0, y = 0, height = 0, used = 0;  // used: texels taken along x
    };
    std::vector<MapSlot> mSlots;
    std::vector<std::uint32_t> mOrder;
    std::vector<Shelf> mShelves;
    std::vector<int> mTops;  // per layer: the rows its shelves take
};

}  // namespace gnomon::shadow
