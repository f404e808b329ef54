// The order in which the main pass visits light records, and the screen tiles it draws
// with fewer of them (shadow/LightTiles.h says why). The shader reads records through the
// order (shaders/lights.glsl, LightOrder): its first entries are every record in turn, for an
// untiled draw; each tile's entries follow, the lights that reach it, grouped by kind as the
// records are.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gnomon/Options.h"
#include "gnomon/Scene.h"
#include "render/MainPass.h"
#include "shadow/LightTiles.h"

namespace gnomon::render {

// Entries the order can hold: the uniform block shaders/lights.glsl declares (16 KiB, the
// least OpenGL 4.5 guarantees for a uniform block).
inline constexpr int kLightOrderCapacity = 4096;

struct LightTile {
    glm::ivec4 scissor{0};  // x, y, width, height in pixels
    int first = 0;          // its unshadowed lights start here in the order...
    glm::ivec4 ends{0};     // ...and its unshadowed, map, cube and cascaded lights end here
};

class TiledLights {
public:
    // Plans one frame. `records` and `ranges` as shadow::FramePlan makes them (world-space records,
    // the ends of each kind), seen through `viewFromWorld` and `clipFromView`; `triangles`: what
    // one more drawing of the scene costs. Tiles only when `allowed` and the cost model
    // (shadow::tilingGainMs) expects a gain. `depth`: the view's reduced depth, which bounds each
    // tile's volume (null: none).
    void plan(const std::vector<GpuLight>& records, glm::ivec4 ranges,
              const glm::mat4& viewFromWorld, const glm::mat4& clipFromView, int width, int height,
              std::uint64_t triangles, bool allowed, const shadow::DepthCells* depth);
    // Is the view depth pass worth drawing for the tiles alone: do two or more shadowed
    // lights that are on have a bounded reach (spots, or point lights with a range)?
    static bool wantsDepth(const Scene& s, const RenderOptions& options);

    const std::vector<std::int32_t>& order() const { return mOrder; }
    // Empty: draw once, with every light (first 0, ends the frame's ranges).
    const std::vector<LightTile>& tiles() const { return mTiles; }
    glm::ivec4 ranges() const { return mRanges; }

private:
    void buildTiles(int width, int height);

    std::vector<std::int32_t> mOrder;
    std::vector<LightTile> mTiles;
    std::vector<shadow::LightReach> mReach;  // reused every frame
    shadow::TileReach mCull, mBest;          // reused every frame
    glm::ivec4 mRanges{0};
};

}  // namespace gnomon::render
