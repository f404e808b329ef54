#include "render/TiledLights.h"

#include "scene/SceneUtil.h"

#include <algorithm>
#include <cstring>

namespace gnomon::render {

namespace {
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

    // The grid with the largest expected gain: in Auto only if it gains, otherwise the best
    // for the way asked for, whatever it gains. Lists take smaller tiles, which cost no draws.
    const glm::mat4 viewFromClip = glm::inverse(clipFromView);
    double best = mode == LightTiles::Auto ? 0.0 : -1e30;
    bool found = false, lists = false;
    for (int size : {16, 32, 64, 128, 256}) {
        const bool listsHere = mode == LightTiles::Lists;
        const bool drawsHere = mode != LightTiles::Lists && size >= 64;
        if (!listsHere && !drawsHere) continue;
        shadow::cullTiles(mReach, viewFromClip, width, height, size, depth, mCull);
        const shadow::TilingGain gain = shadow::tilingGainMs(
            mCull, mReach, width, height, triangles, MainPass::kMaxUnrolledLights);
        const double here = listsHere ? gain.lists : gain.draws;
        if (here > best) {
            best = here;
            found = true;
            lists = listsHere;
            std::swap(mBest, mCull);
        }
    }
    if (!found) return;
    if (lists) {
        if (!buildLists()) mOrder.resize(std::size_t(mRanges.w));
    } else {
        buildTiles(width, height);
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

// One tile per run of neighbours in a row that the same lights reach.
void TiledLights::buildTiles(int width, int height) {
    const std::size_t n = mReach.size();
    for (int r = 0; r < mBest.rows; ++r) {
        for (int c = 0; c < mBest.columns;) {
            const std::uint8_t* reach =
                mBest.reaches.data() + std::size_t(r * mBest.columns + c) * n;
            int run = 1;
            while (c + run < mBest.columns && std::memcmp(reach, reach + run * n, n) == 0)
                ++run;
            LightTile tile = appendLights(reach);
            const int x0 = c * mBest.size, y0 = r * mBest.size;
            tile.scissor = {x0, y0, std::min(width, (c + run) * mBest.size) - x0,
                            std::min(height, (r + 1) * mBest.size) - y0};
            mTiles.push_back(tile);
            c += run;
        }
    }
    if (mOrder.size() > std::size_t(kLightOrderCapacity)) {  // too many: draw untiled
        mOrder.resize(std::size_t(mRanges.w));
        mTiles.clear();
    }
}

// One texel per tile; tiles that the same lights reach share their entries of the order.
// False when the order cannot hold them.
bool TiledLights::buildLists() {
    const std::size_t n = mReach.size();
    mShared.clear();
    mLists.size = mBest.size;
    mLists.columns = mBest.columns;
    mLists.rows = mBest.rows;
    mLists.texels.resize(std::size_t(mBest.columns * mBest.rows));
    std::string reach;
    for (std::size_t t = 0; t < mLists.texels.size(); ++t) {
        reach.assign(reinterpret_cast<const char*>(mBest.reaches.data() + t * n), n);
        // The cascaded end is implied (LightLists): every tile holds every cascaded light,
        // also one where the view's depth shows nothing drawn.
        std::fill(reach.begin() + mRanges.z, reach.end(), char(1));
        auto [it, added] = mShared.try_emplace(reach);
        if (added) it->second = appendLights(reinterpret_cast<const std::uint8_t*>(reach.data()));
        const LightTile& tile = it->second;
        mLists.texels[t] = {tile.first, tile.ends.x, tile.ends.y, tile.ends.z};
    }
    if (mOrder.size() <= std::size_t(kLightOrderCapacity)) return true;
    mLists = {};
    return false;
}

}  // namespace gnomon::render
