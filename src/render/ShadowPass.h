// The shadow pass: one depth-only rendering per map the frame plan (shadow::FramePlan) draws
// again, into the arrays its layout asks for.
// Single-frustum lights (directional, spot, area, textbook point cameras) each own a square of
// a layer of a 2D array (layers a power of two at least as large as the largest map; maps
// share layers, placed by shadow::MapPacker);
// omnidirectional point lights own six layers of a cube-map array, drawn in one instanced
// pass with gl_Layer from the vertex shader, or six passes where the driver cannot.
// A map gets the casters the plan found inside its light's volume; the maps the plan keeps are
// not touched.
#pragma once

#include <string>
#include <vector>

#include "gl/Objects.h"
#include "gnomon/Options.h"
#include "gnomon/Renderer.h"
#include "render/EdgeMaps.h"
#include "render/GpuScene.h"
#include "shadow/FramePlan.h"

namespace gnomon::render {

using shadow::ShadowedLight;

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
    // Draws the maps `plan` marks for redrawing (ShadowedLight::redraw), after remaking the
    // arrays if its layout differs. With `clock`, each map drawn is timed into `timings`.
    ShadowPassStats render(const GpuScene& scene, const shadow::FramePlan& plan,
                           const ShadowOptions& options, PassClock* clock = nullptr,
                           std::vector<PassTiming>* timings = nullptr);
    // What the arrays hold: the plan's input for what it may keep.
    const shadow::HeldMaps& held() const { return mHeld; }
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
    // The 2D maps' caster edges (EdgeMaps), drawn under --shadow-rays uncertain where the
    // driver can; null otherwise.
    const gl::Texture* edgeMaps() const { return mEdges.allocated() ? &mEdges.maps() : nullptr; }
    EdgeMaps& edges() { return mEdges; }
    // A light's map as 16-bit grey, top row first (darker = nearer); cubes unfold as a
    // horizontal strip of the six faces +X, -X, +Y, -Y, +Z, -Z.
    Image16 readBack(const ShadowedLight& light) const;

private:
    // Remakes or releases the arrays where `layout` differs from what they are.
    void allocate(const shadow::MapLayout& layout);
    void drawMap(const GpuScene& scene, const shadow::FramePlan& plan, const ShadowedLight& light,
                 const ShadowOptions& options);
    void allocate2D(int size, int layers, DepthFormat format);
    void allocateCubes(int size, int cubes, DepthFormat format);
    // Depth programs: kPlain (2D maps, native depth), kCube (six faces at once), kColour +
    // 0..2 (r8, packed-256, packed-255 encoders); `alphaTested` adds the ALPHA_TEST variant,
    // `opaqueParts` (coloured shadows) keeps only blended casters' fully opaque texels.
    // Built on first use.
    static constexpr int kPlain = 0, kCube = 1, kColour = 2;
    const gl::Program& program(int variant, bool alphaTested, bool opaqueParts = false);
    void setDepthState(const ShadowOptions& options, bool depthClamp) const;
    // Draws `light`'s casters with program `variant`, switching to its alpha-tested twin for masked
    // and dithered casters (their textures on unit 4); `setUniforms()` runs after each
    // program change.
    template <typename SetUniforms>
    void drawCasters(const GpuScene& scene, const shadow::FramePlan& plan,
                     const ShadowedLight& light, const ShadowOptions& options, int variant,
                     GLsizei instances, const SetUniforms& setUniforms);

    bool mLayered;
    gl::Program mPrograms[5][3];  // variant x plain, alpha-tested, opaque parts
    gl::Texture mMaps, mCubes;
    gl::Texture mColourDepth;  // depth test for colour formats
    DepthFormat mMapFormat = DepthFormat::Depth32F;
    std::vector<gl::Framebuffer> mFramebuffers;          // one per 2D layer
    gl::Framebuffer mCubeFramebuffer;                    // layered: the whole cube array
    std::vector<gl::Framebuffer> mCubeFaceFramebuffers;  // fallback: one per cube face
    shadow::HeldMaps mHeld;
    void forgetOverlapping(const shadow::MapKey& key, std::size_t slot);
    std::vector<char> mHoldsLight;  // per item: its box holds the light (no face culling)
    std::vector<int> mDrawn;        // reused every frame
    // The order maps are drawn in: cubes, then 2D maps layer by layer, so one layer's passes
    // bind its framebuffer once and the driver bins them together. `slot`: the map's place in
    // mHeld (2D maps counted in the plan's order). Returns the number of 2D maps.
    struct Pass {
        std::size_t light = 0, slot = 0;
        int layer = -1;  // 2D maps' layer; -1 for cubes (first)
    };
    std::vector<Pass> mPasses;
    std::size_t orderPasses(const std::vector<ShadowedLight>& lights);
    // How each 2D layer is cleared this frame: whole, once, when every map in it is drawn again
    // (a whole clear costs drivers next to nothing; a scissored one is a drawn square on some,
    // llvmpipe among them), else square by square.
    enum class LayerClear : std::uint8_t { Whole, Done, Squares };
    std::vector<LayerClear> mLayerClears;
    EdgeMaps mEdges;
    bool mEdgesOn = false;   // this frame's 2D maps draw their casters' edges too
    gl::Texture mBareDepth;  // bareDepthPass's target
    gl::Framebuffer mBareFramebuffer;
    int mGeneration = 0;
};

}  // namespace gnomon::render
