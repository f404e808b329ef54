#include "render/MainVariant.h"

#include "render/EdgeMaps.h"

#include "render/MainPassVariants.h"

namespace gnomon::render {

namespace {

// Filters whose kernel width is pcfSize.
bool kernelFilter(const ShadowOptions& s) {
    return s.filter == ShadowFilter::Pcf || s.filter == ShadowFilter::Poisson;
}

// The lookup's filter, kernel width, stored-depth encoding and how it compares.
void addLookupDefines(const MainVariant& v, std::vector<std::string>& d) {
    switch (ShadowFilter(v.filter)) {
        case ShadowFilter::Pcf:
            d.push_back("FILTER_PCF");
            break;
        case ShadowFilter::Poisson:
            d.push_back("FILTER_POISSON");
            break;
        case ShadowFilter::Hw2x2:
            d.push_back("FILTER_HW2X2");
            break;
        case ShadowFilter::None:
            d.push_back("FILTER_NONE");
            break;
        case ShadowFilter::Pcss:
            d.push_back("FILTER_PCSS");
            break;
        case ShadowFilter::Evsm2:
            d.insert(d.end(), {"FILTER_MOMENTS", "MOMENTS_EVSM2"});
            break;
        case ShadowFilter::Evsm4:
            d.insert(d.end(), {"FILTER_MOMENTS", "MOMENTS_EVSM4"});
            break;
        case ShadowFilter::Msm:
            d.insert(d.end(), {"FILTER_MOMENTS", "MOMENTS_MSM"});
            break;
    }
    if (v.pcfSize > 0) d.push_back("PCF_SIZE " + std::to_string(v.pcfSize));
    if (v.packing > 0)
        d.push_back(v.packing == 1 ? "PACK_R8" : v.packing == 2 ? "PACK_256" : "PACK_255");
    if (v.handCompare) d.push_back("HAND_COMPARE");
    if (v.mapNearest) d.push_back("MAP_NEAREST");
}

// `name`(BODY, first, LOOKUP, KIND) as BODY(first + i, LOOKUP, KIND) for i below `count`.
std::string unrolledLoop(const char* name, int count) {
    std::string d = std::string(name) + "(BODY, first, LOOKUP, KIND)";
    for (int i = 0; i < count; ++i)
        d += " BODY((first) + " + std::to_string(i) + ", LOOKUP, KIND)";
    return d;
}

// Every define but MAX_LIGHTS and the unrolled loops, in the order programs are labelled.
std::vector<std::string> choiceDefines(const MainVariant& v) {
    std::vector<std::string> d;
    if (v.visibilityPass) d.push_back("VISIBILITY_PASS");
    if (v.material) d.push_back("MATERIAL_PATH");
    if (v.floor) d.push_back("FLOOR");
    if (v.shadowsOff) d.push_back("SHADOWS_OFF");
    if (v.outsideClamp) d.push_back("OUTSIDE_CLAMP");
    addLookupDefines(v, d);
    // An object that casts no shadow is in no map, so nothing there can be itself: its
    // lookups need no tolerance against self-shadowing (the receiver plane, the normal offset,
    // a single map's rounding bound; a cube keeps its own), only the comparison...
    if (v.receiverOnly) d.push_back("RECEIVER_ONLY");
    // ...but its PCF still reads 2x2 texels per gather where the frame binds the raw depths
    // for the receiver plane (the comparison sampler's 9 bilinear taps cost more).
    if (v.receiverOnly && v.receiverPlane) d.push_back("FLAT_GATHERS");
    if (v.receiverPlane && !v.receiverOnly) d.push_back("RECEIVER_PLANE");
    if (v.normalOffset && !v.receiverOnly) d.push_back("NORMAL_OFFSET");
    if (v.standInLift) d.push_back("STAND_IN_LIFT");
    if (v.debugCascades) d.push_back("DEBUG_CASCADES");
    if (v.contactShadows) d.push_back("CONTACT_SHADOWS");
    if (v.coloured) d.push_back("COLOURED_SHADOWS");
    if (v.dither) d.push_back(v.dither == 2 ? "DITHER_SRGB" : "DITHER_LINEAR");
    if (v.hasCubes) d.push_back("HAS_CUBES");
    if (v.hasCascades) d.push_back("HAS_CASCADES");
    if (v.pointFaces) d.push_back("POINT_FACES");
    if (v.constantFalloff) d.push_back("CONSTANT_FALLOFF");
    if (v.noSpecular) d.push_back("NO_SPECULAR");
    if (v.singleMapKind > 0) d.push_back("SINGLE_MAP_KIND " + std::to_string(v.singleMapKind - 1));
    if (v.shadowedFactor) d.push_back("SHADOWED_FACTOR");
    if (v.shadowRays) d.push_back("SHADOW_RAYS");
    if (v.shadowRays == MainVariant::Bits(ShadowRayMode::Uncertain) ||
        v.shadowRays == MainVariant::kRaysMarked)
        d.push_back("SHADOW_RAYS_UNCERTAIN");
    if (v.casterOutlines) d.push_back("EDGE_MAPS");
    if (v.shadowRays == MainVariant::kRaysMarked) d.push_back("SHADOW_RAYS_MARK");
    if (v.raysResolve) d.push_back("SHADOW_RAYS_RESOLVE");
    if (v.rayOverflow) d.push_back("RAY_JOB_OVERFLOW");
    if (v.rayCutouts) d.push_back("BVH_CUTOUTS");
    if (v.debugRays) d.push_back("DEBUG_RAYS");
    if (v.lightLists) d.push_back("LIGHT_LISTS");
    return d;
}

}  // namespace

std::vector<std::string> MainVariant::defines(int maxLights, int orderSlots) const {
    std::vector<std::string> d = {"MAX_LIGHTS " + std::to_string(maxLights),
                                  "ORDER_SLOTS " + std::to_string(orderSlots)};
    for (std::string& c : choiceDefines(*this))
        d.push_back(std::move(c));
    if (unrolled) {
        d.push_back("UNROLLED_LIGHTS");
        d.push_back(unrolledLoop("UNSHADOWED_LIGHTS", int(unshadowedCount)));
        d.push_back(unrolledLoop("MAP_LIGHTS", int(mapCount)));
        d.push_back(unrolledLoop("CUBE_LIGHTS", int(cubeCount)));
        d.push_back(unrolledLoop("CASCADED_LIGHTS", int(cascadedCount)));
    }
    return d;
}

std::string MainVariant::label() const {
    std::string name;
    for (const std::string& d : choiceDefines(*this))
        name += d + ";";
    if (unrolled) {
        name += "UNROLLED_LIGHTS " + std::to_string(unshadowedCount) + "," +
                std::to_string(mapCount) + "," + std::to_string(cubeCount) + "," +
                std::to_string(cascadedCount) + ";";
    }
    return name;
}

MainVariant variantOf(const RenderOptions& options, bool floor, bool receiverOnly) {
    const ShadowOptions& s = options.shadow;
    MainVariant v;
    v.shadowsOff = !s.enabled;
    v.outsideClamp = s.outside == OutsidePolicy::Clamp;
    v.filter = MainVariant::Bits(s.filter);
    v.pcfSize = kernelFilter(s) ? MainVariant::Bits(s.pcfSize) : 0;
    // Native depth formats all compare the same way; colour formats differ in their packing.
    v.packing = s.depthFormat == DepthFormat::R8               ? 1
                : s.depthFormat == DepthFormat::Rgba8Packed256 ? 2
                : s.depthFormat == DepthFormat::Rgba8Packed255 ? 3
                                                               : 0;
    v.handCompare = handCompare(s);
    // Hand-compared reads of one NEAREST texel: compared at the texel's own centre on the
    // receiver's plane (shadow_lookup.glsl, MAP_NEAREST).
    v.mapNearest = handCompare(s) && s.mapFilter == MapFilter::Nearest;
    v.receiverOnly = receiverOnly;
    v.receiverPlane = s.receiverPlane;
    // Without self-shadowing there is no normal offset to apply (see RECEIVER_ONLY).
    v.normalOffset = s.normalOffset > 0.0f && !receiverOnly;
    // Stand-in casters are in the maps: lookups start off the surface by their error
    // (shadow_lookup.glsl). Without lookups there is nothing to lift.
    v.standInLift = s.enabled && s.casterDetail < 1.0f;
    v.debugCascades = options.debugView == DebugView::Cascades;
    // The floor keeps only what shadows need: no dithering.
    if (options.shading.dither && !floor)
        v.dither = options.shading.output == OutputEncoding::Srgb ? 2 : 1;
    v.shadowedFactor = options.shading.shadowedRule == ShadowedRule::Factor;
    v.shadowRays = tracesShadowRays(s) ? MainVariant::Bits(s.shadowRays) : 0;
    v.casterOutlines = v.shadowRays != 0 && EdgeMaps::wanted(s);
    v.debugRays = options.debugView == DebugView::Rays;
    v.floor = floor;
    return v;
}

}  // namespace gnomon::render
