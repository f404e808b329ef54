// The main pass's program variants as one table (after Filament's Variant.h): every choice
// that selects a program is a named bit-field of MainVariant, whose 64 bits are the program
// cache's key, and defines() spells the same fields out as main.frag.glsl's #defines. A key
// and its defines come from the same fields, so they cannot disagree; tests/gl checks that
// distinct variants give distinct defines.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "gnomon/Options.h"

namespace gnomon::render {

struct MainVariant {
    using Bits = std::uint64_t;
    // shadowRays of an uncertain draw that marks where a ray must decide and traces none
    // (SHADOW_RAYS_MARK, render/RayMarks.h).
    static constexpr Bits kRaysMarked = 3;
    static_assert(int(ShadowRayMode::Uncertain) < 3, "kRaysMarked follows the modes");
    Bits visibilityPass : 1 = 0;   // stores each light's visibility (gnomon score)
    Bits shadowsOff : 1 = 0;       // --shadows off: no lookups at all
    Bits outsideClamp : 1 = 0;     // --outside clamp
    Bits filter : 4 = 0;           // ShadowFilter
    Bits pcfSize : 8 = 0;          // kernel width of pcf and poisson; 0 for other filters
    Bits packing : 2 = 0;          // colour formats' packing: 1 R8, 2 base 256, 3 base 255
    Bits handCompare : 1 = 0;      // stored depth fetched and compared in the shader
    Bits mapNearest : 1 = 0;       // ...at one NEAREST texel's centre
    Bits receiverOnly : 1 = 0;     // the object casts no shadow: no self-shadow tolerances
    Bits receiverPlane : 1 = 0;    // --receiver-plane on
    Bits normalOffset : 1 = 0;     // --normal-offset > 0
    Bits standInLift : 1 = 0;      // stand-in casters are in the maps
    Bits debugCascades : 1 = 0;    // --debug-view cascades
    Bits contactShadows : 1 = 0;   // the view's depth is bound for contact shadows
    Bits coloured : 1 = 0;         // coloured shadows' transmittance maps are bound
    Bits dither : 2 = 0;           // 0 none, 1 in linear values, 2 in their sRGB encoding
    Bits hasCubes : 1 = 0;         // some light has a cube map
    Bits hasCascades : 1 = 0;      // some light is cascaded
    Bits pointFaces : 1 = 0;       // point lights' faces are maps of their own
    Bits constantFalloff : 1 = 0;  // no light falls off with distance
    Bits noSpecular : 1 = 0;       // the object has no highlight
    Bits singleMapKind : 3 = 0;    // the kind every single-map light shares, + 1; 0: mixed
    Bits shadowedFactor : 1 = 0;   // --shadowed-rule factor
    Bits material : 1 = 0;         // textured materials' path
    Bits floor : 1 = 0;            // gnomon's ground under a model
    Bits unrolled : 1 = 0;         // the light loops are unrolled to the counts below
    Bits unshadowedCount : 4 = 0;
    Bits mapCount : 4 = 0;
    Bits cubeCount : 4 = 0;
    Bits cascadedCount : 4 = 0;
    // ShadowRayMode when rays are traced (tracesShadowRays), else 0; or kRaysMarked.
    Bits shadowRays : 2 = 0;
    Bits debugRays : 1 = 0;   // --debug-view rays
    Bits lightLists : 1 = 0;  // each pixel reads its tile's lights (TiledLights' lists)
    // An uncertain draw of the marked pixels that reads their rays' answers
    // (SHADOW_RAYS_RESOLVE, render/RayMarks.h), and traces its own rays for lights beyond a
    // job's two (RAY_JOB_OVERFLOW: the draw may have more than two shadowed lights).
    Bits raysResolve : 1 = 0;
    Bits rayOverflow : 1 = 0;
    Bits rayCutouts : 1 = 0;      // some caster a ray meets is masked or blended (BVH_CUTOUTS)
    Bits casterOutlines : 1 = 0;  // uncertain reads the maps' outlines (EDGE_MAPS)

    // The bits as one number (memcpy: libc++ 14, the web build's, has no std::bit_cast).
    std::uint64_t key() const {
        std::uint64_t k = 0;
        std::memcpy(&k, this, sizeof k);
        return k;
    }
    // main.frag.glsl's #defines for this variant, after MAX_LIGHTS.
    std::vector<std::string> defines(int maxLights, int orderSlots = 1024) const;
    // The defines without the unrolled loops' bodies, as a program's label.
    std::string label() const;
};
// The fields fill the 64 bits exactly: a padding bit would leave a bit of the key undefined.
static_assert(sizeof(MainVariant) == sizeof(std::uint64_t) &&
                  std::has_unique_object_representations_v<MainVariant>,
              "MainVariant's fields must fill exactly 64 bits");

// The fields that come from the options alone (the lookups' filter, format and tolerances,
// dithering, debug view, shading rule); the caller sets what the frame and the item decide.
MainVariant variantOf(const RenderOptions& options, bool floor, bool receiverOnly);

}  // namespace gnomon::render
