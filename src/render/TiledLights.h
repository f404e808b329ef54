// The order in which the main pass visits light records, and the screen tiles that visit fewer
// of them (shadow/LightTiles.h says why). The shader reads records through the order
// (shaders/lights.glsl, LightOrder): its first entries are every record in turn, for an
// untiled draw; each tile's entries follow, the lights that reach it, grouped by kind as the
// records are. The tiles are either drawn one by one under a scissor (tiles()), or described
// by a grid of ranges that one draw reads per pixel (lists()).
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "gnomon/Options.h"
#include "gnomon/Scene.h"
#include "render/MainPass.h"
#include "shadow/LightTiles.h"

namespace gnomon::render {

// Entries the order can hold at most: the uniform block shaders/lights.glsl declares, as large
// as the driver allows up to 64 KiB (MainPass::orderCapacity; 16 KiB, 4096 entries, is the
// least OpenGL 4.5 and OpenGL ES 3.0 guarantee).
inline constexpr int kLightOrderCapacity = 16384;
inline constexpr int kLeastLightOrderCapacity = 4096;

struct LightTile {
    glm::ivec4 scissor{0};  // x, y, width, height in pixels
    int first = 0;          // its unshadowed lights start here in the order...
    glm::ivec4 ends{0};     // ...and its unshadowed, map, cube and cascaded lights end here
};

// The tiles of one draw that reads its lights per pixel (main.frag.glsl, LIGHT_LISTS): tile
// (c, r) covers pixels [c, c + 1) x [r, r + 1) times `size` (rows from the bottom, as
// gl_FragCoord counts), and its texel (first, ends.x, ends.y, ends.z) holds its ranges of the
// order as LightTile does. Cascaded lights are directional and reach every tile, so a tile's
// cascaded end is its cube end plus their count, which the shader adds.
struct LightLists {
    int size = 0;  // tile side in pixels, a power of two (0: no lists)
    int columns = 0, rows = 0;
    std::vector<glm::ivec4> texels;  // [row * columns + column]
};

class TiledLights {
public:
    // Plans one frame. `records` and `ranges` as shadow::FramePlan makes them (world-space records,
    // the ends of each kind), seen through `viewFromWorld` and `clipFromView`; `triangles`: what
    // one more drawing of the scene costs. `mode` (--light-tiles; Off where tiles would not be
    // exact): Auto takes the way and grid the cost model (shadow::tilingGainMs) expects to gain
    // most, if any; Lists and Draws the grid it expects to gain most from. `depth`: the view's
    // reduced depth, which bounds each tile's volume (null: none).
    void plan(const std::vector<GpuLight>& records, glm::ivec4 ranges,
              const glm::mat4& viewFromWorld, const glm::mat4& clipFromView, int width, int height,
              std::uint64_t triangles, LightTiles mode, const shadow::DepthCells* depth);
    // Is the view depth pass worth drawing for the tiles alone: do two or more shadowed
    // lights that are on have a bounded reach (spots, or point lights with a range)?
    static bool wantsDepth(const Scene& s, const RenderOptions& options);
    // Entries the main pass's light order holds (MainPass::orderCapacity): finer tiles whose
    // lists would not fit take coarser ones.
    void setOrderCapacity(int entries) { mOrderCapacity = entries; }

    const std::vector<std::int32_t>& order() const { return mOrder; }
    // Draws, one per tile; empty: one draw (with every light, first 0, ends the frame's ranges,
    // unless lists() has tiles).
    const std::vector<LightTile>& tiles() const { return mTiles; }
    // One draw reading its tiles' lists; size 0 when the frame has none.
    const LightLists& lists() const { return mLists; }
    glm::ivec4 ranges() const { return mRanges; }

private:
    int mOrderCapacity = kLeastLightOrderCapacity;
    bool buildTiles(const shadow::TileReach& grid, int width, int height);
    bool buildLists(const shadow::TileReach& grid);
    // The order's entries for the lights `reach` marks, appended by kind: its range.
    LightTile appendLights(const std::uint8_t* reach);

    // A way of tiling one of mGrids and its expected gain (shadow::tilingGainMs).
    struct Candidate {
        double gain = 0.0;
        std::size_t grid = 0;
        bool lists = false;
    };

    std::vector<std::int32_t> mOrder;
    std::vector<LightTile> mTiles;
    LightLists mLists;
    // Reused every frame: the lights' reach, the grids from the finest tiles up, the ways.
    std::vector<shadow::LightReach> mReach;
    std::vector<shadow::TileReach> mGrids;
    std::vector<Candidate> mCandidates;
    std::unordered_map<std::string, LightTile> mShared;  // lists: tiles with the same lights
    glm::ivec4 mRanges{0};
};

}  // namespace gnomon::render
