// Which lights can reach which part of the screen: the culling of tiled forward shading
// (Olsson and Assarsson, "Tiled Shading", JGT 2011; Harada, McKee and Yang, "Forward+",
// Eurographics 2012 short papers), done on the CPU
// with the view volume of each screen tile. llvmpipe runs every light's shadow lookup on
// every pixel (it executes both sides of any branch whose condition varies between pixels,
// so "outside this spot's cone" saves nothing in the shader); giving each tile only the lights
// that reach it, in a draw of its own or in a list its pixels read, turns that condition into
// one shared by every pixel llvmpipe shades together.
// Exact: a skipped light adds nothing where it was skipped (outside its outer cone a spot's
// falloff is 0, beyond its range a point light's window is 0). No GL here.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "shadow/ViewSamples.h"

namespace gnomon::shadow {

// A light's reach in view space.
struct LightReach {
    enum class Shape { Everywhere, Sphere, Cone };
    Shape shape = Shape::Everywhere;
    glm::vec3 position{0.0f};   // sphere centre, cone apex
    glm::vec3 direction{0.0f};  // cone axis (any length)
    float cosOuter = -1.0f;     // cone: cosine of the outer half-angle
    float range = 0.0f;         // <= 0: unbounded
    bool shadowed = false;      // has a shadow lookup (what skipping it saves)
};

// The 8 view-space corners of a tile's part of the view volume: screen rectangle
// [x0, x1] x [y0, y1] in pixels of a width x height target, between window depths
// `nearest` and `farthest` (0 and 1: the near and far planes).
std::array<glm::vec3, 8> tileCorners(const glm::mat4& viewFromClip, int width, int height, int x0,
                                     int y0, int x1, int y1, float nearest = 0.0f,
                                     float farthest = 1.0f);

// Can any point of the volume spanned by `corners` (a frustum from tileCorners) be lit by
// `light`? Conservative: true unless a separating plane proves otherwise (the cone is
// bounded by its circumscribed square pyramid).
bool mayReach(const LightReach& light, const std::array<glm::vec3, 8>& corners);

// A grid of square tiles over the target, `size` pixels wide (the last row and column may
// be narrower), and for each tile which lights reach it.
struct TileReach {
    int size = 0, columns = 0, rows = 0;
    std::vector<std::uint8_t> reaches;  // [tile * lights + light], tile = row * columns + column
    // [tile]: its pixels, or those of its finer tiles where the view's depth shows something
    // drawn (0: nothing drawn there).
    std::vector<std::int32_t> drawn;
};

// The view's depth reduced to cells (render/ViewDepthPass.h): per cell of grid.block pixels,
// the nearest and farthest window depth drawn there, (1, 1) for none; rows bottom-up.
struct DepthCells {
    const std::vector<glm::vec2>* ranges = nullptr;
    SampleGrid grid;
};

// Culls `lights` per tile of `size` pixels. With `depth`, each tile's volume spans only the
// depths drawn in it (what Forward+ takes from its depth pre-pass), and a tile where nothing
// was drawn is reached by no light; without, it spans the near to the far plane.
void cullTiles(const std::vector<LightReach>& lights, const glm::mat4& viewFromClip, int width,
               int height, int size, const DepthCells* depth, TileReach& out);

// The grid of `fine` with tiles `factor` times as wide: a light reaches a coarse tile where
// it reaches one of its fine ones, and a coarse tile's pixels drawn are theirs. As exact as
// `fine`, and tighter than culling the coarse tiles themselves.
void coarsenTiles(const TileReach& fine, int factor, int width, int height, std::size_t lights,
                  TileReach& out);

// What each way of tiling is worth against one draw with every light on every pixel, in ms
// (positive: expected to pay), from costs measured on llvmpipe (2 cores). Each light a tile
// leaves out saves its share of the main pass on each of the tile's pixels drawn (where nothing
// was drawn, nothing is shaded either way). Draws: each extra drawing of the scene costs its
// triangles' setup again; a draw of up to `maxWrittenOut` lights has its loops written out.
// Lists: one draw, always in loops, plus each pixel's fetch of its tile's list.
struct TilingGain {
    double draws = 0.0;
    double lists = 0.0;
};
TilingGain tilingGainMs(const TileReach& tiles, const std::vector<LightReach>& lights,
                        std::uint64_t triangles, int maxWrittenOut);

}  // namespace gnomon::shadow
