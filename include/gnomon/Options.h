// Render options: everything a user can set for a frame, as structs with one default each.
// Each member's flag name, range and one-line help are its entry in the option schema
// (gnomon/OptionSchema.h), from which the CLI, scene files, the viewer and validate() work.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace gnomon {

// What a shadowed fragment keeps.
enum class ShadowedRule {
    AmbientOnly,  // the light's diffuse and specular terms are dropped (course text)
    Factor,       // the colour is multiplied by shadowFactor (WebGL Programming Guide: 0.7)
};

// A fragment outside a light's shadow map.
enum class OutsidePolicy {
    Lit,    // correct: nothing in the map can shadow it
    Clamp,  // the textbooks' clamp-to-edge lookup, shows the error they warn about
};

// Faces drawn in the depth pass.
enum class CullMode { Back, Front, None };

// How the shadow map is sampled.
enum class ShadowFilter {
    None,     // one lookup filtered by mapFilter, compared by hand: hard, aliased edges
    Hw2x2,    // comparison sampler with LINEAR: 2x2 bilinear PCF (colour formats: one lookup)
    Pcf,      // pcfSize x pcfSize box of comparisons (2x2 bilinear each for native depth)
    Poisson,  // 16 taps of a rotated Poisson disc, pcfSize texels wide
    Pcss,     // percentage-closer soft shadows: a blocker search sizes a Poisson filter by the
              // penumbra of a light of lightRadius (lightAngle for directional lights)
    // Filterable maps: moments of depth, blurred, read with one bilinear lookup
    // (momentBlur, lightBleed). 2D maps only: point lights' cubes keep one comparison.
    Evsm2,  // exponential variance shadow maps, the positive warp (Lauritzen and McCool 2008)
    Evsm4,  // the same with the negative warp too: less light bleeding
    Msm,    // moment shadow maps, 4 moments, Hamburger (Peters and Klein 2015)
};
// Whether `f` reads moments of depth instead of comparing depths.
constexpr bool isMomentFilter(ShadowFilter f) {
    return f == ShadowFilter::Evsm2 || f == ShadowFilter::Evsm4 || f == ShadowFilter::Msm;
}
// Whether `f`'s look is a penumbra wider than a texel (PCSS's, the moments' blur), which a hard
// ray would replace rather than sharpen.
constexpr bool isPenumbraFilter(ShadowFilter f) {
    return f == ShadowFilter::Pcss || isMomentFilter(f);
}

// How a shadow map stores depth. Colour formats write gl_FragCoord.z from the
// fragment shader into an 8-bit RGBA target and compare by hand in the main pass; native
// formats are depth attachments compared by the sampler. Point-light cubes always use a
// native format (depth32f when a colour format is chosen).
enum class DepthFormat {
    R8,              // red channel of RGBA8: 1/256 steps (WebGL Programming Guide, ch. 10)
    Rgba8Packed256,  // four 8-bit channels, base 256 (its Shadow_highp)
    Rgba8Packed255,  // four 8-bit channels, base 255 (the online WebGL tutorial)
    Depth16,
    Depth24,
    Depth32F,
};

// Filtering of the stored depth before a comparison by hand: every lookup of a
// colour format, and --filter none on native depth (the LINEAR lookups of W. Brown's course text).
enum class MapFilter { Nearest, Linear };

// Shadow rays: whether a shadowed light's answer comes from its map or from a ray through a
// BVH of the casters (J. Story, "Hybrid Ray-Traced Shadows", GDC 2015: trace where the map is
// unsure).
enum class ShadowRayMode {
    Off,        // the maps answer every lookup
    All,        // every hard lookup of a shadowed light is one ray from the fragment to the light
    Uncertain,  // the map answers where it is sure, a ray where it is not (penumbra filters:
                // the map everywhere, see tracesShadowRays)
};

