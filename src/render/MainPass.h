// The main pass: the scene from the view camera, lit per light in world
// space, each fragment looking up every shadowed light's map. Program variants (filter,
// outside policy, shadowed rule, shadows off) are #defines injected into one shader file,
// compiled once and cached.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "gl/Objects.h"
#include "gnomon/Options.h"
#include "render/GpuScene.h"
#include "render/RayMarks.h"
#include "render/ShadowPass.h"
#include "shadow/LightRecord.h"

namespace gnomon::render {

class RayScene;
struct LightLists;
class TiledLights;
class TransmittancePass;
class VisibilityTarget;

struct MainPassInputs {
    glm::mat4 viewFromWorld{1.0f};
    glm::mat4 clipFromView{1.0f};
    PixelRayCamera pixelRays;  // shadow rays: each pixel's own ray (shadow_rays.glsl)
    // With cascades: the view depth that picks one, as a row on world positions (the depth
    // along the camera the cascades were fitted to; see main.frag.glsl).
    glm::vec4 cascadeDepth{0.0f};
    glm::vec3 ambient{0.0f};
    const std::vector<GpuLight>* lights = nullptr;  // the scene's lights, then cascade records
    // The light order and screen tiles (ranges: ends of the unshadowed, map, cube and
    // cascaded records).
    const TiledLights* tiled = nullptr;
    bool hasCascades = false;  // some light is cascaded this frame
    // Some point light has a cube this frame (HAS_CUBES), bound or not: under --shadow-rays
    // all the lookups read no map (shadowCubes null) and trace the cube's light all the same.
    bool hasCubes = false;
    bool pointFaces = false;  // point lights' faces are maps of their own (shadow::FramePlan)
    // The kind (lights.glsl's type code) every single-map record shares, or -1 when they mix
    // (FramePlan::singleMapKind): the program drops the other kinds' light code.
    int singleMapKind = -1;
    // No light falls off with distance (FramePlan::constantFalloff): the program drops the
    // distance terms.
    bool constantFalloff = false;
    // The maps the lookups read: 2D array, cube-map array; null when no light has one or
    // nothing reads them (--shadow-rays all), and a 1x1 stand-in is bound instead.
    const gl::Texture* shadowMaps = nullptr;
    const gl::Texture* shadowCubes = nullptr;
    // The 2D maps' caster edges (EdgeMaps) under --shadow-rays uncertain; null: none drawn,
    // and a 1x1 array without edges is bound instead.
    const gl::Texture* edgeMaps = nullptr;
    // The 2D maps' blurred moments (MomentPass) for the moment filters; null otherwise.
    const gl::Texture* shadowMoments = nullptr;
    // The view's depth at the output's size (ViewDepthPass) when contact shadows are on (and
    // shadows are): null otherwise.
    const gl::Texture* viewDepth = nullptr;
    // Coloured shadows' transmittance maps, when a blended caster tints a shadowed light.
    const TransmittancePass* transmittance = nullptr;
    // The casters' BVH when shadow rays replace the lookups (--shadow-rays all); else null.
    const RayScene* rays = nullptr;
    // The target's depth holds the view's opaque depth already (ViewDepthPass, copied): the
    // pass tests LEQUAL, which only the surface kept there passes (nothing lies nearer), and
    // writes none, so each pixel is shaded once.
    bool depthReady = false;
    // The frame's target, bound: under --shadow-rays uncertain the pixels the maps were unsure
    // of are drawn again into it (RayMarks.h). Null: rays in the one draw.
    const gl::Texture* targetColour = nullptr;
    const gl::Texture* targetDepth = nullptr;
};

class MainPass {
public:
    MainPass();
    // Draws the frame; with `visibility`, then stores each light's shadow visibility, map
    // texel size (and with coloured shadows transmittance) for every visible pixel.
    // `floor`: the same geometry and shadow lookups with one diffuse term per light and
    // nothing else (no textures, specular or falloff): what `gnomon bench` compares against.
    void render(const GpuScene& scene, const MainPassInputs& in, const RenderOptions& options,
                const VisibilityTarget* visibility = nullptr, bool floor = false);
    // Lights one frame can hold: the uniform block size limit / the record size, at most 256.
    int maxLights() const { return mMaxLights; }
    // Entries the light order holds (the uniform block's size allows).
    int orderCapacity() const { return mOrderCapacity; }
    // Draws of the last render() whose shadow rays ran in a pass of their own (RayMarks.h).
    int rayPasses() const { return mRayPasses; }
    // Draws with at most this many lights get a program whose light loops are written out
    // (main.frag.glsl, UNROLLED_LIGHTS); more would make a long program to build for each
    // count of each kind a frame or tile has (15 lights: 12 s to build mixed-lights' tiles).
    static constexpr int kMaxUnrolledLights = 8;

private:
    // What every program of one frame's draws is given (the shaders' uniform locations).
    struct FrameUniforms {
        const MainPassInputs* in = nullptr;
        glm::vec3 eye{0.0f};  // the camera's world position
        glm::vec4 viewZFromDepth{0.0f};
        glm::mat4 clipFromWorld{1.0f};  // contact shadows' march
        float shadowFactor = 0.0f, contactLength = 0.0f, lightBleed = 0.0f;
        glm::vec3 depthAware{0.0f};  // steps, map and cube stored-depth spacing
        glm::ivec4 ranges{0};        // the light order's range: every light, or one tile's
        int first = 0;
        int recordLight = -1;      // ES visibility passes: the scene light recorded
        int tileShift = -1;        // light lists: log2 of their tiles' side (-1: no lists)
        glm::ivec2 rayPyramid{0};  // the second uncertain draw: its jobs' numbering (RayMarks)
    };
    void useProgram(const gl::Program& p, const FrameUniforms& u);
    void recordVisibilityByLight(const GpuScene& scene, const RenderOptions& options,
                                 FrameUniforms u, const VisibilityTarget& visibility, bool floor);
    // Which of the items a draw takes: every one, or the opaque (and masked) or blended ones.
    enum class Items { All, Opaque, Blended };
    // Where an uncertain draw's rays run: in it, or in RayMarks' pass between its first draw
    // (the maps' answers, alpha 0 and a ray job where a ray must decide: Mark) and the second
    // (the rays' answers: Resolve).
    enum class RayDraw { Inline, Mark, Resolve };
    void drawItems(const GpuScene& scene, const RenderOptions& options, const FrameUniforms& u,
                   bool visibilityPass, bool floor, Items which = Items::All,
                   RayDraw rays = RayDraw::Inline);
    // The frame's items; under --shadow-rays uncertain the pixels a ray decides drawn again.
    void drawShaded(const GpuScene& scene, const RenderOptions& options, const FrameUniforms& u,
                    bool floor);
    // What an item's own content leaves out of its program, beyond what the frame's does.
    struct ItemVariant {
        bool receiverOnly = false;       // receives shadows, casts none (RECEIVER_ONLY)
        bool noSpecular = false;         // its material has no highlight (NO_SPECULAR)
        RayDraw rays = RayDraw::Inline;  // SHADOW_RAYS_MARK, SHADOW_RAYS_RESOLVE
        bool operator==(const ItemVariant&) const = default;
    };
    // `material`: the MATERIAL_PATH variant (textures, masks, blending). `counts`: the draw's
    // lights of each kind when its loops are written out per light, or all -1. `lists`: the
    // draw reads each pixel's lights from the light lists (LIGHT_LISTS).
    const gl::Program& program(const RenderOptions& options, const MainPassInputs& in,
                               glm::ivec4 counts, bool visibilityPass, bool material, bool floor,
                               ItemVariant item, bool lists);
    void uploadLights(const std::vector<GpuLight>& lights, const std::vector<std::int32_t>& order);
    // The light lists' texture on unit 9, uploaded when it changed; the shift of their tiles.
    int bindLists(const LightLists& lists);
    bool bindMaps(const MainPassInputs& in, const ShadowOptions& so);

