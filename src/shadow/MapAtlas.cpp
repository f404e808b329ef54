#include "shadow/MapAtlas.h"

#include <algorithm>
#include <bit>

namespace gnomon::shadow {

int MapPacker::pack(const std::vector<int>& sizes, int layerSize) {
    mSlots.assign(sizes.size(), MapSlot{});
    mShelves.clear();
    mTops.clear();
    mOrder.resize(sizes.size());
    for (std::uint32_t i = 0; i < mOrder.size(); ++i)
        mOrder[i] = i;
    std::sort(mOrder.begin(), mOrder.end(), [&](std::uint32_t a, std::uint32_t b) {
        return sizes[a] > sizes[b] || (sizes[a] == sizes[b] && a < b);
    });
    for (std::uint32_t i : mOrder) {
        const int size = sizes[i];
        // Beside the maps of a shelf at least as tall (maps come largest first, so every
        // shelf is).
        auto shelf = std::find_if(mShelves.begin(), mShelves.end(),
                                  [&](const Shelf& s) { return s.used + size <= layerSize; });
        if (shelf == mShelves.end()) {
            // A new shelf over the first layer's others that leave room, else a new layer.
            auto top = std::find_if(mTops.begin(), mTops.end(),
                                    [&](int t) { return t + size <= layerSize; });
            if (top == mTops.end()) top = mTops.insert(mTops.end(), 0);
            mShelves.push_back({int(top - mTops.begin()), *top, size, 0});
            *top += size;
            shelf = mShelves.end() - 1;
        }
        mSlots[i] = {shelf->layer, glm::ivec2(shelf->used, shelf->y)};
        shelf->used += size;
    }
    return layers();
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

}  // namespace gnomon::shadow