// What shadow a blended (AlphaMode::Blend) material casts.
enum class BlendShadows {
    Opaque,    // as if opaque: full shadow whatever its alpha (three.js's default)
    None,      // no shadow at all
    Dithered,  // a share of alpha of the map's texels is covered (hashed per texel), so
               // filtered lookups see partial shadow; the reference transmits 1 - alpha
    Coloured,  // light passing the material is tinted: a transmittance map per light beside
               // its depth map, T = (1 - alpha) mix(1, colour, alpha) per blended surface
};
// Under BlendShadows::Coloured a blended texel this opaque (alpha 255 of 255) blocks the light
// as an opaque one does: the shadow pass draws it into the depth maps (alpha_test_vertex.glsl),
// shadow rays stop at it (render/RayMasks.h) and the reference traces it so (truth/AlphaRays.h).
inline constexpr float kOpaqueBlendAlpha = 254.5f / 255.0f;

// What a fitted directional (or area) light's map is made to cover.
enum class FitTo {
    ViewDepth,  // the points the view's depth buffer sees, from a coarse depth pre-pass
                // (sample distribution shadow maps, Lauritzen et al. 2011)
    Boxes,      // the bounding boxes of the receivers inside the view frustum
};

// How a fitted point light that the view sees in more than one cube face is mapped.
enum class PointMaps {
    Faces,  // each face the view looks up, a perspective map fitted to what it sees there
            // (with FitTo::ViewDepth and a filter other than PCSS; else a cube)
    Cube,   // one cube map: every direction at the same density
};

// Where a render's options start (CLI --preset); flags given after it override.
enum class Preset {
    Default,   // gnomon's best: the scene's authored options with gnomon's bias defaults
    Textbook,  // the textbook's own numbers for the scene: constant tolerance, its depth
               // storage and lookups; acne and all (Scene::textbookOptions)
};

