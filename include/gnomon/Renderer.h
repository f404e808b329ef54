// The one headless path: render(scene, options) -> Image, used by the CLI, the tests and
// later the viewer. A Renderer owns an OpenGL 4.5 core context (EGL, no window) and the GPU
// copies of the last scene it drew; geometry is uploaded once and reused across frames.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gnomon/Image.h"
#include "gnomon/Options.h"
#include "gnomon/Scene.h"

namespace gnomon {

struct ContextOptions {
    bool verbose = false;  // print GL vendor/renderer/version to stderr
    bool debug = false;    // KHR_debug messages to stderr (on by default in Debug builds)
    // Draw in the OpenGL 4.5 core context current on the calling thread (a window's, as in
    // `gnomon view`) instead of creating a headless one; it must be current at every call.
    bool currentContext = false;
    // A headless OpenGL ES 3.0 context used as WebGL2 has it (what the browser build runs),
    // for trying that path natively: no cube-map arrays, buffer textures, indirect draws or
    // image stores (each has its stand-in), and no shadow-map readback (shadowMaps() throws).
    // Ignored with currentContext, whose API is found from the context itself.
    bool gles = false;
};

// One light's shadow map read back from the GPU (grey, darker = nearer).
struct ShadowMapImage {
    int light = 0;     // index into Scene::lights
    int cascade = -1;  // cascade index for cascaded directional lights, else -1
    int face = -1;     // a point light's face with a map of its own (0..5: +X, -X, +Y, ...)
    Image16 depth;     // stored depth 0..1 scaled to 0..65535
};

// One pass of a frame, measured with Renderer::setPassTiming (gnomon bench): wall time
// from the previous glFinish() to this pass's glFinish() (llvmpipe's timer queries read
// ~0 for fragment-heavy passes), and what the driver counted where it can.
struct PassTiming {
    std::string name;  // "shadow light N" (", cascade K"), "main", "read-back"
    int light = -1;    // scene light of a shadow pass, else -1
    double milliseconds = 0.0;
    std::uint64_t triangles = 0;  // submitted (cubes: x 6)
    std::int64_t fragments = -1;  // fragment shader invocations; -1: the driver cannot count
};

// What a frame cost: N shadowed lights cost up to N shadow renderings plus the
// main one, and N maps of memory; maps whose light and casters did not change are kept.
// Under --shadow-rays all no map is drawn or in use unless coloured shadows' tints or
// --debug-view shadow-map read them (maps an earlier frame drew stay held, for a later one).
struct FrameStats {
    int shadowPasses = 0;            // shadow maps rendered this frame (kept ones: 0)
    int shadowMapsWaiting = 0;       // changed, kept as drawn earlier by --map-redraws
    int shadowMaps = 0;              // maps in use (a cascaded light: one per cascade)
    std::size_t shadowMapBytes = 0;  // GPU memory held by shadow maps (moments, transmittance)
    // Empty, or one sentence: the maps of lights naming no size did not fit one array's budget
    // (1 GiB, the driver's layers) even at the smallest size by need.
    std::string mapBudgetNote;
    int momentPasses = 0;  // evsm2, evsm4, msm: moment passes drawn (per map made: 1, 2 blurred)
    int transmittancePasses = 0;        // --blend-shadows coloured: transmittance maps drawn
    std::uint64_t shadowTriangles = 0;  // triangles submitted to shadow maps (cubes: x 6)
    std::uint64_t mainTriangles = 0;    // triangles submitted to the main pass
    int castersCulled = 0;              // caster draws skipped as outside a light's volume
    int lightTiles = 0;                 // screen tiles of the main pass (0: drawn untiled)
    int lightLists = 0;  // screen tiles whose lights one main-pass draw reads (0: no lists)
    // --shadow-rays all: the casters' BVH was built this frame (1), or kept (0: casters unchanged).
    int shadowRayBuilds = 0;
    // --shadow-rays uncertain: draws whose marked pixels were traced in a pass of their own
    // (0: the frame marked few, and the second draw traced them where they lie; or none).
    int shadowRayPasses = 0;
    // The main pass started from the view depth pass's depth (depth-prepass): each pixel
    // shaded once.
    bool mainFromViewDepth = false;
    std::vector<PassTiming> passes;  // with setPassTiming(true): each pass drawn, in order
};

// How much of one shadow map of the last frame the view uses: the share of the map's area
// (in 64 x 64 squares, a cube's faces each) that the view's pixels look up.
struct MapUsage {
    int light = 0;     // index into Scene::lights
    int cascade = -1;  // cascade index for cascaded directional lights, else -1
    int mapSize = 0;   // texels per side (per face of a cube)
    float share = 0.0f;
    bool cube = false;  // a point light's six faces, not one map
    int faces = 1;      // a cube's faces the view looks up (and draws; a kept cube may hold more)
    int face = -1;      // a point light's face with a map of its own (0..5: +X, -X, +Y, ...)
    // Changed, and kept as an earlier frame drew it by the redraw budget (--map-redraws).
    bool waiting = false;
};

// Per pixel and light, what the main pass's shadow lookups returned (gnomon score): values at
// [(y * width + x) * lights + light], rows top first. Lights without a lookup at a pixel
// (off, not shadowed, a non-receiver, nothing drawn) read visibility 1 and texel size 0.
struct ShadowVisibility {
    int width = 0, height = 0, lights = 0;
    std::vector<float> visibility;     // 0 shadowed .. 1 lit
    std::vector<float> texelWorld;     // world size of the map texel the lookup used
    std::vector<std::uint8_t> traced;  // 1 where a shadow ray decided (--shadow-rays), else 0
    // Per pixel (top-down rows, not per light): the scene object whose shadows were recorded
    // there, -1 where the main pass drew none that receives them.
    std::vector<int> object;
    // --blend-shadows coloured only (else empty): RGB transmittance per pixel x light (three
    // floats at 3 * cell), 1 where no blended caster tints the light.
    std::vector<float> tint;
};

// A texture in the renderer's OpenGL context, for a UI toolkit drawing in the same context
// (Dear ImGui's ImTextureID is the name): RGBA8, rows bottom-up. The renderer owns it.
struct GlTexture {
    unsigned glName = 0;  // 0: no texture
    int width = 0;
    int height = 0;
    explicit operator bool() const { return glName != 0; }
};

class Renderer {
public:
    // Creates the headless context; throws gnomon::Error (kind Gl) with one sentence
    // naming what is missing when no usable OpenGL 4.5 core is available.
    explicit Renderer(const ContextOptions& options = {});
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Renders one frame. Throws gnomon::Error for invalid options or scenes.
    Image render(const Scene& scene, const RenderOptions& options);
    // The same frame, and each light's shadow visibility per pixel as the main pass computed it.
    Image render(const Scene& scene, const RenderOptions& options, ShadowVisibility& visibility);
    // The same, with the shadow maps fitted to `fitCamera`'s view instead of the scene
    // camera's (cascade splits and the fitted maps follow it; the picture is the scene
    // camera's): what a view's shadows become when only the maps move, as gnomon score's
    // flicker metric asks. Fitted maps draw again whenever the fit camera changes.
    Image render(const Scene& scene, const RenderOptions& options, ShadowVisibility& visibility,
                 const Camera& fitCamera);
    // The same frame left on the GPU, not read back (the viewer): frameTexture() names it.
    void draw(const Scene& scene, const RenderOptions& options);
    // The texture holding the last frame: its bytes are what render() returns (sRGB-encoded
    // for --output-encoding srgb, not decoded when sampled; on OpenGL ES, which has no
    // texture views, sRGB frames are decoded when sampled). Empty before the first frame;
    // valid until the next frame.
    GlTexture frameTexture() const;
    // Draws the last frame's shadow maps of `light` (an index into Scene::lights) as
    // --debug-view shadow-map does, into a texture of width x height kept by the renderer,
    // and returns it; empty when that light had no map in the last frame. Maps the frame
    // left out (--shadow-rays all) are drawn first, from that frame's plan.
    GlTexture drawShadowMapPanel(int light, int width, int height);
    // The shadow maps of the last frame, one per shadowed light (drawn now where the frame
    // left them out, as drawShadowMapPanel says).
    std::vector<ShadowMapImage> shadowMaps();
    // The last frame's counts and timings; the reference stays valid until the next frame.
    // A reference, so a viewer that copies it into its own FrameStats every frame reuses that
    // copy's storage instead of allocating a new one.
    const FrameStats& lastFrameStats() const;
    // For each map of the last frame, the share of it the view uses (measured from a coarse
    // depth pass of the view: the fit's own when it had one, else drawn now).
    std::vector<MapUsage> mapUsage();
    // Measure each pass (glFinish() between passes, so a little slower overall): fills
    // FrameStats::passes. Off by default.
    void setPassTiming(bool on);
    // Frames that follow one another as a camera moves (the viewer, gnomon score --path):
    // with --stabilise on, each fitted directional map keeps its extent, and cascades their
    // split range, while they still cover what the view sees and are at most 1.25x looser
    // than a fresh fit, so small moves change nothing in the maps. Off by default: every
    // frame is then fitted as a single render would be.
    void setFollowing(bool on);
    // Forget every kept shadow map and the view depth samples fitted maps follow: the next
    // frame renders them all (benchmarks of a frame whose lights and camera all moved).
    void invalidateShadowMaps();
    // Wall time of a bare depth-only draw of every caster into a size x size depth buffer
    // through the first shadowed light's camera of the last frame (back faces culled; no
    // offsets, clamp, per-caster culling or layers): the floor a shadow pass can approach.
    // Milliseconds; -1 without such a light.
    double measureBareDepthPass(int size);
    // Wall time of the last frame's main pass drawn by the simplest shader with the same
    // geometry, lights and shadow lookups: one diffuse term per light times its visibility,
    // nothing else (no textures, specular, falloff or cones). The floor the main pass can
    // approach; it overwrites the last frame's image. Milliseconds; -1 before a frame.
    double measureMainFloor();
    // "vendor / renderer / version".
    std::string glInfo() const;

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

}  // namespace gnomon
