// MainPass's programs: the frame's and the item's choices as a MainVariant (its key and its
// #defines for main.frag.glsl, render/MainVariant.h), each built once and cached.
#include <cstdint>
#include <string>
#include <vector>

#include "gl/Program.h"
#include "render/MainPass.h"
#include "render/MainVariant.h"
#include "render/RayScene.h"

namespace gnomon::render {

const gl::Program& MainPass::program(const RenderOptions& options, const MainPassInputs& in,
                                     glm::ivec4 counts, bool visibilityPass, bool material,
                                     bool floor, ItemVariant item, bool lists) {
    // Looking a program up packs the variant's fields (no allocation); the defines are
    // spelled out only to build a new one.
    MainVariant v = variantOf(options, floor, item.receiverOnly);
    v.visibilityPass = visibilityPass;
    v.material = material;
    v.contactShadows = in.viewDepth != nullptr;
    v.coloured = in.transmittance != nullptr;
    v.hasCubes = in.hasCubes;
    v.hasCascades = in.hasCascades;
    v.pointFaces = in.pointFaces;
    v.constantFalloff = in.constantFalloff;
    if (!in.rays) v.shadowRays = 0;  // no caster to trace (shadows off, an empty scene)
    v.rayCutouts = v.shadowRays != 0 && in.rays->masks().any();
    if (v.shadowRays == MainVariant::Bits(ShadowRayMode::Uncertain)) {
        if (item.rays == RayDraw::Mark) v.shadowRays = MainVariant::kRaysMarked;
        // A job holds two lights; a draw with more shadowed ones (or loops over an unknown
        // count) traces the rest itself.
        v.raysResolve = item.rays == RayDraw::Resolve;
        v.rayOverflow = v.raysResolve && (counts.x < 0 || counts.y + counts.z + counts.w > 2);
    }
    v.singleMapKind = MainVariant::Bits(in.singleMapKind + 1);
    v.noSpecular = item.noSpecular;
    v.lightLists = lists;
    static_assert(kMaxUnrolledLights < 16, "a count must fit its four bits");
    if (counts.x >= 0) {
        v.unrolled = 1;
        v.unshadowedCount = MainVariant::Bits(counts.x);
        v.mapCount = MainVariant::Bits(counts.y);
        v.cubeCount = MainVariant::Bits(counts.z);
        v.cascadedCount = MainVariant::Bits(counts.w);
    }
    const std::uint64_t key = v.key();
    if (auto it = mPrograms.find(key); it != mPrograms.end()) return it->second;
    return mPrograms
        .emplace(key, gl::buildProgram("main [" + v.label() + "]",
                                       {{GL_VERTEX_SHADER, "main.vert.glsl"},
                                        {GL_FRAGMENT_SHADER, "main.frag.glsl"}},
                                       v.defines(mMaxLights, mOrderCapacity / 4)))
        .first->second;
}

}  // namespace gnomon::render
