#include "shadow/MapAtlas.h"

#include <algorithm>
#include <bit>

namespace gnomon::shadow {

int MapPacker::footprint(int size) const {
    size = std::max(size, 1);
    const int rounded = (size + kMapAlignment - 1) / kMapAlignment * kMapAlignment;
    return rounded <= mLayerSize ? rounded : size;
}

bool MapPacker::isFree(const MapSlot& at, int size) const {
    if (at.origin.x + size > mLayerSize || at.origin.y + size > mLayerSize) return false;
    if (at.layer >= mLayers) return true;
    const int x0 = at.origin.x / kMapAlignment, y0 = at.origin.y / kMapAlignment;
    const int x1 = (at.origin.x + size - 1) / kMapAlignment;
    const int y1 = (at.origin.y + size - 1) / kMapAlignment;
    const std::uint8_t* layer = &mTaken[std::size_t(at.layer) * std::size_t(mCells * mCells)];
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x)
            if (layer[y * mCells + x]) return false;
    return true;
}

void MapPacker::take(const MapSlot& at, int size) {
    if (at.layer >= mLayers) {
        mLayers = at.layer + 1;
        mTaken.resize(std::size_t(mLayers) * std::size_t(mCells * mCells), 0);
    }
    std::uint8_t* layer = &mTaken[std::size_t(at.layer) * std::size_t(mCells * mCells)];
    const int x1 = std::min((at.origin.x + size - 1) / kMapAlignment, mCells - 1);
    const int y1 = std::min((at.origin.y + size - 1) / kMapAlignment, mCells - 1);
    for (int y = at.origin.y / kMapAlignment; y <= y1; ++y)
        for (int x = at.origin.x / kMapAlignment; x <= x1; ++x)
            layer[y * mCells + x] = 1;
}

// The first free place on the grid of `size` (a footprint), from where the last map of that
// size went: places only fill up, so none before it has room.
MapSlot MapPacker::firstFree(int size) {
    auto cursor = std::find_if(mCursors.begin(), mCursors.end(),
                               [&](const Cursor& c) { return c.size == size; });
    if (cursor == mCursors.end()) cursor = mCursors.insert(mCursors.end(), Cursor{size, 0, 0});
    // A map larger than the layer (outside pack's contract) gets a layer of its own, at its
    // corner, rather than a search without end.
    if (size > mLayerSize) return MapSlot{std::max(mLayers, cursor->layer), glm::ivec2(0)};
    const int across = mLayerSize / size;
    for (;; ++cursor->index) {
        if (cursor->index == across * across) {
            cursor->index = 0;
            ++cursor->layer;
        }
        const MapSlot at{cursor->layer,
                         glm::ivec2(cursor->index % across, cursor->index / across) * size};
        if (isFree(at, size)) return at;
    }
}

int MapPacker::pack(const std::vector<int>& sizes, int layerSize, bool keep) {
    mLayerSize = layerSize;
    mCells = (layerSize + kMapAlignment - 1) / kMapAlignment;
    mLayers = 0;
    mTaken.clear();
    mCursors.clear();
    mSizes = sizes;
    mSlots.assign(sizes.size(), MapSlot{});
    mPlaced.assign(sizes.size(), 0);
    if (keep && mKeptLayerSize == layerSize) {
        for (std::size_t i = 0; i < sizes.size() && i < mKeptSizes.size(); ++i) {
            const int size = footprint(sizes[i]);
            if (size != footprint(mKeptSizes[i]) || !isFree(mKeptSlots[i], size)) continue;
            mSlots[i] = mKeptSlots[i];
            take(mSlots[i], size);
            mPlaced[i] = 1;
        }
    }
    mOrder.clear();
    for (std::uint32_t i = 0; i < sizes.size(); ++i)
        if (!mPlaced[i]) mOrder.push_back(i);
    std::sort(mOrder.begin(), mOrder.end(), [&](std::uint32_t a, std::uint32_t b) {
        return sizes[a] > sizes[b] || (sizes[a] == sizes[b] && a < b);
    });
    for (std::uint32_t i : mOrder) {
        const int size = footprint(sizes[i]);
        mSlots[i] = firstFree(size);
        take(mSlots[i], size);
    }
    return mLayers;
}

int MapPacker::packLeast(const std::vector<int>& sizes) {
    if (sizes.empty()) {
        pack(sizes, 0);
        return 0;
    }
    const int least = int(std::bit_ceil(unsigned(*std::max_element(sizes.begin(), sizes.end()))));
    int best = least;
    long long bestTexels = -1;
    for (int size = least; size == least || size <= std::min(4 * least, kLargestChosenLayer);
         size *= 2) {
        const long long texels = (long long)pack(sizes, size) * size * size;
        if (bestTexels < 0 || texels < bestTexels) {
            best = size;
            bestTexels = texels;
        }
    }
    pack(sizes, best);
    return best;
}

void MapPacker::keep() {
    mKeptLayerSize = mLayerSize;
    mKeptSlots = mSlots;
    mKeptSizes = mSizes;
}

}  // namespace gnomon::shadow
