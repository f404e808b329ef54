// The maps' side of the frame plan: where each map lies in its array, which casters reach it,
// the key it is drawn under, and which maps are drawn again this frame.
#include <algorithm>
#include <bit>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "shadow/FramePlan.h"

namespace gnomon::shadow {

namespace {

// Are the 2D maps' (or the cubes') arrays as they were: every map they held is still there?
bool sameArrays(const MapLayout& have, const MapLayout& want, bool cubes) {
    return cubes ? have.sizeCube == want.sizeCube && have.cubes == want.cubes &&
                       have.formatCube == want.formatCube
                 : have.size2D == want.size2D && have.layers2D == want.layers2D &&
                       have.format2D == want.format2D;
}

}  // namespace

// Sizes the arrays for the maps and gives each its layer (and, for 2D maps, its square in the
// layer).
void FramePlan::layOutMaps(const ShadowOptions& options) {
    MapLayout layout;
    mSizes.clear();
    for (ShadowedLight& l : mShadowed) {
        if (l.frame.kind == FrameKind::Cube) {
            layout.sizeCube = std::max(layout.sizeCube, l.mapSize);
            l.layer = layout.cubes++;
        } else {
            mSizes.push_back(l.mapSize);
        }
    }
    // A cube map array has one size, and a cube's lookups read whole faces: every cube is
    // drawn at the largest size asked for, its texel shrunk to match (a light that asked for
    // less gets the finer map).
    for (ShadowedLight& l : mShadowed) {
        if (l.frame.kind != FrameKind::Cube || l.mapSize == layout.sizeCube) continue;
        l.frame.texelWorldSize *= float(l.mapSize) / float(layout.sizeCube);
        l.mapSize = layout.sizeCube;
    }
    layout.format2D = options.depthFormat;
    layout.size2D = mPacker.packLeast(mSizes);
    layout.layers2D = mPacker.layers();
    keepHeldArray(layout);
    std::size_t next2D = 0;
    for (ShadowedLight& l : mShadowed) {
        if (l.frame.kind == FrameKind::Cube) continue;
        l.layer = mPacker.slots()[next2D].layer;
        l.origin = mPacker.slots()[next2D++].origin;
    }
    // Cubes of colour formats store native depth.
    layout.formatCube =
        isColourFormat(options.depthFormat) ? DepthFormat::Depth32F : options.depthFormat;
    mLayout = layout;
}

// The 2D maps' array as earlier frames left it, when this frame's maps fit it and its layers
// take at most a quarter more texels than the best size's, each map kept where it was while
// its size is: lights that move change their sizes from frame to frame, and a new array or
// new places would drop the maps they held.
void FramePlan::keepHeldArray(MapLayout& layout) {
    const MapLayout& held = mHeldLayout;
    if (layout.layers2D == 0 || held.layers2D == 0 || held.format2D != layout.format2D) return;
    auto texels = [](int size, int layers) { return double(size) * double(size) * layers; };
    const int largest = *std::max_element(mSizes.begin(), mSizes.end());
    if (held.size2D < largest ||
        texels(held.size2D, held.layers2D) > 1.25 * texels(layout.size2D, layout.layers2D)) {
        return;
    }
    // Maps whose size did not change stay where they were.
    if (mPacker.pack(mSizes, held.size2D, true) <= held.layers2D) {
        layout.size2D = held.size2D;
        layout.layers2D = held.layers2D;
        return;
    }
    mPacker.pack(mSizes, layout.size2D);  // back to the best size's places
}

// The records' map fields from where the maps went.
void FramePlan::fillMapRecords() {
    for (const ShadowedLight& sl : mShadowed) {
        GpuLight& g = mLights[std::size_t(sl.record)];
        const bool cube = sl.frame.kind == FrameKind::Cube;
        const int arraySize = cube ? mLayout.sizeCube : mLayout.size2D;
        g.layer = sl.layer;
        g.texelWorldSize = sl.frame.texelWorldSize;  // a cube drawn larger has finer texels
        g.uvScale = float(sl.mapSize) / float(arraySize);
        g.texelUv = 1.0f / float(arraySize);
        // A 2D map's square in its layer (LightRecord::mapCorner).
        if (!cube) g.mapCorner = glm::vec2(sl.origin) / float(arraySize);
    }
}

void FramePlan::planMaps(const std::vector<ShadowedLight>& maps, const PlanScene& scene,
                         const ShadowOptions& options, const HeldMaps& held) {
    mMade.valid = false;
    mLights.clear();
    mRanges = glm::ivec4(0);
    mHasCascades = mHasFaces = false;
    mShadowed = maps;
    mHeldLayout = held.layout;
    layOutMaps(options);
    mPacker.keep();
    collectCasters(scene, options);
    chooseRedraws(held, options.mapRedraws);
}

// Each map's depth casters (those inside its light's volume) and the key it is drawn under.
// Tinting casters are drawn by the transmittance pass after the map: they count in the key's
// hash (moving one redraws both), not in the list.
void FramePlan::collectCasters(const PlanScene& scene, const ShadowOptions& options) {
    mCasters.clear();
    mHoldsLight.clear();
    mCulled = 0;
    const std::vector<SceneItem>& items = *scene.items;
    for (ShadowedLight& l : mShadowed) {
        const LightVolume volume(l);
        const bool cube = l.frame.kind == FrameKind::Cube;
        l.firstCaster = std::uint32_t(mCasters.size());
        std::uint64_t hash = scene.geometryHash;
        for (std::uint32_t i = 0; i < items.size(); ++i) {
            const SceneItem& item = items[i];
            const bool depth = castsDepth(item.casts, item.drawable, item.alphaMode, options);
            if (!depth && !castsTint(item.casts, item.drawable, item.alphaMode, options)) continue;
            if (volume.outside(item.bounds)) {
                if (depth) ++mCulled;
                continue;
            }
            if (depth) {
                mCasters.push_back(i);
                mHoldsLight.push_back(std::uint8_t(item.closed && volume.holdsLight(item.bounds)));
            }
            hash = (hash ^ item.dataHash) * 0x100000001b3ull + i;
        }
        l.casterCount = std::uint32_t(mCasters.size()) - l.firstCaster;
        MapKey& key = l.key;
        key = MapKey{};
        key.mapSize = l.mapSize;
        key.place = cube ? glm::ivec3(0, 0, l.layer) : glm::ivec3(l.origin, l.layer);
        key.castersHash = hash;
        key.cull = options.cull;
        key.slope = options.biasSlope;
        key.units = options.biasUnits;
        key.depthClamp = l.depthClamp;
        key.format = options.depthFormat;
        key.blend = options.blendShadows;
        key.edges = options.shadowRays == ShadowRayMode::Uncertain && options.casterOutlines;
        key.faces = cube ? l.frame.faces : kAllCubeFaces;
        key.eye = glm::vec3(glm::inverse(l.frame.lightFromWorld)[3]);
        key.near = l.frame.near;
        key.far = l.frame.far;
        key.texelWorldSize = l.frame.texelWorldSize;
        for (int face = 0; face < (cube ? 6 : 1); ++face)
            key.clipFromWorld[std::size_t(face)] =
                cube ? l.frame.faceClipFromWorld(face) : l.frame.clipFromWorld();
    }
}

// A map is kept when its array was not remade and what it holds serves the key wanted now;
// with a redraw budget, maps that changed may wait (keepWaiting).
void FramePlan::chooseRedraws(const HeldMaps& held, int budget) {
    const bool same2D = sameArrays(held.layout, mLayout, false);
    const bool sameCubes = sameArrays(held.layout, mLayout, true);
    std::size_t next2D = 0;
    for (ShadowedLight& l : mShadowed) {
        const bool cube = l.frame.kind == FrameKind::Cube;
        const std::size_t slot = cube ? std::size_t(l.layer) : next2D++;
        const std::vector<MapKey>& keys = cube ? held.cubes : held.maps2D;
        l.redraw = !((cube ? sameCubes : same2D) && slot < keys.size() && keys[slot].serves(l.key));
        if (l.waiting) writeLookup(l, l.key);  // waited last frame: the plan's camera again
        l.waiting = false;
    }
    if (budget > 0) keepWaiting(held, budget);
}

// At most `budget` maps drawn this frame when many changed (moving lights): maps with nothing
// to show in their place are drawn whatever the budget; of the spot and point lights' maps
// that changed but hold an earlier drawing in their place, the longest waiting are drawn first,
// the most visible (the largest: maps are sized by their reach on screen) ahead; the rest keep what
// they hold, their records' lookups following the camera it was drawn with (the shadows of
// where the light was). Cached shadow maps under a re-render budget, as engines keep them.
void FramePlan::keepWaiting(const HeldMaps& held, int budget) {
    const bool same2D = sameArrays(held.layout, mLayout, false);
    const bool sameCubes = sameArrays(held.layout, mLayout, true);
    mWaitOrder.clear();
    int drawn = 0;
    std::size_t next2D = 0;
    for (std::size_t i = 0; i < mShadowed.size(); ++i) {
        const ShadowedLight& l = mShadowed[i];
        const bool cube = l.frame.kind == FrameKind::Cube;
        const std::size_t slot = cube ? std::size_t(l.layer) : next2D++;
        if (!l.redraw) continue;
        const std::vector<MapKey>& keys = cube ? held.cubes : held.maps2D;
        const std::vector<std::uint64_t>& when = cube ? held.drawnCubes : held.drawn2D;
        const bool local = l.cascade < 0 && l.frame.kind != FrameKind::Orthographic;
        const bool canWait = local && (cube ? sameCubes : same2D) && slot < keys.size() &&
                             slot < when.size() && keys[slot].samePlace(l.key);
        if (!canWait) {
            ++drawn;
            continue;
        }
        // Frames since it was drawn, and a head start of a frame per doubling of its size: a
        // map waits at most as many frames as the budget needs to draw every map once, and
        // the head start.
        const double age = double(held.frame - std::min(when[slot], held.frame));
        mWaitOrder.push_back({-(age + std::log2(double(std::max(l.mapSize, 1)))), i, slot});
    }
    std::sort(mWaitOrder.begin(), mWaitOrder.end());
    for (const Waiting& w : mWaitOrder) {
        if (drawn < budget) {
            ++drawn;
            continue;
        }
        ShadowedLight& l = mShadowed[w.light];
        l.redraw = false;
        l.waiting = true;
        const bool cube = l.frame.kind == FrameKind::Cube;
        writeLookup(l, cube ? held.cubes[w.slot] : held.maps2D[w.slot]);
    }
}

// The record fields through which `light`'s lookups read its map, from the camera `key`
// names.
void FramePlan::writeLookup(const ShadowedLight& light, const MapKey& key) {
    GpuLight& g = mLights[std::size_t(light.record)];
    g.textureFromWorld = light.frame.kind == FrameKind::Cube
                             ? glm::translate(glm::mat4(1.0f), -key.eye)
                             : textureFromClip() * key.clipFromWorld[0];
    g.mapNear = key.near;
    g.mapFar = key.far;
    g.texelWorldSize = key.texelWorldSize;
}

}  // namespace gnomon::shadow
