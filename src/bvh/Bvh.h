// A bounding volume hierarchy over triangles, of the project's own: no Embree, no GL, so the
// reference can trace where Embree cannot go (wasm), and the renderer's shadow rays read the
// same arrays in a fragment shader (render/RayScene.h, shaders/bvh_trace.glsl). Built top-down with
// the surface area heuristic over binned centroids (Wald 2007, "On fast Construction of SAH-based
// Bounding Volume Hierarchies"); traversed with the watertight ray/triangle test of Woop, Benthin
// and Wald 2013 ("Watertight Ray/Triangle Intersection") and box tests widened as Ize 2013 ("Robust
// BVH Ray Traversal") shows, so that a ray through an edge or a vertex two triangles share meets at
// least one.
//
// Layout: two flat arrays whose elements are whole RGBA32F texels, to be uploaded as they are
// and read with texelFetch (texel k of an array at (k mod width, k / width)). Every field is a
// float; indices and flags are whole numbers stored as floats (exact below 2^24), so no bit
// pattern depends on how a driver treats NaNs or denormals, and a shader reads them with
// int(texel.w).
//   node i      texel 2i     (lo.x, lo.y, lo.z, first)
//               texel 2i+1   (hi.x, hi.y, hi.z, info)     info = 2 count + casters
//       count 0: an inner node; its children are nodes first and first + 1 (a pair).
//       count > 0: a leaf; its triangles are first .. first + count - 1.
//       casters: 1 when a triangle under the node casts shadows (shadow rays skip it if 0).
//       Node 0 is the root; an empty hierarchy has no node.
//   triangle j  texel 3j     (p0.xyz, object)
//               texel 3j+1   (p1.xyz, primitive)        the triangle's index in its object
//               texel 3j+2   (p2.xyz, flags)            kCaster + kFiltered
// Triangles are stored in leaf order with their own corners (no index buffer): a leaf's are
// contiguous, and corners shared in the input stay bit-identical, which watertightness needs.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace gnomon::bvh {

struct BvhNode {
    glm::vec3 lo{0.0f};
    float first = 0.0f;
    glm::vec3 hi{0.0f};
    float info = 0.0f;

    bool leaf() const { return info >= 2.0f; }
    std::uint32_t count() const { return std::uint32_t(info) >> 1; }
    bool casters() const { return (std::uint32_t(info) & 1u) != 0; }
};
static_assert(sizeof(BvhNode) == 2 * 4 * sizeof(float), "a node is two RGBA32F texels");

struct BvhTriangle {
    // Flags: shadow rays see only casters; a hit on a filtered triangle asks the filter
    // (masked and blended surfaces).
    static constexpr std::uint32_t kCaster = 1, kFiltered = 2;

    glm::vec3 p0{0.0f};
    float object = 0.0f;
    glm::vec3 p1{0.0f};
    float primitive = 0.0f;
    glm::vec3 p2{0.0f};
    float flags = 0.0f;

    std::uint32_t objectIndex() const { return std::uint32_t(object); }
    std::uint32_t primitiveIndex() const { return std::uint32_t(primitive); }
    bool has(std::uint32_t flag) const { return (std::uint32_t(flags) & flag) != 0; }
};
static_assert(sizeof(BvhTriangle) == 3 * 4 * sizeof(float), "a triangle is three texels");

// The most triangles a hierarchy holds: its nodes (fewer than twice as many) then stay
// below 2^24, where floats stop holding every whole number.
constexpr std::size_t kBvhMaxTriangles = std::size_t(1) << 23;
// A traversal's stack: deeper than medianDepth (at most 40) the build splits at the median,
// which halves the triangles, so no path from the root is longer than 40 + 23 nodes.
constexpr int kBvhMaxDepth = 64;

// The surface area heuristic's terms over `bins` bins per axis: a split's cost is
// traversalCost + triangleCost x (the children's triangles weighted by their share of the
// parent's area), a leaf's triangleCost x its triangles. Leaves hold up to maxLeaf
// triangles; above it a node is always split.
struct BvhBuildOptions {
    int bins = 16;
    float traversalCost = 1.0f;
    float triangleCost = 1.0f;
    int maxLeaf = 8;
    int medianDepth = 40;
};

struct BvhRay {
    glm::vec3 origin{0.0f};
    glm::vec3 dir{0.0f, 0.0f, 1.0f};
    float tnear = 0.0f;  // hits lie in tnear < t <= tfar, as Embree's do
    float tfar = 0.0f;
};

// A hit on triangles()[triangle] at origin + t dir; (u, v) weigh p1 and p2, (1 - u - v) p0.
struct BvhHit {
    static constexpr std::uint32_t kNone = 0xffffffffu;
    std::uint32_t triangle = kNone;
    float t = 0.0f, u = 0.0f, v = 0.0f;
    bool hit() const { return triangle != kNone; }
};

// Asked on every hit of a kFiltered triangle: true when the hit counts (stops a shadow ray, is
// a candidate nearest hit), false when the ray goes on through.
using BvhFilter = bool (*)(void* context, const BvhTriangle& triangle, const BvhHit& hit);

class Bvh {
public:
    Bvh() = default;
    // Reorders `triangles` into leaf order. At most kBvhMaxTriangles (std::length_error).
    explicit Bvh(std::vector<BvhTriangle> triangles, const BvhBuildOptions& options = {});

    // The nearest hit of any triangle (filtered ones when `filter` accepts them; every one
    // when `filter` is null).
    BvhHit nearest(const BvhRay& ray, BvhFilter filter, void* context) const;
    // True when a caster's hit stops the ray: any unfiltered caster's, or a filtered one's
    // that `filter` accepts. Every filtered caster's hit is shown to `filter` until then.
    bool occluded(const BvhRay& ray, BvhFilter filter, void* context) const;

    const std::vector<BvhNode>& nodes() const { return mNodes; }
    const std::vector<BvhTriangle>& triangles() const { return mTriangles; }

private:
    std::vector<BvhNode> mNodes;
    std::vector<BvhTriangle> mTriangles;
};

}  // namespace gnomon::bvh