struct ShadowOptions {
    bool enabled = true;                         // false: every shadow test off, lighting unchanged
    OutsidePolicy outside = OutsidePolicy::Lit;  // lookups outside a light's map
    // Stored-depth units [0, 1) added to the map depth: the textbooks' tolerance. Default 0:
    // the receiver plane and the depth-aware step cover self-shadowing, while a constant in
    // stored depth is a distance that grows with the square of the distance from a spot or
    // point light and lifts shadows off their contacts (docs/techniques/acne-and-bias.md).
    float biasConstant = 0.0f;
    float biasDepthAware = 1.0f;  // + this many steps of the stored depth's spacing
    // glPolygonOffset factor in the depth pass, >= 0. It covers what the receiver plane leaves
    // (planes steeper than its cap); more lifts shadows off their casters' contacts, and 0
    // lets smooth meshes shadow themselves near their terminators
    // (docs/techniques/acne-and-bias.md).
    float biasSlope = 0.7f;
    float biasUnits = 2.0f;  // glPolygonOffset units in the depth pass, >= 0
    // Receiver-plane depth: each tap compares against the depth the receiver's own plane
    // has at the texel it reads (Isidoro 2006; Dou et al. 2014), instead of one depth for
    // every tap. Off: one reference depth per lookup (the textbooks').
    bool receiverPlane = true;
    // Lookup shift along the normal: texels x filter reach x sin(angle), 0..100. Not needed
    // with receiverPlane (its tolerance already follows the surface); 1 is the classic
    // companion of one reference depth per lookup.
    float normalOffset = 0.0f;
    // Faces culled in the depth pass, of closed meshes of single-sided materials only (an
    // open surface culled would cast from one side: glTF's NegativeScaleTest's panels).
    CullMode cull = CullMode::Back;
    ShadowFilter filter = ShadowFilter::Pcf;  // lookup filter
    int pcfSize = 3;                          // kernel width for Pcf and Poisson, odd, 1..9
    // Moment filters: the box blur's radius over the moments, texels (0..16: a (2r+1)^2 box;
    // 0 leaves filtering to the bilinear lookup's 2x2, see docs/techniques/filterable-maps.md),
    // and light-bleeding reduction: visibility below this share reads as shadow and the rest
    // is stretched over [0, 1] (0..0.99).
    int momentBlur = 0;
    float lightBleed = 0.1f;
    float lightRadius = 0.25f;  // Pcss: emitter radius of spot, point and area lights, world units
    float lightAngle = 1.0f;    // Pcss: angular radius of directional lights, degrees, 0..20
    int mapSize = 0;            // texels per side for every light, 64..8192; 0 = each light's own
    // The most spot and point light maps drawn again in a frame when many changed (moving
    // lights): the largest and longest waiting first, the rest keep the map last drawn (the
    // shadow of where their light was) until their turn; 0 = every map that changed.
    int mapRedraws = 0;
    // Fitted directional lights: 1..4 maps along the view; 0 = auto: with fitTo ViewDepth,
    // one per factor of 8 in the depth range the view sees (1..4); with Boxes, 1.
    int cascades = 0;
    FitTo fitTo = FitTo::ViewDepth;          // what fitted lights cover (docs/techniques.md)
    PointMaps pointMaps = PointMaps::Faces;  // needs fitTo ViewDepth (docs/techniques.md)
    // Fitted maps that follow the view keep a quantised size and move in whole texels, so
    // their edges hold still while the camera moves; false refits them exactly every frame
    // (each map uses its texels a little better, and its shadows shimmer).
    bool stabilise = true;
    float cascadeLambda = 0.75f;  // splits: 0 uniform .. 1 logarithmic
    float cascadeBlend = 0.1f;    // fraction of each cascade handed to the next (dithered), 0..0.5
    DepthFormat depthFormat = DepthFormat::Depth32F;  // storage of the maps
    MapFilter mapFilter = MapFilter::Nearest;         // hand-compared lookups: filtering of depth
    BlendShadows blendShadows = BlendShadows::Coloured;  // shadows of blended materials
    // Stand-in casters: the share of each mesh's triangles drawn into shadow maps, 0.001..1
    // (meshoptimizer's simplification, made once per value); 1 = the full meshes.
    float casterDetail = 1.0f;
    // Screen-space contact shadows: each pixel marches this far (world units) towards each
    // shadowed light through the view's depth, for the contacts a map misses; 0 = off.
    float contactLength = 0.0f;
    // Off: the maps alone decide (the textbooks' way); Uncertain: the map decides where it is
    // sure and a shadow ray where it is not; All: a shadow ray per lookup decides (exact hard
    // shadows, the error and timing reference; no map is drawn but for coloured shadows' tints
    // and --debug-view shadow-map).
    ShadowRayMode shadowRays = ShadowRayMode::Off;
    // Under Uncertain (OpenGL 4.5): each single-frustum map's casters' outlines drawn beside it,
    // so that a caster thinner than a texel, missing from the map, still sends the lookups
    // within a texel of it to rays (render/EdgeMaps.h).
    bool casterOutlines = true;

    bool operator==(const ShadowOptions&) const = default;
};

// Whether the main pass traces shadow rays under `s`: with shadows on, under All, and under
// Uncertain unless the filter's look is a penumbra (where the map keeps every answer).
constexpr bool tracesShadowRays(const ShadowOptions& s) {
    return s.enabled && (s.shadowRays == ShadowRayMode::All ||
                         (s.shadowRays == ShadowRayMode::Uncertain && !isPenumbraFilter(s.filter)));
}

// Diagnostic renderings: the shadow machinery itself drawn, an option like any other.
enum class DebugView {
    None,
    Cascades,     // tint each pixel by the cascade its shadow came from (red, green, blue, yellow)
    ShadowMap,    // instead of the scene, one light's maps in grey (lightOnly's, else the first
                  // shadowed light's): cascades side by side, a cube's faces in two rows
    LightFrusta,  // the scene with every shadow camera's volume drawn as lines, one colour per
                  // light
    Rays,         // tint the pixels where a shadow ray decided (--shadow-rays) in magenta
};

