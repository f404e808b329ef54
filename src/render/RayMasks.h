// The cut-outs of masked and blended casters for shadow rays (shaders/bvh_trace.glsl): which
// casters a ray sees and how, and, for those whose texture decides, each triangle's texture
// coordinates and its texture's alpha, in textures the main pass reads with texelFetch.
//
// A ray meets a caster as the shadow maps draw it (shadow::castsDepth, alpha_test_vertex.glsl)
// and as the reference traces it (truth/AlphaRays.h): a masked texel blocks where its alpha
// reaches the material's cutoff; a blended one blocks whole under --blend-shadows opaque, where
// it is opaque (alpha 254.5/255 and up) under coloured (the transmittance maps tint the light
// through the rest), where its alpha reaches one half under dithered (a single layer then lets
// through under half the light), and never under none.
//
// Layout. uvs: three RGBA32F texels a triangle in the hierarchy's leaf order, (u0, v0, u1, v1),
// (u2, v2, threshold, modes), (first / 4096, first mod 4096, width, height) with the texture
// coordinates after the material's uvTransform; the texel blocks where its alpha is at least
// `threshold`; modes = wrapS + 3 wrapT + 9 nearest; `first` the index of the texture's first
// alpha in `alphas`, in two parts that floats hold exactly (bvh_trace.glsl joins them). alphas:
// every such texture's alpha, rows top-down, one byte each, four to an RGBA8 texel (byte k in texel
// k / 4, channel k mod 4), texel t at (t mod width, t / width).
#pragma once

#include <vector>

#include "bvh/Bvh.h"
#include "gl/Objects.h"
#include "gnomon/Options.h"
#include "gnomon/Scene.h"

namespace gnomon::render {

// How shadow rays treat one object's triangles.
struct RayCaster {
    bool casts = false;      // in the hierarchy at all
    bool filtered = false;   // its texture's alpha decides, texel by texel
    float threshold = 0.0f;  // filtered: the texture alpha from which a texel blocks
    int texture = -1;        // filtered: Scene::textures index
};
RayCaster rayCaster(const Scene& scene, const Object& object, const ShadowOptions& options);

class RayMasks {
public:
    // The tables for `triangles` (the hierarchy's, leaf order) whose objects are `casters`
    // (per scene object); 1-texel tables when no triangle is filtered.
    void build(const Scene& scene, const std::vector<RayCaster>& casters,
               const std::vector<bvh::BvhTriangle>& triangles, int rowTexels);
    const gl::Texture& uvs() const { return mUvs; }
    const gl::Texture& alphas() const { return mAlphas; }
    // Whether any triangle's texture decides: without, the shaders leave the test out
    // (BVH_CUTOUTS, bvh_trace.glsl).
    bool any() const { return mAny; }

private:
    gl::Texture mUvs, mAlphas;
    bool mAny = false;
};

}  // namespace gnomon::render
