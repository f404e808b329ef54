// Everything about a frame's lights and shadow maps decided before drawing, with no GL: each
// light's main-pass record (shaders/light_record.glsl), ordered by kind for the shader's
// loops, and each map's light camera, size, place in its array, casters and whether it is
// drawn again. The passes only consume the plan.
//
// Fitted cameras cover what the view sees: the visible receivers' boxes, or, with
// FitTo::ViewDepth, the view's depth samples: directional and area lights cover them (which
// also choose cascade splits and, with `cascades` 0, their count), a point light whose samples
// fit a 90-degree cone gets one frustum over them instead of a cube, and a spot maps only the
// window of its cone they lie in. A plan is kept while everything it is made from is
// unchanged; which maps to draw again is decided every frame against the maps held.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gnomon/Options.h"
#include "gnomon/Scene.h"
#include "shadow/LightRecord.h"
#include "shadow/MapAtlas.h"
#include "shadow/PlannedMap.h"
#include "shadow/ShadowMath.h"
#include "shadow/ViewSamples.h"

namespace gnomon::shadow {

// The scene as the plan sees it: its drawable items (in draw order), their bounds, and
// counters that change whenever they do.
struct PlanScene {
    const std::vector<SceneItem>* items = nullptr;
    Aabb bounds;
    std::uint64_t revision = 0;      // changes whenever any item or its data changes
    std::uint64_t geometryHash = 0;  // of the vertices and indices drawn into maps
};

// The arrays the maps live in: 2D maps share square layers of `size2D` texels a side (smaller
// maps packed by MapPacker), each cube takes six layers of a cube-map array. Cubes of colour
// formats store native depth.
struct MapLayout {
    int size2D = 0, layers2D = 0, sizeCube = 0, cubes = 0;
    DepthFormat format2D = DepthFormat::Depth32F, formatCube = DepthFormat::Depth32F;
    bool operator==(const MapLayout&) const = default;
};

// What the map arrays hold from earlier frames: their layout and the key each map was last
// drawn under (2D maps in the plan's order, cubes by cube). The shadow pass keeps it; the plan
// reads it to decide what to draw again (a map whose key still serves is kept).
struct HeldMaps {
    MapLayout layout;
    std::vector<MapKey> maps2D, cubes;
    // Frames drawn so far, and the frame each map was last drawn in (as maps2D and cubes).
    std::uint64_t frame = 0;
    std::vector<std::uint64_t> drawn2D, drawnCubes;
};

class FramePlan {
public:
    // Does planning `s` with `options` use view samples (a fitted light that casts shadows,
    // with FitTo::ViewDepth)?
    static bool wantsViewSamples(const Scene& s, const RenderOptions& options);

    // Plans every light of `s` as world-space records: the main pass lights and looks up in
    // world space, so a record depends on the view only through the maps fitted to it.
    // `samples`: what the view sees, or null to fit to boxes. `fitCamera`: the camera the
    // maps follow when not the scene's (samples then come from its view). `held`: the maps
    // kept from earlier frames, which serve where nothing they were drawn from changed.
    void plan(const Scene& s, const RenderOptions& options, const PlanScene& scene,
              const ViewSamples* samples, const Camera* fitCamera, const HeldMaps& held);
    // A plan of `maps` alone, their light cameras given and no light records: for tests and
    // tools that draw chosen cameras.
    void planMaps(const std::vector<ShadowedLight>& maps, const PlanScene& scene,
                  const ShadowOptions& options, const HeldMaps& held);
    // Frames that follow one another as a view moves (the viewer, a scored path): each
    // stabilised map keeps its extent, and cascades their depth range, while those still
    // cover what the view sees (HeldExtent). Off: every frame is fitted afresh.
    void setFollowing(bool on) { mFollowing = on; }
    // The most records the main pass holds: a plan whose point lights' faces would need more
    // gives them cubes instead.
    void setRecordLimit(int records) { mRecordLimit = records; }
    // The most bytes and layers one map array may take: lights naming no map size get smaller
    // maps (halved together) until their arrays fit (MapSizing.h).
    void setMapBudget(std::size_t bytes, int layers) {
        mBudgetBytes = bytes;
        mMaxLayers = layers;
    }
    // Empty, or one sentence: the maps do not fit the budget even at the smallest size.
    const std::string& budgetNote() const { return mBudgetNote; }

