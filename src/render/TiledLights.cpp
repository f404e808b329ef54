#include "render/TiledLights.h"

#include "scene/SceneUtil.h"

#include <algorithm>
#include <cstring>

namespace gnomon::render {

namespace {
// Tiles' sides, in pixels: lists go down to the finest, draws to kSmallestDrawnTile (each
// draw costs the scene's triangles again).
constexpr int kCoarsestTile = 256;
constexpr int kSmallestDrawnTile = 64;
constexpr std::int64_t kMaxTiles = 16384;

// A record's reach (shaders/main.frag.glsl, lightAt): spots end at their outer cone, point
// and spot lights with a range at that range; directional and area lights reach everywhere.
shadow::LightReach reachOf(const GpuLight& g, bool shadowed, const glm::mat4& viewFromWorld) {
    shadow::LightReach r;
    r.shadowed = shadowed;
    const int type = g.type;
    if (type != gpu::kSpot && type != gpu::kPoint) return r;  // directional, area
    // Records are in world space; tiles are culled in the view's.
    r.position = glm::vec3(viewFromWorld * glm::vec4(g.position, 1.0f));
    r.range = g.range > 0.0f ? g.range : 0.0f;
    if (type == gpu::kSpot) {
        r.shape = shadow::LightReach::Shape::Cone;
        r.direction = glm::mat3(viewFromWorld) * g.direction;
        r.cosOuter = g.cosOuter;
    } else if (r.range > 0.0f) {
        r.shape = shadow::LightReach::Shape::Sphere;
    }
    return r;
}
// The finest tiles: 8 pixels (whole 4 x 4 blocks, what llvmpipe's fragment code shades at a
// time), or the least power of two that keeps their count within kMaxTiles (culling costs
// each tile and light on the CPU every frame).
int finestTile(int width, int height) {
    int size = 8;
    while (size < kCoarsestTile &&
           std::int64_t((width + size - 1) / size) * ((height + size - 1) / size) > kMaxTiles)
        size *= 2;
    return size;
}
}  // namespace

bool TiledLights::wantsDepth(const Scene& s, const RenderOptions& options) {
    if (!options.shadow.enabled) return false;
    int bounded = 0;
    for (std::size_t i = 0; i < s.lights.size(); ++i) {
        const Light& l = s.lights[i];
        if (l.castsShadows && lightIsOn(s, options, i) &&
            (l.type == LightType::Spot || (l.type == LightType::Point && l.range > 0.0f))) {
            ++bounded;
        }
    }
    // One such light saves less in lookups than the depth pass costs when the camera moves;
    // two or more may save more.
    return bounded >= 2;
}

void TiledLights::plan(const std::vector<GpuLight>& records, glm::ivec4 ranges,
                       const glm::mat4& viewFromWorld, const glm::mat4& clipFromView, int width,
                       int height, std::uint64_t triangles, LightTiles mode,
                       const shadow::DepthCells* depth) {
    mRanges = ranges;
    mTiles.clear();
    mLists = {};
    mOrder.resize(std::size_t(ranges.w));
    for (int i = 0; i < ranges.w; ++i)
        mOrder[std::size_t(i)] = i;
    if (mode == LightTiles::Off || ranges.w == 0) return;

    mReach.clear();
    bool anyBounded = false;
    for (int i = 0; i < ranges.w; ++i) {
        mReach.push_back(reachOf(records[std::size_t(i)], i >= ranges.x, viewFromWorld));
        anyBounded = anyBounded || mReach.back().shape != shadow::LightReach::Shape::Everywhere;
    }
    if (!anyBounded && mode == LightTiles::Auto) return;

    // Every grid from the finest to the coarsest tiles, the finest culled and the others made
    // from it; each way and grid with its expected gain, tried from the best down until the
    // order holds one: in Auto only those that gain, otherwise the way asked for, whatever it
    // gains.
    const int finest = finestTile(width, height);
    std::size_t grids = 0;
    for (int size = finest; size <= kCoarsestTile; size *= 2)
        ++grids;
    mGrids.resize(grids);
    shadow::cullTiles(mReach, glm::inverse(clipFromView), width, height, finest, depth, mGrids[0]);
    mCandidates.clear();
    for (std::size_t g = 0; g < grids; ++g) {
        const int size = finest << g;
        if (g > 0) {
            shadow::coarsenTiles(mGrids[0], size / finest, width, height, mReach.size(), mGrids[g]);
        }
        const shadow::TilingGain gain =
            shadow::tilingGainMs(mGrids[g], mReach, triangles, MainPass::kMaxUnrolledLights);
        if (mode != LightTiles::Draws) mCandidates.push_back({gain.lists, g, true});
        if (mode != LightTiles::Lists && size >= kSmallestDrawnTile)
            mCandidates.push_back({gain.draws, g, false});
    }
    std::sort(mCandidates.begin(), mCandidates.end(),
              [](const Candidate& a, const Candidate& b) { return a.gain > b.gain; });
    for (const Candidate& c : mCandidates) {
        if (mode == LightTiles::Auto && !(c.gain > 0.0)) return;
        if (c.lists ? buildLists(mGrids[c.grid]) : buildTiles(mGrids[c.grid], width, height))
            return;
    }
}

// The order's entries for the lights `reach` marks, by kind, after those it holds.
LightTile TiledLights::appendLights(const std::uint8_t* reach) {
    const int ends[4] = {mRanges.x, mRanges.y, mRanges.z, mRanges.w};
    LightTile tile;
    tile.first = int(mOrder.size());
    int start = 0;
    for (int kind = 0; kind < 4; ++kind) {
        for (int i = start; i < ends[kind]; ++i)
            if (reach[i]) mOrder.push_back(i);
        tile.ends[kind] = int(mOrder.size());
        start = ends[kind];
    }
    return tile;
}

// One tile per run of neighbours in a row that the same lights reach. False when the order
// cannot hold them.
bool TiledLights::buildTiles(const shadow::TileReach& grid, int width, int height) {
    const std::size_t n = mReach.size();
    for (int r = 0; r < grid.rows; ++r) {
        for (int c = 0; c < grid.columns;) {
            const std::uint8_t* reach = grid.reaches.data() + std::size_t(r * grid.columns + c) * n;
            int run = 1;
            while (c + run < grid.columns && std::memcmp(reach, reach + run * n, n) == 0)
                ++run;
            LightTile tile = appendLights(reach);
            const int x0 = c * grid.size, y0 = r * grid.size;
            tile.scissor = {x0, y0, std::min(width, (c + run) * grid.size) - x0,
                            std::min(height, (r + 1) * grid.size) - y0};
            mTiles.push_back(tile);
            c += run;
        }
    }
    if (mOrder.size() <= std::size_t(mOrderCapacity)) return true;
    mOrder.resize(std::size_t(mRanges.w));
    mTiles.clear();
    return false;
}

// One texel per tile; tiles that the same lights reach share their entries of the order.
// False when the order cannot hold them.
bool TiledLights::buildLists(const shadow::TileReach& grid) {
    const std::size_t n = mReach.size();
    mShared.clear();
    mLists.size = grid.size;
    mLists.columns = grid.columns;
    mLists.rows = grid.rows;
    mLists.texels.resize(std::size_t(grid.columns * grid.rows));
    std::string reach;
    for (std::size_t t = 0; t < mLists.texels.size(); ++t) {
        reach.assign(reinterpret_cast<const char*>(grid.reaches.data() + t * n), n);
        // The cascaded end is implied (LightLists): every tile holds every cascaded light,
        // also one where the view's depth shows nothing drawn.
        std::fill(reach.begin() + mRanges.z, reach.end(), char(1));
        auto [it, added] = mShared.try_emplace(reach);
        if (added) it->second = appendLights(reinterpret_cast<const std::uint8_t*>(reach.data()));
        const LightTile& tile = it->second;
        mLists.texels[t] = {tile.first, tile.ends.x, tile.ends.y, tile.ends.z};
    }
    if (mOrder.size() <= std::size_t(mOrderCapacity)) return true;
    mOrder.resize(std::size_t(mRanges.w));
    mLists = {};
    return false;
}

}  // namespace gnomon::render
