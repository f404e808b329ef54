// Where each 2D shadow map goes in the array of square layers they share: a layer is as
// large as the largest map, and smaller maps share layers instead of each taking one (14
// maps of 512² beside one of 4096² take 2 layers, not 15). Pure: no GL.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace gnomon::shadow {

struct MapSlot {
    int layer = 0;
    glm::ivec2 origin{0};  // the map's lower-left texel in its layer
};

// Places maps of `sizes` (texels per side) in layers of layerSize² (at least the largest
// size): each map gets the smallest slot of layerSize / 2^k (k <= 6) that holds it, slots
// filled largest first (maps of one slot size in their given order) in Z order, so slots never
// overlap and a map lies inside its layer. Fills `slots` (one per size, same order); returns the
// number of layers used.
int packMaps(const std::vector<int>& sizes, int layerSize, std::vector<MapSlot>& slots);

}  // namespace gnomon::shadow