    const std::vector<ShadowedLight>& shadowed() const { return mShadowed; }
    const std::vector<GpuLight>& records() const { return mLights; }
    const MapLayout& layout() const { return mLayout; }
    // Item indices (into PlanScene::items) of every map's depth casters, ascending per map
    // (ShadowedLight::firstCaster, casterCount), and whether each one's box might hold the
    // map's light (its faces are then not culled).
    const std::vector<std::uint32_t>& casters() const { return mCasters; }
    const std::vector<std::uint8_t>& castersHoldLight() const { return mHoldsLight; }
    // Depth casters left out of maps as outside their lights' volumes, over all maps.
    int castersCulled() const { return mCulled; }
    glm::ivec4 ranges() const { return mRanges; }  // ends of the record kinds
    bool hasCascades() const { return mHasCascades; }
    // Some point light's faces are maps of their own this frame (kFrameFaces: the cube
    // range's lookups pick a face's record). Never with cubes in the same frame.
    bool hasPointFaces() const { return mHasFaces; }
    // The type code (shaders/light_record.glsl) all single-map records share, or -1 when
    // they mix kinds or there are none.
    int singleMapKind() const;
    // No light this frame falls off with distance: every point, spot and area light has no
    // range and attenuation (c0, 0, 0), so the main pass's falloff is the constant 1 / c0.
    bool constantFalloff() const;

private:
    void orderLights(std::size_t sceneLights);
    void planCascades(const Scene& s, const RenderOptions& options, std::size_t lightIndex,
                      const glm::vec3& direction, int mapSize, int count, float aspect,
                      const Aabb& sceneBounds, GpuLight& g);
    // Point lights the view sees all around: a map per face it looks up, as records after
    // the light's own (like cascades), in place of a cube.
    void planFaces(const Scene& s, const RenderOptions& options, std::size_t lightIndex,
                   std::uint8_t faces, int mapSize, GpuLight& g);
    void planLights(const Scene& s, const RenderOptions& options, const PlanScene& scene,
                    const ViewSamples* samples, bool faces);
    void planWithin(const Scene& s, const RenderOptions& options, const PlanScene& scene,
                    const ViewSamples* samples, bool faces);
    void fitBudget(const Scene& s, const RenderOptions& options, const PlanScene& scene,
                   const ViewSamples* samples, bool faces);
    int wantedSize(const Light& light, const RenderOptions& options) const;
    // Light `index`'s size by need (`wanted`, 0: its own) made smaller where its fitted window
    // is narrower than its whole cone or face (windowMapSize).
    int windowSize(std::size_t index, const Light& light, const RenderOptions& options, int wanted);
    // Points mFit.samples at what `light`'s fits read: with a range, only the samples within
    // it (mWithin); false when that leaves none (the light lights nothing the view sees).
    bool withinRange(const Light& light, const ViewSamples* samples);
    // FrameMaps.cpp: the maps' places in their arrays (and the records' map fields), their
    // casters and keys, and which to draw again.
    void layOutMaps(const ShadowOptions& options);
    void keepHeldArray(MapLayout& layout);
    void fillMapRecords();
    void collectCasters(const PlanScene& scene, const ShadowOptions& options);
    void chooseRedraws(const HeldMaps& held, int budget);
    void keepWaiting(const HeldMaps& held, int budget);
    void writeLookup(const ShadowedLight& light, const MapKey& key);

    static constexpr int kMaxCascades = 4;
    // Extents a light may hold: its single map's (0, also where a point light tries one
    // frustum), its cascades' (0..3) or its faces' (1..6, apart from the frustum it tried).
    static constexpr int kHeldMaps = 7;
    // What a following frame keeps of the previous one, per scene light: its maps' extents
    // and the depth range its cascades split.
    struct Held {
        HeldExtent maps[kHeldMaps];
        glm::vec2 splitRange{0.0f};
        int cascades = 0;  // 0: no range held
    };
    // Light `i`'s, or null when not following.
    Held* held(std::size_t i);

    // What the last plan was made from: a frame whose inputs are all the same keeps it
    // (a still view of an unchanged scene plans nothing). Compared in place, so an unchanged
    // frame allocates nothing.
    struct Made {
        bool valid = false;
        std::uint64_t geometry = 0, samples = 0;  // PlanScene::revision, ViewSamples generation
        std::vector<Light> lights;
        Camera camera, fitCamera;
        bool hasFitCamera = false, following = false;
        RenderOptions options;
    };
    bool unchanged(const Scene& s, const RenderOptions& options, const PlanScene& scene,
                   const ViewSamples* samples, const Camera* fitCamera) const;

    Made mMade;
    bool mFollowing = false;
    std::vector<Held> mHeld;  // grows with the scene's lights, never shrinks
    std::vector<ShadowedLight> mShadowed;
    std::vector<GpuLight> mLights;          // scene lights, then cascade records
    std::vector<GpuLight> mCascadeRecords;  // reused every frame
    std::vector<GpuLight> mOrdered;         // reused every frame
    std::vector<int> mRemap;                // scene light -> record, reused
    std::vector<std::uint8_t> mHasMap;      // scene light has a map this frame
    glm::ivec4 mRanges{0};
    bool mHasCascades = false, mHasFaces = false;
    int mRecordLimit = 1 << 30;
    std::size_t mBudgetBytes = ~std::size_t(0);
    int mMaxLayers = 1 << 30;
    int mSizeCap = 0;  // 0, or the largest size of a light naming none (fitBudget)
    std::string mBudgetNote;
    // keepWaiting's candidates: -priority, index into mShadowed, slot held.
    struct Waiting {
        double order = 0.0;
        std::size_t light = 0, slot = 0;
        bool operator<(const Waiting& o) const {
            return order < o.order || (order == o.order && light < o.light);
        }
    };
    std::vector<Waiting> mWaitOrder;
    Camera mFitCamera;
    FitScene mFit;        // reused every frame
    ViewSamples mWithin;  // a ranged light's samples (withinRange), storage kept
    MapLayout mLayout;
    MapLayout mHeldLayout;    // the arrays' layout when this plan began (HeldMaps::layout)
    std::vector<int> mSizes;  // reused: the 2D maps' sizes for mPacker
    MapPacker mPacker;
    std::vector<std::uint32_t> mCasters;
    std::vector<std::uint8_t> mHoldsLight;
    int mCulled = 0;
};

}  // namespace gnomon::shadow
