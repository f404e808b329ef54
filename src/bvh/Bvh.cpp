#include "bvh/Bvh.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <utility>

namespace gnomon::bvh {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

struct Box {
    glm::vec3 lo{kInf}, hi{-kInf};

    void extend(const glm::vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void extend(const Box& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    // Half the surface area (the heuristic only compares areas); 0 for an empty box.
    float halfArea() const {
        const glm::vec3 d = hi - lo;
        if (!(d.x >= 0.0f)) return 0.0f;
        return d.x * d.y + d.y * d.z + d.z * d.x;
    }
};

// Builds the hierarchy top-down over `order` (input triangle indices), each node's
// triangles a contiguous range of it, children allocated as adjacent pairs.
class Builder {
public:
    Builder(const std::vector<BvhTriangle>& triangles, const BvhBuildOptions& options)
        : mTriangles(triangles), mOptions(options) {
        mOptions.bins = std::clamp(mOptions.bins, 2, 256);
        mOptions.maxLeaf = std::clamp(mOptions.maxLeaf, 1, 1024);
        mOptions.medianDepth = std::clamp(mOptions.medianDepth, 0, 40);
        const std::size_t n = triangles.size();
        mBounds.resize(n);
        mCentroids.resize(n);
        mOrder.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const BvhTriangle& t = triangles[i];
            Box& b = mBounds[i];
            b.extend(t.p0);
            b.extend(t.p1);
            b.extend(t.p2);
            mCentroids[i] = 0.5f * (b.lo + b.hi);
            mOrder[i] = std::uint32_t(i);
        }
        mNodes.reserve(2 * n);
    }

    void build() {
        if (mTriangles.empty()) return;
        mNodes.emplace_back();
        split(0, 0, std::uint32_t(mTriangles.size()), 0);
    }
    std::vector<BvhNode> takeNodes() { return std::move(mNodes); }
    const std::vector<std::uint32_t>& order() const { return mOrder; }

private:
    struct Split {
        int axis = -1;
        int bin = 0;     // triangles in bins below it go left
        float cost = 0;  // traversal + triangle costs, times the parent's area
    };

    int binOf(const glm::vec3& centroid, int axis, const Box& centroids, float scale) const {
        const int b = int((centroid[axis] - centroids.lo[axis]) * scale);
        return std::clamp(b, 0, mOptions.bins - 1);
    }
    float scaleOf(const Box& centroids, int axis) const {
        const float extent = centroids.hi[axis] - centroids.lo[axis];
        return extent > 0.0f ? float(mOptions.bins) / extent : 0.0f;
    }

    // The cheapest split between bins over the three axes (axis -1 when no axis has extent).
    Split bestSplit(std::uint32_t begin, std::uint32_t end, const Box& centroids) {
        Split best;
        best.cost = kInf;
        const int bins = mOptions.bins;
        std::vector<Box>& box = mBinBoxes;
        std::vector<std::uint32_t>& count = mBinCounts;
        box.assign(std::size_t(bins) * 3, Box{});
        count.assign(std::size_t(bins) * 3, 0);
        float scale[3];
        for (int axis = 0; axis < 3; ++axis)
            scale[axis] = scaleOf(centroids, axis);
        for (std::uint32_t i = begin; i < end; ++i) {
            const std::uint32_t t = mOrder[i];
            for (int axis = 0; axis < 3; ++axis) {
                if (scale[axis] == 0.0f) continue;
                const std::size_t k =
                    std::size_t(axis * bins + binOf(mCentroids[t], axis, centroids, scale[axis]));
                box[k].extend(mBounds[t]);
                ++count[k];
            }
        }
        std::vector<float>& rightCost = mRightCosts;
        rightCost.assign(std::size_t(bins), 0.0f);
        for (int axis = 0; axis < 3; ++axis) {
            if (scale[axis] == 0.0f) continue;
            const std::size_t base = std::size_t(axis * bins);
            Box right;
            std::uint32_t rightCount = 0;
            for (int b = bins - 1; b > 0; --b) {  // right side of a split below bin b
                right.extend(box[base + std::size_t(b)]);
                rightCount += count[base + std::size_t(b)];
                rightCost[std::size_t(b)] = right.halfArea() * float(rightCount);
            }
            Box left;
            std::uint32_t leftCount = 0;
            for (int b = 1; b < bins; ++b) {
                left.extend(box[base + std::size_t(b - 1)]);
                leftCount += count[base + std::size_t(b - 1)];
                if (leftCount == 0 || leftCount == end - begin) continue;
                const float cost = left.halfArea() * float(leftCount) + rightCost[std::size_t(b)];
                if (cost < best.cost) best = {axis, b, cost};
            }
        }
        return best;
    }

    void makeLeaf(std::uint32_t node, std::uint32_t begin, std::uint32_t end) {
        bool casters = false;
        for (std::uint32_t i = begin; i < end; ++i)
            casters = casters || mTriangles[mOrder[i]].has(BvhTriangle::kCaster);
        mNodes[node].first = float(begin);
        mNodes[node].info = float(2 * (end - begin) + (casters ? 1 : 0));
    }

    // Splits at the median centroid along the axis where centroids spread most: always two
    // non-empty halves, so the depth below stays under log2 of the count.
    std::uint32_t medianSplit(std::uint32_t begin, std::uint32_t end, const Box& centroids) {
        const glm::vec3 extent = centroids.hi - centroids.lo;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                         : extent.y >= extent.z                       ? 1
                                                                      : 2;
        const std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(mOrder.begin() + begin, mOrder.begin() + mid, mOrder.begin() + end,
                         [&](std::uint32_t a, std::uint32_t b) {
                             return mCentroids[a][axis] < mCentroids[b][axis];
                         });
        return mid;
    }

    void split(std::uint32_t node, std::uint32_t begin, std::uint32_t end, int depth) {
        Box bounds, centroids;
        for (std::uint32_t i = begin; i < end; ++i) {
            bounds.extend(mBounds[mOrder[i]]);
            centroids.extend(mCentroids[mOrder[i]]);
        }
        mNodes[node].lo = bounds.lo;
        mNodes[node].hi = bounds.hi;
        const std::uint32_t n = end - begin;
        if (n == 1) return makeLeaf(node, begin, end);
        std::uint32_t mid = 0;
        if (depth >= mOptions.medianDepth) {
            if (n <= std::uint32_t(mOptions.maxLeaf)) return makeLeaf(node, begin, end);
            mid = medianSplit(begin, end, centroids);
        } else {
            const Split s = bestSplit(begin, end, centroids);
            // Both costs times the node's area, so a flat or empty box compares too.
            const float area = bounds.halfArea();
            const float leafCost = mOptions.triangleCost * float(n) * area;
            const float splitCost = mOptions.traversalCost * area + mOptions.triangleCost * s.cost;
            if (n <= std::uint32_t(mOptions.maxLeaf) && !(splitCost < leafCost)) {
                return makeLeaf(node, begin, end);
            }
            if (s.axis < 0) {
                mid = medianSplit(begin, end, centroids);
            } else {
                const float scale = scaleOf(centroids, s.axis);
                auto left = [&](std::uint32_t t) {
                    return binOf(mCentroids[t], s.axis, centroids, scale) < s.bin;
                };
                mid = std::uint32_t(
                    std::partition(mOrder.begin() + begin, mOrder.begin() + end, left) -
                    mOrder.begin());
                if (mid == begin || mid == end) mid = medianSplit(begin, end, centroids);
            }
        }
        const auto child = std::uint32_t(mNodes.size());
        mNodes.emplace_back();
        mNodes.emplace_back();
        split(child, begin, mid, depth + 1);
        split(child + 1, mid, end, depth + 1);
        const bool casters = mNodes[child].casters() || mNodes[child + 1].casters();
        mNodes[node].first = float(child);
        mNodes[node].info = casters ? 1.0f : 0.0f;
    }

    const std::vector<BvhTriangle>& mTriangles;
    BvhBuildOptions mOptions;
    std::vector<Box> mBounds;
    std::vector<glm::vec3> mCentroids;
    std::vector<std::uint32_t> mOrder;
    std::vector<BvhNode> mNodes;
    // bestSplit's bins, kept between nodes.
    std::vector<Box> mBinBoxes;
    std::vector<std::uint32_t> mBinCounts;
    std::vector<float> mRightCosts;
};

// 1 + 2 gamma(3) (gamma(n) = n u / (1 - n u), u = 2^-24): a box's exit distance times it
// covers the rounding of the slab test (Ize 2013), so no box is missed that holds a hit.
constexpr float kWiden = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);

// What a ray's box and triangle tests share, in plain arrays: glm's vectors pick a
// component by a run-time index through a switch, a branch per access in the inner loops.
struct RayFrame {
    float origin[3];
    float inv[3];  // 1 / dir, +inf for a zero component (never -inf: see hitBox)
    // Per axis, where a node's near and far bounds lie among its 8 floats (lo at 0..2, hi
    // at 4..6): lo first when the ray runs up that axis.
    int nearSlot[3], farSlot[3];
    // Woop et al. 2013: the axis the ray runs most along (kz) and the shear that turns the
    // ray into +z; kx, ky swapped when dir[kz] < 0 to keep the triangles' winding.
    int kx, ky, kz;
    float sx, sy, sz;

