// MainPass's program variants: the choices that select one, packed in a key, and the
// #defines they inject into main.frag.glsl (built once per key and cached).
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "gl/Program.h"
#include "render/MainPass.h"
#include "render/MainPassVariants.h"

namespace gnomon::render {

namespace {
// 0: no dithering (asked for, or the floor, which keeps only what shadows need); 1: in the
// stored values; 2: in their sRGB encoding.
int ditherMode(const RenderOptions& options, bool floor) {
    if (!options.shading.dither || floor) return 0;
    return options.shading.output == OutputEncoding::Srgb ? 2 : 1;
}
// Hand-compared reads of one NEAREST texel: compared at the texel's own centre on the receiver's
// plane (shadow_lookup.glsl, MAP_NEAREST).
bool nearestHandCompare(const ShadowOptions& s) {
    return handCompare(s) && s.mapFilter == MapFilter::Nearest;
}
// Filters whose kernel width is pcfSize.
bool kernelFilter(const ShadowOptions& s) {
    return s.filter == ShadowFilter::Pcf || s.filter == ShadowFilter::Poisson;
}
// Stand-in casters are in the maps: lookups start off the surface by their error
// (shadow_lookup.glsl). Without lookups there is nothing to lift.
bool standInLift(const ShadowOptions& s) {
    return s.enabled && s.casterDetail < 1.0f;
}

// The lookup's filter, kernel width, stored-depth encoding and how it compares.
void addLookupDefines(const ShadowOptions& s, std::vector<std::string>& defines) {
    switch (s.filter) {
        case ShadowFilter::Pcf:
            defines.push_back("FILTER_PCF");
            break;
        case ShadowFilter::Poisson:
            defines.push_back("FILTER_POISSON");
            break;
        case ShadowFilter::Hw2x2:
            defines.push_back("FILTER_HW2X2");
            break;
        case ShadowFilter::None:
            defines.push_back("FILTER_NONE");
            break;
        case ShadowFilter::Pcss:
            defines.push_back("FILTER_PCSS");
            break;
        case ShadowFilter::Evsm2:
            defines.push_back("FILTER_MOMENTS");
            defines.push_back("MOMENTS_EVSM2");
            break;
        case ShadowFilter::Evsm4:
            defines.push_back("FILTER_MOMENTS");
            defines.push_back("MOMENTS_EVSM4");
            break;
        case ShadowFilter::Msm:
            defines.push_back("FILTER_MOMENTS");
            defines.push_back("MOMENTS_MSM");
            break;
    }
    if (kernelFilter(s)) {
        defines.push_back("PCF_SIZE " + std::to_string(s.pcfSize));
    }
    switch (s.depthFormat) {
        case DepthFormat::R8:
            defines.push_back("PACK_R8");
            break;
        case DepthFormat::Rgba8Packed256:
            defines.push_back("PACK_256");
            break;
        case DepthFormat::Rgba8Packed255:
            defines.push_back("PACK_255");
            break;
        default:
            break;
    }
    if (handCompare(s)) defines.push_back("HAND_COMPARE");
    if (nearestHandCompare(s)) defines.push_back("MAP_NEAREST");
}

// `name`(BODY, first, LOOKUP, KIND) as BODY(first + i, LOOKUP, KIND) for i below `count`.
std::string unrolledLoop(const char* name, int count) {
    std::string d = std::string(name) + "(BODY, first, LOOKUP, KIND)";
    for (int i = 0; i < count; ++i)
        d += " BODY((first) + " + std::to_string(i) + ", LOOKUP, KIND)";
    return d;
}
}  // namespace

const gl::Program& MainPass::program(const RenderOptions& options, const MainPassInputs& in,
                                     glm::ivec4 counts, bool visibilityPass, bool material,
                                     bool floor, ItemVariant item) {
    const bool receiverOnly = item.receiverOnly;
    // Every choice that selects a variant, packed in one number: looking a program up costs
    // no allocation; the defines are spelled out only to build a new one.
    const ShadowOptions& so = options.shadow;
    const std::uint64_t key =
        std::uint64_t(visibilityPass) | std::uint64_t(so.enabled) << 1 |
        std::uint64_t(so.outside) << 2 | std::uint64_t(so.filter) << 4 |
        std::uint64_t(kernelFilter(so) ? so.pcfSize : 0) << 8 |
        std::uint64_t(so.depthFormat) << 16 |
        std::uint64_t(options.debugView == DebugView::Cascades) << 20 |
        std::uint64_t(in.shadowCubes != nullptr) << 21 | std::uint64_t(in.hasCascades) << 22 |
        std::uint64_t(options.shading.shadowedRule) << 23 | std::uint64_t(material) << 24 |
        std::uint64_t(so.receiverPlane) << 25 | std::uint64_t(floor) << 26 |
        std::uint64_t(ditherMode(options, floor)) << 27 |
        std::uint64_t(in.viewDepth != nullptr) << 29 | std::uint64_t(so.normalOffset > 0.0f) << 30 |
        std::uint64_t(in.transmittance != nullptr) << 31 |
        std::uint64_t(nearestHandCompare(so)) << 32 |
        std::uint64_t(in.singleMapKind + 1) << 33 |  // 0..4: 3 bits
        std::uint64_t(standInLift(so)) << 36 | std::uint64_t(counts.x >= 0) << 37 |
        std::uint64_t(std::max(counts.x, 0)) << 38 | std::uint64_t(std::max(counts.y, 0)) << 42 |
        std::uint64_t(std::max(counts.z, 0)) << 46 | std::uint64_t(std::max(counts.w, 0)) << 50 |
        std::uint64_t(in.pointFaces) << 54 | std::uint64_t(in.constantFalloff) << 55 |
        std::uint64_t(item.noSpecular) << 56 | std::uint64_t(receiverOnly) << 57;
    static_assert(kMaxUnrolledLights < 16, "a count must fit the key's four bits");
    if (auto it = mPrograms.find(key); it != mPrograms.end()) return it->second;

    std::vector<std::string> defines = {"MAX_LIGHTS " + std::to_string(mMaxLights)};
    if (visibilityPass) defines.push_back("VISIBILITY_PASS");
    if (material) defines.push_back("MATERIAL_PATH");
    if (floor) defines.push_back("FLOOR");
    const ShadowOptions& s = so;
    if (!s.enabled) defines.push_back("SHADOWS_OFF");
    if (s.outside == OutsidePolicy::Clamp) defines.push_back("OUTSIDE_CLAMP");
    addLookupDefines(s, defines);
    // An object that casts no shadow is in no map, so nothing there can be itself: its
    // lookups need no tolerance against self-shadowing (the receiver plane, the normal offset,
    // a single map's rounding bound; a cube keeps its own), only the comparison.
    if (receiverOnly) defines.push_back("RECEIVER_ONLY");
    // ...but its PCF still reads 2x2 texels per gather where the frame binds the raw depths
    // for the receiver plane (the comparison sampler's 9 bilinear taps cost more).
    if (receiverOnly && s.receiverPlane) defines.push_back("FLAT_GATHERS");
    if (s.receiverPlane && !receiverOnly) defines.push_back("RECEIVER_PLANE");
    if (s.normalOffset > 0.0f && !receiverOnly) defines.push_back("NORMAL_OFFSET");
    if (standInLift(s)) defines.push_back("STAND_IN_LIFT");
    if (options.debugView == DebugView::Cascades) defines.push_back("DEBUG_CASCADES");
    if (in.viewDepth) defines.push_back("CONTACT_SHADOWS");
    if (in.transmittance) defines.push_back("COLOURED_SHADOWS");
    if (const int dither = ditherMode(options, floor)) {
        defines.push_back(dither == 2 ? "DITHER_SRGB" : "DITHER_LINEAR");
    }
    if (in.shadowCubes) defines.push_back("HAS_CUBES");
    if (in.hasCascades) defines.push_back("HAS_CASCADES");
    if (in.pointFaces) defines.push_back("POINT_FACES");
    if (in.constantFalloff) defines.push_back("CONSTANT_FALLOFF");
    if (item.noSpecular) defines.push_back("NO_SPECULAR");
    if (in.singleMapKind >= 0) {
        defines.push_back("SINGLE_MAP_KIND " + std::to_string(in.singleMapKind));
    }
    if (options.shading.shadowedRule == ShadowedRule::Factor) {
        defines.push_back("SHADOWED_FACTOR");
    }
    std::string name;
    for (const auto& d : defines)
        name += d + ";";
    if (counts.x >= 0) {
        defines.push_back("UNROLLED_LIGHTS");
        defines.push_back(unrolledLoop("UNSHADOWED_LIGHTS", counts.x));
        defines.push_back(unrolledLoop("MAP_LIGHTS", counts.y));
        defines.push_back(unrolledLoop("CUBE_LIGHTS", counts.z));
        defines.push_back(unrolledLoop("CASCADED_LIGHTS", counts.w));
        name += "UNROLLED_LIGHTS " + std::to_string(counts.x) + "," + std::to_string(counts.y) +
                "," + std::to_string(counts.z) + "," + std::to_string(counts.w) + ";";
    }
    return mPrograms
        .emplace(key, gl::buildProgram("main [" + name + "]",
                                       {{GL_VERTEX_SHADER, "main.vert.glsl"},
                                        {GL_FRAGMENT_SHADER, "main.frag.glsl"}},
                                       defines))
        .first->second;
}

}  // namespace gnomon::render
