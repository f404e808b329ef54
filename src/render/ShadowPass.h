// The shadow pass: one depth-only rendering per shadowed light.
// Single-frustum lights (directional, spot, area, textbook point cameras) each own a square of
// a layer of a 2D array (layers as large as the largest map; smaller maps share layers,
// placed by shadow::packMaps);
// omnidirectional point lights own six layers of a cube-map array, drawn in one instanced
// pass with gl_Layer from the vertex shader, or six passes where the driver cannot.
// Casters outside a light's volume are not drawn into its map, and a map is re-rendered
// only when its camera, the depth state or a caster inside its volume changed.
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "gl/Objects.h"
#include "gnomon/Options.h"
#include "gnomon/Renderer.h"
#include "render/GpuScene.h"
#include "shadow/FrustumClip.h"
#include "shadow/MapAtlas.h"
#include "shadow/ShadowMath.h"

namespace gnomon::render {

struct ShadowedLight {
    int light = 0;  // index into Scene::lights
    int mapSize = 1024;
    shadow::LightCameraFrame frame;
    bool depthClamp = false;  // fitted cameras: casters in front of near still cast
    int layer = 0;            // 2D array layer, or cube index in the cube-map array
    int record = 0;           // the main pass light record this map belongs to
    int cascade = -1;         // cascade index of a directional light, -1 if not cascaded
    // The view depths whose pixels read this map (a cascade's slice and the previous
    // cascade's blend band; every depth for the others).
    float depthFrom = 0.0f, depthTo = std::numeric_limits<float>::max();
    glm::ivec2 origin{0};  // 2D maps: the map's lower-left texel in its layer (shadow pass)
    int face = -1;         // a point light's face drawn as a map of its own (0..5), else -1
};

// What a light's map sees, for culling what it need not draw: its clip volume (casters in
// front of the near plane count when the depth is clamped), or its cube's: within the far
// sphere and, when only some faces are drawn, inside one of theirs.
class LightVolume {
public:
    explicit LightVolume(const ShadowedLight& light)
        : mLight(light),
          mCube(light.frame.kind == shadow::FrameKind::Cube),
          mClipFromWorld(mCube ? glm::mat4(1.0f) : light.frame.clipFromWorld()),
          mEye(glm::inverse(light.frame.lightFromWorld)[3]) {
        for (int face = 0; mCube && light.frame.faces != shadow::kAllCubeFaces && face < 6;
             ++face) {
            if (light.frame.drawsFace(face))
                mFaces[std::size_t(mFaceCount++)] = light.frame.faceClipFromWorld(face);
        }
    }
    bool outside(const Aabb& box) const {
        if (!mCube) return shadow::outsideClipVolume(box, mClipFromWorld, mLight.depthClamp);
        if (shadow::outsideCube(box, mLight.frame)) return true;
        for (int i = 0; i < mFaceCount; ++i) {
            if (!shadow::outsideClipVolume(box, mFaces[std::size_t(i)], true)) return false;
        }
        return mFaceCount > 0;
    }
    // Might `box` hold the light (a spot's or point light's position)? Then a closed caster
    // in it is seen from inside, every face turned away, and culling would drop it all: a
    // point light inside a closed caster (the spider's abdomen in assimp-testmodels'
    // spider.fbx) would otherwise light everything around it.
    bool holdsLight(const Aabb& box) const {
        return !mLight.frame.orthographic && glm::all(glm::lessThanEqual(box.min, mEye)) &&
               glm::all(glm::lessThanEqual(mEye, box.max));
    }

private:
    const ShadowedLight& mLight;
    bool mCube;
    glm::mat4 mClipFromWorld;
    glm::vec3 mEye;                     // the light's position (perspective and cube frames)
    std::array<glm::mat4, 6> mFaces{};  // the drawn faces' clip volumes, when not all six
    int mFaceCount = 0;
};

// A pass's name for one map in FrameStats::passes: "<what> light N[, cascade K | face F]".
inline std::string mapPassName(const char* what, const ShadowedLight& light) {
    return std::string(what) + " light " + std::to_string(light.light) +
           (light.cascade >= 0 ? ", cascade " + std::to_string(light.cascade) : "") +
           (light.face >= 0 ? ", face " + std::to_string(light.face) : "");
}

// The passes that follow the shadow pass per map (moments, transmittance) run for the maps
// it drew (`drawn`: indices into `lights`), or for every map when `all` (their own targets
// are new): `pass(light)` for each.
template <typename Pass>
void forMapsDrawn(const std::vector<ShadowedLight>& lights, const std::vector<int>& drawn, bool all,
                  const Pass& pass) {
    if (all) {
        for (const ShadowedLight& light : lights)
            pass(light);
    } else {
        for (int i : drawn)
            pass(lights[std::size_t(i)]);
    }
}

struct ShadowPassStats {
    int rendered = 0;             // maps drawn this frame (the others were kept)
    std::uint64_t triangles = 0;  // triangles submitted to the drawn maps (cubes: x 6)
    int culled = 0;               // caster draws skipped as outside a light's volume
};

class PassClock;

class ShadowPass {
public:
    // `layeredCubes` false forces six passes per cube (to test the fallback path).
    explicit ShadowPass(bool layeredCubes = true);
    // Renders (or keeps) every light's map. Lights with frame.kind == Cube go to the cube
    // array (layer = cube index), others to the 2D array.
    // With `clock`, each map drawn is timed into `timings`.
    ShadowPassStats render(const GpuScene& scene, std::vector<ShadowedLight>& lights,
                           const ShadowOptions& options, PassClock* clock = nullptr,
                           std::vector<PassTiming>* timings = nullptr);
    // Every map is drawn again next frame.
    void invalidate();
    // A bare depth-only draw of every caster into a size x size buffer through
    // `clipFromWorld` (back faces culled, no offsets, no clamp, no per-caster culling),
    // timed with glFinish(): milliseconds.
    double bareDepthPass(const GpuScene& scene, const glm::mat4& clipFromWorld, int size);
    // The 2D maps: a depth texture, or for colour formats an RGBA8 texture of encoded depth.
    const gl::Texture& maps() const { return mMaps; }
    // The 2D maps' depth as the rasteriser tested it: the maps themselves, or for colour
    // formats the depth buffer drawn beside the encoded maps.
    const gl::Texture& mapDepth() const { return mColourDepth ? mColourDepth : mMaps; }
    DepthFormat mapFormat() const { return mMapFormat; }
    const gl::Texture& cubes() const { return mCubes; }
    int mapArraySize() const { return mMaps ? mMaps.width() : 0; }
    // Counts the arrays' allocations: what holds their textures must remake its framebuffers
    // when it changes (a new texture may reuse a deleted one's name).
    int generation() const { return mGeneration; }
    // The maps the last render() drew (the others were kept): indices into its `lights`.
    const std::vector<int>& drawn() const { return mDrawn; }
    std::size_t bytes() const;
    // A light's map as 16-bit grey, top row first (darker = nearer); cubes unfold as a
    // horizontal strip of the six faces +X, -X, +Y, -Y, +Z, -Z.
    Image16 readBack(const ShadowedLight& light) const;

private:
    void layOut(std::vector<ShadowedLight>& lights, const ShadowOptions& options);
    void drawMap(const GpuScene& scene, const ShadowedLight& light, const ShadowOptions& options,
                 const std::array<glm::mat4, 6>& m);
    struct LayerState {
        std::array<glm::mat4, 6> clipFromWorld{};  // one (2D map) or six (cube) used
        int mapSize = 0;
        glm::ivec3 place{-1};               // 2D maps: origin and layer
        std::uint64_t castersHash = ~0ull;  // geometry + the casters in the volume
        CullMode cull = CullMode::Back;
        float slope = -1.0f, units = -1.0f;
        bool depthClamp = false;
        DepthFormat format = DepthFormat::Depth32F;
        BlendShadows blend = BlendShadows::Dithered;
        std::uint8_t faces = shadow::kAllCubeFaces;  // cubes: the faces drawn
        bool operator==(const LayerState&) const = default;
        // A map drawn as `this` serves `want`: the same, its faces a superset of want's.
        bool serves(const LayerState& want) const;
    };
    void allocate2D(int size, int layers, DepthFormat format);
    void allocateCubes(int size, int cubes, DepthFormat format);
    // Depth programs: kPlain (2D maps, native depth), kCube (six faces at once), kColour +
    // 0..2 (r8, packed-256, packed-255 encoders); `alphaTested` adds the ALPHA_TEST variant,
    // `opaqueParts` (coloured shadows) keeps only blended casters' fully opaque texels.
    // Built on first use.
    static constexpr int kPlain = 0, kCube = 1, kColour = 2;
    const gl::Program& program(int variant, bool alphaTested, bool opaqueParts = false);
    void setDepthState(const ShadowOptions& options, bool depthClamp) const;
    // The casters of `light` that can reach its map (indices into scene.items()), and a hash
    // of them; fills mVisible.
    std::uint64_t collectCasters(const GpuScene& scene, const ShadowedLight& light,
                                 const ShadowOptions& options);
    // Draws mVisible with program `variant`, switching to its alpha-tested twin for masked
    // and dithered casters (their textures on unit 4); `setUniforms()` runs after each
    // program change.
    template <typename SetUniforms>
    void drawCasters(const GpuScene& scene, const ShadowOptions& options, int variant,
                     GLsizei instances, const SetUniforms& setUniforms);

    bool mLayered;
    gl::Program mPrograms[5][3];  // variant x plain, alpha-tested, opaque parts
    gl::Texture mMaps, mCubes;
    gl::Texture mColourDepth;  // depth test for colour formats
    DepthFormat mMapFormat = DepthFormat::Depth32F;
    std::vector<gl::Framebuffer> mFramebuffers;          // one per 2D layer
    gl::Framebuffer mCubeFramebuffer;                    // layered: the whole cube array
    std::vector<gl::Framebuffer> mCubeFaceFramebuffers;  // fallback: one per cube face
    std::vector<LayerState> mLayers, mCubeLayers;        // per 2D map (in lights' order), per cube
    std::vector<int> mSizes;                             // reused every frame
    std::vector<shadow::MapSlot> mSlots;                 // reused every frame
    std::vector<std::uint32_t> mVisible;                 // reused every frame
    std::vector<char> mHoldsLight;  // per item: its box holds the light (no face culling)
    std::vector<int> mDrawn;        // reused every frame
    gl::Texture mBareDepth;         // bareDepthPass's target
    gl::Framebuffer mBareFramebuffer;
    int mCulled = 0;
    int mGeneration = 0;
};

}  // namespace gnomon::render
