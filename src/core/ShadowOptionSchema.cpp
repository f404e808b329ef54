// The shadow technique's options (Shadow maps, Tolerances, Filtering, Cascades groups) and
// the rules for when they have an effect; the schema itself is OptionSchema.cpp.
#include "core/OptionSchemaEntries.h"

namespace gnomon::schema {
namespace {

// The rules for when an option has an effect (OptionSpec::matters), each with its condition
// in the CLI's words. Options of these groups without one need shadows on (OptionSchema.cpp).
// Shadow rays have an effect where they are traced (and `off` wherever shadows are on).
bool raysTraced(const RenderOptions& o) {
    return o.shadow.shadowRays == ShadowRayMode::Off ? o.shadow.enabled
                                                     : tracesShadowRays(o.shadow);
}
bool outlinesDrawn(const RenderOptions& o) {
    return o.shadow.shadowRays == ShadowRayMode::Uncertain && tracesShadowRays(o.shadow);
}
bool momentFilters(const RenderOptions& o) {
    return isMomentFilter(o.shadow.filter);
}
constexpr const char* kMomentFilters = "--filter evsm2, evsm4 or msm";
bool pcss(const RenderOptions& o) {
    return o.shadow.filter == ShadowFilter::Pcss;
}
constexpr const char* kPcss = "--filter pcss";
bool kernelFilters(const RenderOptions& o) {
    return o.shadow.filter == ShadowFilter::Pcf || o.shadow.filter == ShadowFilter::Poisson;
}
// Depth is compared by hand: colour formats always, native ones with --filter none.
bool handCompared(const RenderOptions& o) {
    return o.shadow.filter == ShadowFilter::None || isColourFormat(o.shadow.depthFormat);
}
bool severalCascades(const RenderOptions& o) {
    return o.shadow.cascades != 1;
}
constexpr const char* kSeveralCascades = "more than one cascade (--cascades auto or 2..4)";

}  // namespace

// Whether and how maps are made.
void addShadowMaps(std::vector<OptionSpec>& s) {
    using K = OptionKind;
    using G = OptionGroup;
    auto add = [&](OptionSpec spec) { s.push_back(std::move(spec)); };
    add({.name = "shadows",
         .group = G::ShadowMaps,
         .doc = "off disables every shadow test, lighting unchanged",
         .kind = K::Switch,
         .max = 1,
         NUMBER(shadow.enabled, bool),
         .mattersWithoutShadows = true});
    add({.name = "map-size",
         .group = G::ShadowMaps,
         .doc = "shadow map texels per side for every light",
         .kind = K::Integer,
         .min = 64,
         .max = 8192,
         .zeroAllowed = true,
         .defaultNote = "0: each light's own",
         NUMBER(shadow.mapSize, int)});
    add({.name = "map-redraws",
         .group = G::ShadowMaps,
         .doc = "the most spot and point light maps drawn again a frame when many changed "
                "(moving lights): the longest waiting first, larger maps a little ahead; the "
                "others keep the "
                "map drawn last, the shadow of where their light was, until their turn",
         .kind = K::Integer,
         .min = 1,
         .max = 100000,
         .zeroAllowed = true,
         .defaultNote = "0: every map that changed",
         NUMBER(shadow.mapRedraws, int)});
    add({.name = "caster-detail",
         .group = G::ShadowMaps,
         .doc = "share of each mesh's triangles drawn into shadow maps: simplified stand-in "
                "casters (meshoptimizer), made once per value, or the file's own coarser "
                "version nearest that share (glTF MSFT_lod); 1 = the full meshes",
         .unit = "of the triangles",
         .kind = K::Real,
         .min = 0.001,
         .max = 1,
         NUMBER(shadow.casterDetail, float)});
    add({.name = "depth-format",
         .group = G::ShadowMaps,
         .doc = "shadow map storage (point-light cubes use depth32f for colour formats)",
         .kind = K::Choice,
         .choices = namesOf<DepthFormat>(),
         ENUM(shadow.depthFormat, DepthFormat)});
    add({.name = "fit-to",
         .group = G::ShadowMaps,
         .doc = "what fitted lights' maps cover: the points a coarse depth pre-pass of the view "
                "sees (a point light whose points fit a cube face's angle gets one frustum over "
                "them; a spot maps only the part of its cone they lie in), or the visible "
                "receivers' boxes",
         .kind = K::Choice,
         .choices = namesOf<FitTo>(),
         ENUM(shadow.fitTo, FitTo)});
    add({.name = "point-maps",
         .group = G::ShadowMaps,
         .doc = "a fitted point light the view sees in more than one cube face: with --fit-to "
                "view-depth, a map per face fitted to what the view sees there (finer on real "
                "scenes; pcss keeps cubes), or one cube (every direction at one density)",
         .kind = K::Choice,
         .choices = namesOf<PointMaps>(),
         ENUM(shadow.pointMaps, PointMaps)});
    add({.name = "stabilise",
         .group = G::ShadowMaps,
         .doc = "fitted maps that follow the view keep a quantised size and move in whole "
                "texels, so edges hold still as the camera moves (off: refitted exactly, shimmers)",
         .kind = K::Switch,
         .max = 1,
         NUMBER(shadow.stabilise, bool)});
    add({.name = "outside",
         .group = G::ShadowMaps,
         .doc = "lookups outside a light's map: lit, or clamp (shows the textbooks' error)",
         .kind = K::Choice,
         .choices = namesOf<OutsidePolicy>(),
         ENUM(shadow.outside, OutsidePolicy)});
    add({.name = "blend-shadows",
         .group = G::ShadowMaps,
         .doc = "shadows of alpha-blended materials: full, none, covering alpha of the map's "
                "texels, or light tinted by their colour",
         .kind = K::Choice,
         .choices = namesOf<BlendShadows>(),
         ENUM(shadow.blendShadows, BlendShadows)});
    add({.name = "shadow-rays",
         .group = G::ShadowMaps,
         .doc = "off: the maps alone decide (the textbooks' way, and the textbook preset's). "
                "all: each shadowed light's hard lookup is one ray through a BVH of the casters "
                "instead of the map (directional and area lights along their direction, area "
                "lights up to their plane as they light; spot and point lights to their "
                "position) along the line through the point, its first stretch within a "
                "rounding margin of the surface skipped, from the surface's own triangle where "
                "the pixel's ray meets it, as the reference starts it (WebGL2: near edge-on "
                "only); soft "
                "filters (pcss, moments) trace that hard ray too; masked and blended casters "
                "block it where their texels are opaque as the maps draw them; no map is drawn but "
                "for coloured shadows' tints and --debug-view shadow-map. uncertain: the map "
                "answers where it is sure, a ray "
                "where its filter's footprint is part lit and part shadowed (edges, thin "
                "casters), where a texel is lit only within the tolerance band, where it "
                "finds lit a surface within 7 degrees of edge-on to the light, or (OpenGL 4.5, "
                "single-frustum maps) where a caster's outline as the light sees it, drawn "
                "beside the map as lines, passes within a texel nearer the light than the "
                "surface (a caster thinner than a texel), traced in a "
                "pass of those pixels alone; under "
                "pcss and the moment filters, whose penumbra is their look, the map answers "
                "everywhere",
         .kind = K::Choice,
         .choices = namesOf<ShadowRayMode>(),
         ENUM(shadow.shadowRays, ShadowRayMode),
         .matters = raysTraced,
         .onlyWith = "--shadows on (uncertain: with a filter whose look is no wider penumbra: "
                     "none, hw2x2, pcf, poisson)"});
    add({.name = "caster-outlines",
         .group = G::ShadowMaps,
         .doc = "under --shadow-rays uncertain (OpenGL 4.5): draw each single-frustum map's "
                "casters' outlines as the light sees them (edges between a triangle facing it "
                "and one facing away, and open borders) beside the map as lines, and send to a "
                "ray a lookup the map is sure of where an outline within its four texels lies "
                "nearer the light than the surface: a caster thinner than a texel, which the map "
                "can miss, keeps its shadow. off: no outline pass and no outline memory (4 bytes "
                "a map texel), and such casters leak",
         .kind = K::Switch,
         .max = 1,
         NUMBER(shadow.casterOutlines, bool),
         .matters = outlinesDrawn,
         .onlyWith = "--shadow-rays uncertain"});
}

// What keeps lit surfaces from shadowing themselves.
void addTolerances(std::vector<OptionSpec>& s) {
    using K = OptionKind;
    using G = OptionGroup;
    auto add = [&](OptionSpec spec) { s.push_back(std::move(spec)); };
    add({.name = "bias-constant",
         .group = G::Tolerances,
         .doc = "tolerance added to the stored depth",
         .unit = "stored-depth units",
         .kind = K::Real,
         .max = 1,
         .maxExclusive = true,
         NUMBER(shadow.biasConstant, float)});
    add({.name = "bias-depth-aware",
         .group = G::Tolerances,
         .doc = "plus this many steps of the stored depth's spacing for the map's format (float "
                "storage: one ulp of 0.5, or the lookup's own float rounding where larger)",
         .unit = "steps",
         .kind = K::Real,
         .max = 1000,
         NUMBER(shadow.biasDepthAware, float)});
    add({.name = "bias-slope",
         .group = G::Tolerances,
         .doc = "polygon-offset factor in the depth pass",
         .kind = K::Real,
         .max = 100,
         NUMBER(shadow.biasSlope, float)});
    add({.name = "bias-units",
         .group = G::Tolerances,
         .doc = "polygon-offset units in the depth pass",
         .kind = K::Real,
         .max = 1e6,
         NUMBER(shadow.biasUnits, float)});
    add({.name = "receiver-plane",
         .group = G::Tolerances,
         .doc = "compare each tap against the receiver's plane at the texel it reads (off: one "
                "reference depth per lookup)",
         .kind = K::Switch,
         .max = 1,
         NUMBER(shadow.receiverPlane, bool)});
    add({.name = "normal-offset",
         .group = G::Tolerances,
         .doc = "lookup shift along the normal, in texels x the filter's reach x sin(light angle)",
         .unit = "texels",
         .kind = K::Real,
         .max = 100,
         NUMBER(shadow.normalOffset, float)});
    add({.name = "cull",
         .group = G::Tolerances,
         .doc = "faces culled in the depth pass (only on solids: closed, wound outwards, not cut "
                "by a texture)",
         .kind = K::Choice,
         .choices = namesOf<CullMode>(),
         ENUM(shadow.cull, CullMode)});
}

// How a lookup reads the map.
void addFiltering(std::vector<OptionSpec>& s) {
    using K = OptionKind;
    using G = OptionGroup;
    auto add = [&](OptionSpec spec) { s.push_back(std::move(spec)); };
    add({.name = "filter",
         .group = G::Filtering,
         .doc = "shadow map lookup filter",
         .kind = K::Choice,
         .choices = namesOf<ShadowFilter>(),
         ENUM(shadow.filter, ShadowFilter)});
    add({.name = "pcf-size",
         .group = G::Filtering,
         .doc = "kernel width for pcf and poisson",
         .unit = "texels",
         .kind = K::Integer,
         .min = 1,
         .max = 9,
         .odd = true,
         NUMBER(shadow.pcfSize, int),
         .matters = kernelFilters,
         .onlyWith = "--filter pcf or poisson"});
    add({.name = "moment-blur",
         .group = G::Filtering,
         .doc = "evsm2, evsm4, msm: radius of the box blur over the moments (0: none)",
         .unit = "texels",
         .kind = K::Integer,
         .max = 16,
         NUMBER(shadow.momentBlur, int),
         .matters = momentFilters,
         .onlyWith = kMomentFilters});
    add({.name = "light-bleed",
         .group = G::Filtering,
         .doc = "evsm2, evsm4, msm: light-bleeding reduction, visibility below this reads as "
                "shadow",
         .kind = K::Real,
         .max = 0.99,
         NUMBER(shadow.lightBleed, float),
         .matters = momentFilters,
         .onlyWith = kMomentFilters});
    add({.name = "light-radius",
         .group = G::Filtering,
         .doc = "pcss: emitter radius of spot, point and area lights",
         .unit = "world units",
         .kind = K::Real,
         .max = 1e4,
         NUMBER(shadow.lightRadius, float),
         .matters = pcss,
         .onlyWith = kPcss});
    add({.name = "light-angle",
         .group = G::Filtering,
         .doc = "pcss: angular radius of directional lights",
         .unit = "degrees",
         .kind = K::Real,
         .max = 20,
         NUMBER(shadow.lightAngle, float),
         .matters = pcss,
         .onlyWith = kPcss});
    add({.name = "contact-length",
         .group = G::Filtering,
         .doc = "screen-space contact shadows: march this far towards each shadowed light "
                "through the view's depth, for contacts the map misses (0: off)",
         .unit = "world units",
         .kind = K::Real,
         .max = 1e6,
         NUMBER(shadow.contactLength, float)});
    add({.name = "map-filter",
         .group = G::Filtering,
         .doc = "filtering of the stored depth before a comparison by hand (colour formats, and "
                "--filter none)",
         .kind = K::Choice,
         .choices = namesOf<MapFilter>(),
         ENUM(shadow.mapFilter, MapFilter),
         .matters = handCompared,
         .onlyWith = "--filter none or a colour --depth-format (r8, rgba8-packed-*)"});
}

// Directional lights split along the view.
void addCascades(std::vector<OptionSpec>& s) {
    using K = OptionKind;
    using G = OptionGroup;
    auto add = [&](OptionSpec spec) { s.push_back(std::move(spec)); };
    add({.name = "cascades",
         .group = G::Cascades,
         .doc = "fitted directional lights: cascaded maps along the view; auto: one per factor of "
                "8 in the depth the view sees",
         .kind = K::Integer,
         .min = 1,
         .max = 4,
         .zeroAllowed = true,
         .zeroName = "auto",
         NUMBER(shadow.cascades, int)});
    add({.name = "cascade-lambda",
         .group = G::Cascades,
         .doc = "cascade splits: 0 uniform .. 1 logarithmic",
         .kind = K::Real,
         .max = 1,
         NUMBER(shadow.cascadeLambda, float),
         .matters = severalCascades,
         .onlyWith = kSeveralCascades});
    add({.name = "cascade-blend",
         .group = G::Cascades,
         .doc = "fraction of each cascade handed to the next pixel by pixel (dithered)",
         .kind = K::Real,
         .max = 0.5,
         NUMBER(shadow.cascadeBlend, float),
         .matters = severalCascades,
         .onlyWith = kSeveralCascades});
}

#undef NUMBER
#undef ENUM

}  // namespace gnomon::schema
