// The lights of one frame as the passes need them: each light's main-pass record, ordered
// by kind for the shader's loops (shaders/lights.glsl), and the light cameras of those that
// cast shadows this frame. Fitted cameras cover what the view sees: the visible receivers'
// boxes, or, with FitTo::ViewDepth, the view's depth samples: directional and area lights cover
// them (which also choose cascade splits and, with `cascades` 0, their count), a point light
// whose samples fit a 90-degree cone gets one frustum over them instead of a cube, and a spot
// maps only the window of its cone they lie in. No drawing: the samples come in from the view
// depth pass. A plan is kept while everything it is made from is unchanged.
#pragma once

#include <cstdint>
#include <vector>

#include "gnomon/Options.h"
#include "gnomon/Scene.h"
#include "render/GpuScene.h"
#include "render/MainPass.h"
#include "render/ShadowPass.h"
#include "shadow/ShadowMath.h"

namespace gnomon::render {

class LightPlan {
public:
    // Does planning `s` with `options` use view samples (a fitted light that casts shadows,
    // with FitTo::ViewDepth)?
    static bool wantsViewSamples(const Scene& s, const RenderOptions& options);

    // Plans every light of `s` (the GPU copy `scene` gives the items' world boxes) as
    // world-space records: the main pass lights and looks up in world space, so a record
    // depends on the view only through the maps fitted to it.
    // `samples`: what the view sees, or null to fit to boxes. `fitCamera`: the camera the
    // maps follow when not the scene's (samples then come from its view).
    void plan(const Scene& s, const RenderOptions& options, const GpuScene& scene,
              const shadow::ViewSamples* samples, const Camera* fitCamera = nullptr);
    // Frames that follow one another as a view moves (the viewer, a scored path): each
    // stabilised map keeps its extent, and cascades their depth range, while those still
    // cover what the view sees (shadow::HeldExtent). Off: every frame is fitted afresh.
    void setFollowing(bool on) { mFollowing = on; }
    // After the shadow pass placed each map: its layer and its share of its array.
    void finish(const ShadowPass& pass);

    const std::vector<ShadowedLight>& shadowed() const { return mShadowed; }
    std::vector<ShadowedLight>& shadowed() { return mShadowed; }
    const std::vector<GpuLight>& records() const { return mLights; }
    glm::ivec4 ranges() const { return mRanges; }  // ends of the record kinds
    bool hasCascades() const { return mHasCascades; }
    // Some point light's faces are maps of their own this frame (kFrameFaces: the cube
    // range's lookups pick a face's record). Never with cubes in the same frame.
    bool hasPointFaces() const { return mHasFaces; }
    // The most records the main pass holds: a plan whose point lights' faces would need more
    // gives them cubes instead.
    void setRecordLimit(int records) { mRecordLimit = records; }
    // The type code (shaders/lights.glsl) all single-map records share, or -1 when they
    // mix kinds or there are none.
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
    void planLights(const Scene& s, const RenderOptions& options, const GpuScene& scene,
                    const shadow::ViewSamples* samples, bool faces);

    static constexpr int kMaxCascades = 4;
    // Extents a light may hold: its single map's (0, also where a point light tries one
    // frustum), its cascades' (0..3) or its faces' (1..6, apart from the frustum it tried).
    static constexpr int kHeldMaps = 7;
    // What a following frame keeps of the previous one, per scene light: its maps' extents
    // and the depth range its cascades split.
    struct Held {
        shadow::HeldExtent maps[kHeldMaps];
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
        std::uint64_t geometry = 0, samples = 0;  // GpuScene::revision, ViewSamples generation
        std::vector<Light> lights;
        Camera camera, fitCamera;
        bool hasFitCamera = false, following = false;
        RenderOptions options;
    };
    bool unchanged(const Scene& s, const RenderOptions& options, const GpuScene& scene,
                   const shadow::ViewSamples* samples, const Camera* fitCamera) const;

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
    Camera mFitCamera;
    shadow::FitScene mFit;  // reused every frame
};

}  // namespace gnomon::render
