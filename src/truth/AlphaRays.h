// What masked and blended surfaces let through, for the reference's rays: their alpha and
// colour at a hit, and the rule every tracer (truth/Tracer.h) applies to such a hit. View rays
// look through cut-away and blended surfaces; shadow rays through cut-away ones, and through
// blended ones by the --blend-shadows rule: dithered ones pass 1 - alpha of the light,
// coloured ones tint it by T = (1 - alpha) mix(1, colour, alpha).
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "gnomon/Options.h"
#include "gnomon/Scene.h"

namespace gnomon::truth {

// A masked or blended object's hits need its material, mesh and base colour texture.
struct AlphaSurface {
    const Mesh* mesh = nullptr;
    const Material* material = nullptr;
    const Texture* texture = nullptr;  // null: the material's factors alone
};

// The base colour (linear RGB: factor x texture decoded from sRGB x vertex colour) and alpha
// at barycentric (u, v) of triangle `prim`, bilinear on the full-size image (the renderer's
// mip levels can differ where the texture is minified).
glm::vec4 colourAt(const AlphaSurface& a, unsigned prim, float u, float v);
float alphaAt(const AlphaSurface& a, unsigned prim, float u, float v);

// What one blended surface of colour `c` and opacity `alpha` passes under
// --blend-shadows coloured: the share 1 - alpha, filtered by its colour as strongly as it is
// opaque (white passes 1 - alpha, as dithered does; alpha 0 passes all, alpha 1 nothing).
glm::vec3 tintThrough(const glm::vec3& c, float alpha);

// What a ray carries past masked and blended hits (one per ray).
struct AlphaState {
    bool viewRay = false;
    BlendShadows blend = BlendShadows::Dithered;
    float transmission = 1.0f;  // dithered: the product of 1 - alpha
    glm::vec3 tint{1.0f};       // coloured: the product of tintThrough
    // Hits already counted (a tracer can report a primitive again); a short ring suffices.
    std::uint64_t seen[8] = {};
    int seenCount = 0;
};

// A hit at barycentric (u, v) of triangle `prim` of `surface` (object `object`): true when it
// stops the ray, false when the ray goes on through it (a cut-away texel, or a blended
// surface, whose share of the light is then taken into `state`).
bool alphaStops(const AlphaSurface& surface, unsigned object, unsigned prim, float u, float v,
                AlphaState& state);

}  // namespace gnomon::truth