    std::map<std::uint64_t, gl::Program> mPrograms;  // by the variant's packed choices
    int mMaxLights = 0, mOrderCapacity = 4096;
    int mRayPasses = 0;
    gl::Buffer mLights;  // sized for mMaxLights once; the used part is updated on change
    std::vector<GpuLight> mUploaded;
    gl::Buffer mOrder;  // the light order (mOrderCapacity entries), updated on change
    std::vector<std::int32_t> mUploadedOrder;
    gl::Texture mLists;  // the light lists' tiles (TiledLights.h, LightLists), updated on change
    std::vector<glm::ivec4> mUploadedLists;
    // Unit 0 (2D maps): compares for native formats, filters encoded depth for colour ones.
    // Unit 1 (cubes): always compares. Rebuilt only when the options they follow change.
    gl::Sampler mMapSampler, mCubeSampler;
    // NEAREST, no comparison: stored depth (PCSS, contact shadows), transmittance cubes.
    gl::Sampler mRawSampler;
    gl::Sampler mMomentSampler;  // moments: LINEAR, clamped (one bilinear lookup filters them)
    gl::Sampler mTintSampler;    // 2D transmittance maps: LINEAR, clamped
    int mMapSamplerKey = -1, mCubeSamplerKey = -1;          // the filters they were made for
    gl::Texture mDummyMaps, mDummyCubes, mNoEdges;          // bound when a kind of map is absent
    std::vector<std::pair<float, std::uint32_t>> mBlended;  // distance, item: reused per frame
    std::vector<std::uint32_t> mBackFaces;  // opaque double-sided items: reused per frame
    RayMarks mRayMarks;
};

}  // namespace gnomon::render
