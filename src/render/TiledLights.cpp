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
                       int height, std::uint64_t triangles, bool allowed,
                       const shadow::DepthCells* depth) {
    mRanges = ranges;
    mTiles.clear();
    mOrder.resize(std::size_t(ranges.w));
    for (int i = 0; i < ranges.w; ++i)
        mOrder[std::size_t(i)] = i;
    if (!allowed || ranges.w == 0) return;

    mReach.clear();
    bool anyBounded = false;
    for (int i = 0; i < ranges.w; ++i) {
        mReach.push_back(reachOf(records[std::size_t(i)], i >= ranges.x, viewFromWorld));
        anyBounded = anyBounded || mReach.back().shape != shadow::LightReach::Shape::Everywhere;
    }
    if (!anyBounded) return;

    // The grid with the largest expected gain, if any gains.
    const glm::mat4 viewFromClip = glm::inverse(clipFromView);
    double best = 0.0;
    for (int size : {64, 128, 256}) {
        shadow::cullTiles(mReach, viewFromClip, width, height, size, depth, mCull);
        const double gain = shadow::tilingGainMs(mCull, mReach, width, height, triangles);
        if (gain > best) {
            best = gain;
            std::swap(mBest, mCull);
        }
    }
    if (best > 0.0) buildTiles(width, height);
}

// One tile per run of neighbours in a row that the same lights reach.
void TiledLights::buildTiles(int width, int height) {
    const std::size_t n = mReach.size();
    const int ends[4] = {mRanges.x, mRanges.y, mRanges.z, mRanges.w};
    for (int r = 0; r < mBest.rows; ++r) {
        for (int c = 0; c < mBest.columns;) {
            const std::uint8_t* reach =
                mBest.reaches.data() + std::size_t(r * mBest.columns + c) * n;
            int run = 1;
            while (c + run < mBest.columns && std::memcmp(reach, reach + run * n, n) == 0)
                ++run;
            LightTile tile;
            const int x0 = c * mBest.size, y0 = r * mBest.size;
            tile.scissor = {x0, y0, std::min(width, (c + run) * mBest.size) - x0,
                            std::min(height, (r + 1) * mBest.size) - y0};
            tile.first = int(mOrder.size());
            int start = 0;
            for (int kind = 0; kind < 4; ++kind) {
                for (int i = start; i < ends[kind]; ++i)
                    if (reach[i]) mOrder.push_back(i);
                tile.ends[kind] = int(mOrder.size());
                start = ends[kind];
            }
            mTiles.push_back(tile);
            c += run;
        }
    }
    if (mOrder.size() > std::size_t(kLightOrderCapacity)) {  // too many: draw untiled
        mOrder.resize(std::size_t(mRanges.w));
        mTiles.clear();
    }
}

}  // namespace gnomon::render
