// Scores rendered shadow visibility against the ray-traced reference (no GL): misclassified
// pixels split into false shadow (acne: reference lit, rendered shadowed) and light leak
// (peter-panning, missed casters: reference shadowed, rendered lit), each also counted only
// outside the aliasing band around the reference's shadow boundaries, plus the mean absolute
// visibility error. The error map colours what went wrong where.
#pragma once

#include <vector>

#include "gnomon/Image.h"
#include "gnomon/Score.h"
#include "truth/Reference.h"

namespace gnomon::truth {

// The most a map texel is taken to stretch along a surface tilted to the light (1 / cos of
// the tilt, here up to 75.5 degrees): beyond it, "away from the edge" would mean nothing.
constexpr float kBandMaxStretch = 4.0f;

// Per pixel x light ([pixel * lights + light], rows top first): 1 inside the aliasing band,
// within `bandTexels` map texels of a reference shadow boundary of that light (never less
// than a pixel). `texelWorld` holds the world size of the map texel each lookup used; on a
// surface tilted by theta to the light a texel covers texel / cos(theta) of it, counted up
// to kBandMaxStretch times (see Metrics.cpp).
std::vector<std::uint8_t> aliasingBand(const Reference& reference,
                                       const std::vector<float>& texelWorld, float bandTexels,
                                       bool soft);

// The band as its definition reads, along the surface: aliasingBand measures distances on
// screen, so it misses a boundary the camera does not see (under the caster that makes it,
// behind a fold, past a silhouette). Each cell the render got wrong outside `band` is probed
// with more shadow rays on its surface around it, as far as the band reaches there
// (ShadowRays::otherSideWithin), and put in the band where the reference's shadow changes
// within that reach. Hard shadows only (`reference.rays` set: traceReference's; `visibility`
// and `texelWorld` as for scoreVisibility and aliasingBand).
void extendBandAlongSurfaces(const Scene& scene, const Reference& reference,
                             const std::vector<float>& visibility,
                             const std::vector<float>& texelWorld, float bandTexels,
                             std::vector<std::uint8_t>& band);

// `reference` where the render drew the same surface: a copy in which no light applies at
// the pixels whose `object` (per pixel, the scene object the render drew, -1 none) is not
// the one the reference sees; `excluded` counts the pixels where a light applied. An empty
// `object` (no record) keeps every pixel.
Reference onSameSurfaces(const Reference& reference, const std::vector<int>& object,
                         long& excluded);

// Whether the reference shadows `cell` (pixel x light): its hard answer, or with `soft` its
// soft visibility under one half.
bool occludedRef(const Reference& reference, std::size_t cell, bool soft);

// `visibility` holds the renderer's visibility per pixel x light (0 shadowed .. 1 lit). Hard
// metrics threshold it at 0.5; with `soft`, the reference is the soft one (thresholded at
// 0.5 for the hard metrics).
struct Scores {
    std::vector<ShadowScore> lights;  // lights with scored pixels, in scene order
    ShadowScore overall;
};
Scores scoreVisibility(const Scene& scene, const Reference& reference,
                       const std::vector<float>& visibility, const std::vector<std::uint8_t>& band,
                       bool soft);

// --blend-shadows coloured: the rendered light (visibility x `tint`, three floats per cell)
// against the reference's (hard, or with `soft` soft, x tint) where either is tinted.
TintScore scoreTint(const Reference& reference, const std::vector<float>& visibility,
                    const std::vector<float>& tint, const std::vector<std::uint8_t>& band,
                    bool soft);
// Per pixel, the worst light's transmitted-light error where tinted: dark green right,
// yellow at 4/255, red from 16/255; elsewhere the render in dim grey.
Image tintErrorMap(const Reference& reference, const std::vector<float>& visibility,
                   const std::vector<float>& tint, bool soft, const Image& render);

// Per pixel: false shadow red, light leak blue (pale inside the aliasing band), elsewhere
// the render in dim grey.
Image errorMap(const Reference& reference, const std::vector<float>& visibility,
               const std::vector<std::uint8_t>& band, bool soft, const Image& render);

// Squared Euclidean distance (in pixels) from every pixel to the nearest `seed` pixel
// (Felzenszwalb and Huttenlocher 2012); huge where there is no seed.
std::vector<float> squaredDistance(const std::vector<std::uint8_t>& seeds, int width, int height);

}  // namespace gnomon::truth
