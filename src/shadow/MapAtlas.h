// Where each 2D shadow map goes in the array of square layers they share. Maps are placed
// largest first, each at the first free place on a grid of its own size, so maps of sizes
// between powers of two leave little of a layer empty; the layer's size is the power of two
// that takes the fewest texels in all, since every layer drawn is cleared whole (14 maps of
// 512² beside one of 4096² take 2 layers, not 15; 25 maps of 360² take one 2048² layer, not
// the two of 512² slots). From frame to frame a map keeps its place while its size does, so
// one light's new size does not move the others' maps (a moved map must be drawn again, which
// a redraw budget cannot defer). Pure: no GL.
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

// Maps start on multiples of this many texels (where the layer holds the rounded size):
// llvmpipe rasterises and clears in tiles of 64 x 64 pixels, so no tile holds parts of two
// maps.
constexpr int kMapAlignment = 64;

// Places maps; its storage is reused from call to call (it runs whenever a plan changes).
class MapPacker {
public:
    // Places maps of `sizes` (texels per side, each at most layerSize) in layers of layerSize²:
    // largest first (equal sizes in their given order), each at the first free place of the
    // first layer with one, on a grid as fine as its size rounded up to kMapAlignment. With
    // `keep`, and the kept placement (keep()) at this layer size, map i keeps its kept place
    // first where its rounded size is what it was. Maps never overlap and lie inside their
    // layer. Fills slots() (one per size, same order); returns the number of layers used.
    int pack(const std::vector<int>& sizes, int layerSize, bool keep = false);
    // Packs at the layer size whose layers take the fewest texels: the least power of two that
    // holds the largest map, or twice or four times it while at most kLargestChosenLayer (the
    // smaller size on a tie). Returns that size; layers() is the count.
    int packLeast(const std::vector<int>& sizes);
    // Remembers the last packing as the placement pack(..., keep) keeps.
    void keep();

    const std::vector<MapSlot>& slots() const { return mSlots; }
    int layers() const { return mLayers; }

private:
    int footprint(int size) const;
    bool isFree(const MapSlot& at, int size) const;
    void take(const MapSlot& at, int size);
    MapSlot firstFree(int size);

    struct Cursor {
        int size = 0, layer = 0, index = 0;  // the next place to try for maps of this footprint
    };
    int mLayerSize = 0, mCells = 0, mLayers = 0;  // mCells: kMapAlignment cells per side
    std::vector<MapSlot> mSlots;
    std::vector<std::uint32_t> mOrder;
    std::vector<std::uint8_t> mTaken;  // per layer, mCells² cells, row by row
    std::vector<Cursor> mCursors;
    std::vector<std::uint8_t> mPlaced;
    int mKeptLayerSize = 0;
    std::vector<MapSlot> mKeptSlots;
    std::vector<int> mKeptSizes, mSizes;
};

}  // namespace gnomon::shadow