    explicit RayFrame(const BvhRay& ray) {
        const float d[3] = {ray.dir.x + 0.0f, ray.dir.y + 0.0f, ray.dir.z + 0.0f};  // -0 to +0
        const float o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
        for (int a = 0; a < 3; ++a) {
            origin[a] = o[a];
            inv[a] = 1.0f / d[a];
            nearSlot[a] = inv[a] < 0.0f ? 4 + a : a;
            farSlot[a] = inv[a] < 0.0f ? a : 4 + a;
        }
        const float mx = std::fabs(d[0]), my = std::fabs(d[1]), mz = std::fabs(d[2]);
        kz = mx >= my && mx >= mz ? 0 : my >= mz ? 1 : 2;
        kx = (kz + 1) % 3;
        ky = (kx + 1) % 3;
        if (d[kz] < 0.0f) std::swap(kx, ky);
        sx = d[kx] / d[kz];
        sy = d[ky] / d[kz];
        sz = 1.0f / d[kz];
    }
};

// The slab test. A ray parallel to a slab whose origin lies on its plane gives 0 x inf = NaN:
// the comparisons keep the running bound then, so the slab counts as not limiting the ray
// (which is right: it lies within it). Zero components are +0, so the NaN falls where it is
// dropped. `entry`: where the ray enters the box.
inline bool hitBox(const BvhNode& n, const RayFrame& r, float tnear, float tfar, float& entry) {
    float f[8];
    std::memcpy(f, &n, sizeof f);
    float t0 = tnear, t1 = tfar;
    for (int a = 0; a < 3; ++a) {
        const float tn = (f[r.nearSlot[a]] - r.origin[a]) * r.inv[a];
        const float tf = (f[r.farSlot[a]] - r.origin[a]) * r.inv[a] * kWiden;
        t0 = tn > t0 ? tn : t0;
        t1 = tf < t1 ? tf : t1;
    }
    entry = t0;
    return t0 <= t1;
}

// Woop, Benthin and Wald 2013: the corners relative to the origin, sheared so the ray runs
// along +z; the signed 2D areas U, V, W of the edges' triangles with the origin decide.
// Shared corners give the same numbers in both triangles (an edge's area is negated
// exactly), so a ray through a shared edge meets one or both; an area of exactly 0 is
// recomputed in double precision, where the products are exact and its sign right.
inline bool hitTriangle(const RayFrame& r, const BvhTriangle& tri, float tnear, float tfar,
                        BvhHit& hit) {
    const float a[3] = {tri.p0.x - r.origin[0], tri.p0.y - r.origin[1], tri.p0.z - r.origin[2]};
    const float b[3] = {tri.p1.x - r.origin[0], tri.p1.y - r.origin[1], tri.p1.z - r.origin[2]};
    const float c[3] = {tri.p2.x - r.origin[0], tri.p2.y - r.origin[1], tri.p2.z - r.origin[2]};
    const float ax = a[r.kx] - r.sx * a[r.kz], ay = a[r.ky] - r.sy * a[r.kz];
    const float bx = b[r.kx] - r.sx * b[r.kz], by = b[r.ky] - r.sy * b[r.kz];
    const float cx = c[r.kx] - r.sx * c[r.kz], cy = c[r.ky] - r.sy * c[r.kz];
    float u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
    if (u == 0.0f || v == 0.0f || w == 0.0f) {
        u = float(double(cx) * double(by) - double(cy) * double(bx));
        v = float(double(ax) * double(cy) - double(ay) * double(cx));
        w = float(double(bx) * double(ay) - double(by) * double(ax));
    }
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return false;
    const float det = u + v + w;
    if (det == 0.0f) return false;
    const float t = u * (r.sz * a[r.kz]) + v * (r.sz * b[r.kz]) + w * (r.sz * c[r.kz]);
    // tnear < t / det <= tfar without dividing: both sides times |det|.
    const float sign = det < 0.0f ? -1.0f : 1.0f;
    const float st = t * sign, absDet = det * sign;
    if (!(st > tnear * absDet) || !(st <= tfar * absDet)) return false;
    const float rcp = 1.0f / det;
    hit.t = t * rcp;
    hit.u = v * rcp;
    hit.v = w * rcp;
    return true;
}

// Front-to-back traversal with a stack of deferred siblings; `leaf(node)` handles a leaf and
// returns true to stop. `tfar` may shrink as leaves find hits (the nearest so far).
template <bool kCastersOnly, typename Leaf>
void traverse(const std::vector<BvhNode>& nodes, const RayFrame& r, float tnear, float& tfar,
              const Leaf& leaf) {
    if (nodes.empty()) return;
    float entry = 0.0f;
    if (kCastersOnly && !nodes[0].casters()) return;
    if (!hitBox(nodes[0], r, tnear, tfar, entry)) return;
    struct Deferred {
        std::uint32_t node;
        float entry;
    };
    Deferred stack[kBvhMaxDepth];
    int top = 0;
    std::uint32_t node = 0;
    for (;;) {
        const BvhNode& n = nodes[node];
        if (!n.leaf()) {
            std::uint32_t near = std::uint32_t(n.first), far = near + 1;
            float e0 = 0.0f, e1 = 0.0f;
            const bool h0 =
                (!kCastersOnly || nodes[near].casters()) && hitBox(nodes[near], r, tnear, tfar, e0);
            const bool h1 =
                (!kCastersOnly || nodes[far].casters()) && hitBox(nodes[far], r, tnear, tfar, e1);
            if (h0 && h1) {
                if (e1 < e0) {
                    std::swap(near, far);
                    std::swap(e0, e1);
                }
                assert(top < kBvhMaxDepth);
                stack[top++] = {far, e1};
                node = near;
                continue;
            }
            if (h0 || h1) {
                node = h0 ? near : far;
                continue;
            }
        } else if (leaf(n)) {
            return;
        }
        // The next deferred node the ray may still meet before its (shrunk) end.
        do {
            if (top == 0) return;
            --top;
        } while (stack[top].entry > tfar * kWiden);
        node = stack[top].node;
    }
}

}  // namespace