// How the main pass leaves out the lights that cannot reach part of the screen (tiled forward
// shading): each way gives the same image.
enum class LightTiles {
    Auto,   // the cheapest of the three below by a cost model of llvmpipe (--light-tiles on)
    Lists,  // one draw; each pixel reads its screen tile's list of lights from a texture
    Draws,  // one draw per screen tile, each with the lights that reach it
    Off,    // one draw, every light on every pixel
};

// How computed colours are stored in the output image.
enum class OutputEncoding {
    Linear,  // as computed, no transfer function: the textbooks' programs (built-in scenes)
    Srgb,    // sRGB-encoded for display, as glTF viewers do (loaded model files)
};

struct ShadingOptions {
    ShadowedRule shadowedRule = ShadowedRule::AmbientOnly;  // what a shadowed fragment keeps
    float shadowFactor = 0.7f;  // colour multiplier for ShadowedRule::Factor, 0..1
    OutputEncoding output = OutputEncoding::Linear;  // colours as computed, or sRGB-encoded
    // Ordered dithering of the 8-bit colours (within half a step) against banding.
    bool dither = true;
    // Main pass in screen tiles, each looking up only the lights that can reach it (tiled
    // forward shading): the same image, fewer lookups where spots or ranged lights are.
    LightTiles lightTiles = LightTiles::Auto;
    // The main pass starts from the view depth pass's depth, where that pass is drawn for
    // this view anyway, and shades only the surface nearest in each pixel: the same image,
    // no shading of surfaces that a nearer one covers later.
    bool depthPrepass = true;

    bool operator==(const ShadingOptions&) const = default;
};

struct RenderOptions {
    int width = 512;       // output width in pixels, 1..16384
    int height = 512;      // output height in pixels, 1..16384
    double time = 0.0;     // seconds: poses animated scenes (book triangle: 40 deg/s)
    int lightOnly = -1;    // >= 0: only this light (index) is on; -1: the scene's own switches
    ShadowOptions shadow;  // shadow technique
    DebugView debugView = DebugView::None;  // diagnostic tint of the picture
    ShadingOptions shading;

    // Empty when valid; otherwise one sentence per problem, naming the option.
    std::vector<std::string> validate() const;
    bool operator==(const RenderOptions&) const = default;
};

// Names as the CLI spells them, for parsing and printing.
const char* toString(ShadowedRule v);
const char* toString(OutsidePolicy v);
const char* toString(CullMode v);
const char* toString(ShadowFilter v);
const char* toString(DepthFormat v);
const char* toString(MapFilter v);
const char* toString(Preset v);
const char* toString(DebugView v);
const char* toString(BlendShadows v);
const char* toString(ShadowRayMode v);
const char* toString(FitTo v);
const char* toString(PointMaps v);
const char* toString(OutputEncoding v);
const char* toString(LightTiles v);
std::optional<ShadowedRule> parseShadowedRule(const std::string& s);
std::optional<OutsidePolicy> parseOutsidePolicy(const std::string& s);
std::optional<CullMode> parseCullMode(const std::string& s);
std::optional<ShadowFilter> parseShadowFilter(const std::string& s);
std::optional<DepthFormat> parseDepthFormat(const std::string& s);
std::optional<MapFilter> parseMapFilter(const std::string& s);
std::optional<Preset> parsePreset(const std::string& s);
std::optional<DebugView> parseDebugView(const std::string& s);
std::optional<BlendShadows> parseBlendShadows(const std::string& s);
std::optional<ShadowRayMode> parseShadowRayMode(const std::string& s);
std::optional<FitTo> parseFitTo(const std::string& s);
std::optional<PointMaps> parsePointMaps(const std::string& s);
std::optional<OutputEncoding> parseOutputEncoding(const std::string& s);
// True for the formats stored in colour channels (r8 and the RGBA8 packings).
bool isColourFormat(DepthFormat v);

}  // namespace gnomon