Bvh::Bvh(std::vector<BvhTriangle> triangles, const BvhBuildOptions& options) {
    if (triangles.size() > kBvhMaxTriangles) {
        throw std::length_error("a BVH holds at most 2^23 triangles");
    }
    Builder builder(triangles, options);
    builder.build();
    mNodes = builder.takeNodes();
    mTriangles.resize(triangles.size());
    const std::vector<std::uint32_t>& order = builder.order();
    for (std::size_t i = 0; i < order.size(); ++i)
        mTriangles[i] = triangles[order[i]];
}

BvhHit Bvh::nearest(const BvhRay& ray, BvhFilter filter, void* context) const {
    BvhHit best;
    const RayFrame r(ray);
    float tfar = ray.tfar;
    traverse<false>(mNodes, r, ray.tnear, tfar, [&](const BvhNode& leaf) {
        const auto first = std::uint32_t(leaf.first), end = first + leaf.count();
        for (std::uint32_t i = first; i < end; ++i) {
            const BvhTriangle& tri = mTriangles[i];
            BvhHit hit;
            if (!hitTriangle(r, tri, ray.tnear, tfar, hit)) continue;
            hit.triangle = i;
            if (filter && tri.has(BvhTriangle::kFiltered) && !filter(context, tri, hit)) continue;
            best = hit;
            tfar = hit.t;
        }
        return false;
    });
    return best;
}

bool Bvh::occluded(const BvhRay& ray, BvhFilter filter, void* context) const {
    const RayFrame r(ray);
    float tfar = ray.tfar;
    bool stopped = false;
    traverse<true>(mNodes, r, ray.tnear, tfar, [&](const BvhNode& leaf) {
        const auto first = std::uint32_t(leaf.first), end = first + leaf.count();
        for (std::uint32_t i = first; i < end; ++i) {
            const BvhTriangle& tri = mTriangles[i];
            if (!tri.has(BvhTriangle::kCaster)) continue;
            BvhHit hit;
            if (!hitTriangle(r, tri, ray.tnear, tfar, hit)) continue;
            hit.triangle = i;
            if (filter && tri.has(BvhTriangle::kFiltered) && !filter(context, tri, hit)) continue;
            stopped = true;
            return true;
        }
        return false;
    });
    return stopped;
}

}  // namespace gnomon::bvh
