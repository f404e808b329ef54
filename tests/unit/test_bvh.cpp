// The project's own BVH (bvh/Bvh.h): hits on hand-made triangles land where they should,
// within (tnear, tfar]; rays through edges and corners that triangles share meet one or more
// of them, never none (inside a closed mesh every ray hits); the build puts every triangle in
// exactly one leaf, children inside their parents, casters flagged up the tree; and
// traversal finds what a brute-force double-precision test of every triangle finds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

#include "bvh/Bvh.h"

namespace gnomon::bvh {
namespace {

constexpr std::uint32_t kCaster = BvhTriangle::kCaster;

BvhTriangle tri(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, int prim,
                std::uint32_t flags = kCaster) {
    return {a, 0.0f, b, float(prim), c, float(flags)};
}

// Counts every hit shown to it and lets the ray go on (triangles flagged kFiltered).
bool countHit(void* context, const BvhTriangle&, const BvhHit&) {
    ++*static_cast<int*>(context);
    return false;
}
int hitsAlong(const Bvh& bvh, const BvhRay& ray) {
    int hits = 0;
    EXPECT_FALSE(bvh.occluded(ray, &countHit, &hits));
    return hits;
}

glm::vec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<float> n(0.0f, 1.0f);
    for (;;) {
        const glm::vec3 d(n(rng), n(rng), n(rng));
        if (glm::length(d) > 1e-3f) return glm::normalize(d);
    }
}

TEST(Bvh, HitsATriangleWhereTheRayMeetsIt) {
    const glm::vec3 p0(-1.0f, -1.0f, 5.0f), p1(2.0f, -1.0f, 5.0f), p2(-1.0f, 3.0f, 5.0f);
    const Bvh bvh({tri(p0, p1, p2, 7)});
    const BvhRay ray{{0.25f, 0.5f, 0.0f}, {0.0f, 0.0f, 1.0f}, 0.0f, 100.0f};
    const BvhHit h = bvh.nearest(ray, nullptr, nullptr);
    ASSERT_TRUE(h.hit());
    EXPECT_FLOAT_EQ(h.t, 5.0f);
    const glm::vec3 at = (1.0f - h.u - h.v) * p0 + h.u * p1 + h.v * p2;
    EXPECT_NEAR(at.x, 0.25f, 1e-6f);
    EXPECT_NEAR(at.y, 0.5f, 1e-6f);
    EXPECT_FLOAT_EQ(bvh.triangles()[h.triangle].primitive, 7.0f);
    // The same from behind, and along a slanted ray.
    EXPECT_TRUE(
        bvh.nearest({{0.25f, 0.5f, 9.0f}, {0, 0, -1}, 0.0f, 100.0f}, nullptr, nullptr).hit());
    const glm::vec3 d = glm::normalize(glm::vec3(0.1f, 0.2f, 1.0f));
    const BvhHit s = bvh.nearest({{0, 0, 0}, d, 0.0f, 100.0f}, nullptr, nullptr);
    ASSERT_TRUE(s.hit());
    EXPECT_NEAR(s.t, 5.0f / d.z, 1e-5f);
    EXPECT_TRUE(bvh.occluded({{0, 0, 0}, d, 0.0f, 100.0f}, nullptr, nullptr));
}

TEST(Bvh, MissesBesideBehindAndAlongTheTriangle) {
    const Bvh bvh({tri({-1, -1, 5}, {1, -1, 5}, {-1, 1, 5}, 0)});
    auto none = [&](const BvhRay& r) {
        return !bvh.nearest(r, nullptr, nullptr).hit() && !bvh.occluded(r, nullptr, nullptr);
    };
    EXPECT_TRUE(none({{0.6f, 0.6f, 0}, {0, 0, 1}, 0.0f, 100.0f}));  // past the hypotenuse
    EXPECT_TRUE(none({{0, 0, 0}, {0, 0, -1}, 0.0f, 100.0f}));       // pointing away
    EXPECT_TRUE(none({{-5, 0, 5}, {1, 0, 0}, 0.0f, 100.0f}));       // in its plane
    EXPECT_TRUE(none({{0, 0, 0}, {0, 0, 0}, 0.0f, 100.0f}));        // no direction
    EXPECT_FALSE(none({{0, 0, 0}, {0, 0, 1}, 0.0f, 100.0f}));
    const Bvh empty(std::vector<BvhTriangle>{});
    EXPECT_TRUE(empty.nodes().empty());
    EXPECT_FALSE(empty.nearest({{0, 0, 0}, {0, 0, 1}, 0.0f, 100.0f}, nullptr, nullptr).hit());
}

// Hits count in tnear < t <= tfar, as Embree counts them.
TEST(Bvh, HitsLieWithinTnearAndTfar) {
    const Bvh bvh({tri({-1, -1, 5}, {1, -1, 5}, {-1, 1, 5}, 0)});
    auto hits = [&](float tnear, float tfar) {
        const BvhRay r{{0, 0, 0}, {0, 0, 1}, tnear, tfar};
        const bool n = bvh.nearest(r, nullptr, nullptr).hit();
        EXPECT_EQ(n, bvh.occluded(r, nullptr, nullptr)) << tnear << " " << tfar;
        return n;
    };
    EXPECT_TRUE(hits(0.0f, 5.0f));
    EXPECT_FALSE(hits(0.0f, std::nextafter(5.0f, 0.0f)));
    EXPECT_FALSE(hits(5.0f, 10.0f));
    EXPECT_TRUE(hits(std::nextafter(5.0f, 0.0f), 10.0f));
    EXPECT_TRUE(hits(0.0f, INFINITY));
    // Two triangles, one behind the other: the nearest within the bounds is found.
    const Bvh two(
        {tri({-1, -1, 5}, {1, -1, 5}, {-1, 1, 5}, 0), tri({-1, -1, 8}, {1, -1, 8}, {-1, 1, 8}, 1)});
    EXPECT_FLOAT_EQ(two.nearest({{0, 0, 0}, {0, 0, 1}, 0.0f, 100.0f}, nullptr, nullptr).t, 5.0f);
    EXPECT_FLOAT_EQ(two.nearest({{0, 0, 0}, {0, 0, 1}, 6.0f, 100.0f}, nullptr, nullptr).t, 8.0f);
}

// Rays aimed at points of the edge two triangles share (a folded quad's diagonal, corners in
// no special position) and at the corner a fan of six shares: each meets one or both edge
// triangles, one or more of the fan's, never none. (Where the fold's edge is a silhouette,
// both triangles lie on one side of it and a ray just beside it rightly misses both: those
// rays are not counted.) A test that decides each triangle's edges on its own
// (Moeller-Trumbore with rounding) lets some of them through.
TEST(Bvh, RaysThroughSharedEdgesAndCornersAlwaysHit) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const std::uint32_t counted = kCaster | BvhTriangle::kFiltered;
    const glm::vec3 a(-1.3f, -0.7f, 4.1f), b(1.1f, -0.9f, 5.3f), c(0.9f, 1.2f, 4.7f),
        d(-0.8f, 1.05f, 3.9f);
    const Bvh quad({tri(a, b, c, 0, counted), tri(a, c, d, 1, counted)});
    const glm::vec3 centre(0.13f, -0.21f, 2.7f);
    std::vector<BvhTriangle> fan;
    for (int i = 0; i < 6; ++i) {
        const float a0 = 1.0471976f * float(i), a1 = 1.0471976f * float(i + 1);
        const glm::vec3 q0 = centre + glm::vec3(std::cos(a0), std::sin(a0), 0.3f * std::sin(a0));
        const glm::vec3 q1 = centre + glm::vec3(std::cos(a1), std::sin(a1), 0.3f * std::sin(a1));
        fan.push_back(tri(centre, q0, q1, i, counted));
    }
    fan[5].p2 = fan[0].p1;  // the fan closes on its first spoke, bit for bit
    const Bvh fanBvh(fan);
    const glm::dvec3 fanNormal = glm::normalize(glm::dvec3(0.0, -0.3, 1.0));  // z = 0.3 y
    int acrossEdge = 0, twice = 0, atCorner = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 from = glm::vec3(unit(rng), unit(rng), unit(rng)) * 6.0f - 3.0f;
        const glm::vec3 target = glm::mix(a, c, unit(rng));
        const glm::vec3 dir = glm::normalize(target - from);
        // b and d on either side of the plane through the ray and the edge, clear of it.
        const glm::dvec3 o(from);
        const glm::dvec3 m = glm::normalize(glm::cross(glm::dvec3(a) - o, glm::dvec3(c) - o));
        const double sb = glm::dot(m, glm::dvec3(b) - o), sd = glm::dot(m, glm::dvec3(d) - o);
        const int n = hitsAlong(quad, {from, dir, 0.0f, 100.0f});
        ASSERT_LE(n, 2);
        if (sb * sd < 0.0 && std::min(std::fabs(sb), std::fabs(sd)) > 1e-3) {
            ASSERT_GE(n, 1) << "through the edge at ray " << i;
            ++acrossEdge;
            twice += n == 2;
        }
        const glm::vec3 toCorner = glm::normalize(centre - from);
        if (std::fabs(glm::dot(fanNormal, glm::dvec3(toCorner))) < 1e-2) continue;  // edge-on
        ++atCorner;
        const int k = hitsAlong(fanBvh, {from, toCorner, 0.0f, 100.0f});
        ASSERT_GE(k, 1) << "through the corner at ray " << i;
        ASSERT_LE(k, 6);
        ASSERT_TRUE(fanBvh.nearest({from, toCorner, 0.0f, 100.0f}, nullptr, nullptr).hit());
    }
    EXPECT_GT(acrossEdge, 10000);
    EXPECT_GT(atCorner, 19000);
    std::printf("%d rays across the edge, %d of them met both triangles\n", acrossEdge, twice);
}

// A bumpy closed sphere (shared corners, a seam closed on the same vertices): every ray from
// inside meets it; none leaks through a crack.
TEST(Bvh, NoRayLeaksOutOfAClosedMesh) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> bump(0.9f, 1.1f);
    const int rows = 24, columns = 40;
    std::vector<glm::vec3> v;
    v.push_back({0.0f, 2.0f, 0.0f});  // the poles
    v.push_back({0.0f, -2.0f, 0.0f});
    for (int r = 1; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            const float th = 3.14159265f * float(r) / float(rows);
            const float ph = 6.2831853f * float(c) / float(columns);
            v.push_back(
                2.0f * bump(rng) *
                glm::vec3(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph)));
        }
    }
    auto at = [&](int r, int c) { return v[std::size_t(2 + (r - 1) * columns + c % columns)]; };
    std::vector<BvhTriangle> t;
    for (int c = 0; c < columns; ++c) {
        t.push_back(tri(v[0], at(1, c + 1), at(1, c), int(t.size())));
        t.push_back(tri(v[1], at(rows - 1, c), at(rows - 1, c + 1), int(t.size())));
        for (int r = 1; r + 1 < rows; ++r) {
            t.push_back(tri(at(r, c), at(r, c + 1), at(r + 1, c + 1), int(t.size())));
            t.push_back(tri(at(r, c), at(r + 1, c + 1), at(r + 1, c), int(t.size())));
        }
    }
    const Bvh bvh(t, {16, 1.0f, 1.0f, 2});
    std::uniform_real_distribution<float> inside(-0.5f, 0.5f);
    for (int i = 0; i < 100000; ++i) {
        const glm::vec3 from(inside(rng), inside(rng), inside(rng));
        const BvhRay ray{from, randomUnit(rng), 0.0f, INFINITY};
        ASSERT_TRUE(bvh.nearest(ray, nullptr, nullptr).hit()) << "ray " << i << " leaked";
        ASSERT_TRUE(bvh.occluded(ray, nullptr, nullptr)) << "ray " << i << " leaked";
    }
    // Rays aimed straight at the vertices from the centre, along axes through the poles.
    for (const glm::vec3& p : v) {
        ASSERT_TRUE(
            bvh.nearest({{0, 0, 0}, glm::normalize(p), 0.0f, 10.0f}, nullptr, nullptr).hit());
    }
}

// Axis-aligned squares side by side and a ray straight down their shared edge: its
// direction's zero components and an origin on the boxes' faces give 0 x inf in the slab
// test, which must not throw the boxes away.
TEST(Bvh, AxisAlignedRaysOnBoxFacesStillHit) {
    std::vector<BvhTriangle> t;
    for (int i = 0; i < 4; ++i) {
        const float x0 = float(i - 2), x1 = float(i - 1);
        t.push_back(tri({x0, 0, 0}, {x1, 0, 0}, {x1, 0, 1}, 2 * i));
        t.push_back(tri({x0, 0, 0}, {x1, 0, 1}, {x0, 0, 1}, 2 * i + 1));
    }
    const Bvh bvh(t, {16, 1.0f, 1.0f, 1});
    for (const float x : {-2.0f, -1.0f, 0.0f, 1.0f, 2.0f}) {
        for (const float z : {0.0f, 0.5f, 1.0f}) {
            for (const float zero : {0.0f, -0.0f}) {
                const BvhRay down{{x, 3.0f, z}, {zero, -1.0f, zero}, 0.0f, 10.0f};
                EXPECT_TRUE(bvh.nearest(down, nullptr, nullptr).hit()) << x << ", " << z;
                EXPECT_TRUE(bvh.occluded(down, nullptr, nullptr)) << x << ", " << z;
            }
        }
    }
}

// A triangle soup: random sizes, clusters and a few long slivers.
std::vector<BvhTriangle> soup(int n, std::mt19937& rng) {
    std::uniform_real_distribution<float> pos(-10.0f, 10.0f), size(0.05f, 1.5f);
    std::vector<BvhTriangle> t;
    for (int i = 0; i < n; ++i) {
        const glm::vec3 c(pos(rng), pos(rng) * (i % 3 == 0 ? 0.1f : 1.0f), pos(rng));
        const float s = size(rng) * (i % 50 == 0 ? 8.0f : 1.0f);
        t.push_back({c + s * randomUnit(rng), float(i % 7), c + s * randomUnit(rng), float(i),
                     c + s * randomUnit(rng), float(i % 4 == 0 ? 0u : kCaster)});
    }
    return t;
}

bool inside(const glm::vec3& p, const BvhNode& n) {
    return glm::all(glm::greaterThanEqual(p, n.lo)) && glm::all(glm::lessThanEqual(p, n.hi));
}

// Walks the tree: every triangle in exactly one leaf, boxes nested, casters flagged.
// `depth` (if set): the depth of the deepest leaf (the root's is 0).
void checkTree(const Bvh& bvh, std::size_t triangles, int maxLeaf, int* depth = nullptr) {
    const std::vector<BvhNode>& nodes = bvh.nodes();
    ASSERT_EQ(bvh.triangles().size(), triangles);
    std::vector<int> inLeaves(triangles, 0);
    std::vector<std::pair<std::uint32_t, int>> stack{{0u, 0}};
    int deepest = 0;
    while (!stack.empty()) {
        const auto [i, depth] = stack.back();
        stack.pop_back();
        ASSERT_LT(i, nodes.size());
        const BvhNode& n = nodes[i];
        deepest = std::max(deepest, depth);
        ASSERT_EQ(n.first, std::floor(n.first));
        ASSERT_EQ(n.info, std::floor(n.info));
        bool casters = false;
        if (n.leaf()) {
            ASSERT_LE(n.count(), std::uint32_t(maxLeaf));
            const auto first = std::uint32_t(n.first);
            for (std::uint32_t k = first; k < first + n.count(); ++k) {
                ASSERT_LT(k, triangles);
                ++inLeaves[k];
                const BvhTriangle& t = bvh.triangles()[k];
                ASSERT_TRUE(inside(t.p0, n) && inside(t.p1, n) && inside(t.p2, n)) << k;
                casters = casters || t.has(kCaster);
            }
        } else {
            const auto c = std::uint32_t(n.first);
            ASSERT_LT(c + 1, nodes.size());
            for (const std::uint32_t child : {c, c + 1}) {
                ASSERT_TRUE(inside(nodes[child].lo, n) && inside(nodes[child].hi, n)) << child;
                casters = casters || nodes[child].casters();
                stack.push_back({child, depth + 1});
            }
        }
        ASSERT_EQ(n.casters(), casters) << "node " << i;
    }
    EXPECT_LT(deepest, kBvhMaxDepth);
    for (std::size_t k = 0; k < triangles; ++k)
        ASSERT_EQ(inLeaves[k], 1) << "triangle " << k;
    if (depth) *depth = deepest;
}

TEST(Bvh, BuildPutsEveryTriangleInOneLeafInsideNestedBoxes) {
    std::mt19937 rng(3);
    std::vector<BvhTriangle> t = soup(5000, rng);
    const Bvh bvh(t);
    checkTree(bvh, t.size(), BvhBuildOptions{}.maxLeaf);
    // The leaves hold the input's triangles, each once, unchanged.
    auto key = [](const BvhTriangle& x) { return std::pair(x.primitive, x.p0.x); };
    std::vector<std::pair<float, float>> in, out;
    for (const BvhTriangle& x : t)
        in.push_back(key(x));
    for (const BvhTriangle& x : bvh.triangles())
        out.push_back(key(x));
    std::sort(in.begin(), in.end());
    std::sort(out.begin(), out.end());
    EXPECT_EQ(in, out);
    // The heuristic makes a real tree: leaves far smaller than the soup.
    EXPECT_GT(bvh.nodes().size(), t.size() / 8);
    // Nothing to split on: identical triangles still build, to the median rule's depth.
    const std::vector<BvhTriangle> same(3000, tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0));
    const Bvh stacked(same);
    checkTree(stacked, same.size(), BvhBuildOptions{}.maxLeaf);
    checkTree(Bvh(t, {4, 1.0f, 2.0f, 1}), t.size(), 1);
    // Below the median depth each split halves the triangles: no deeper than log2 of them.
    int depth = 0;
    checkTree(Bvh(t, {16, 1.0f, 1.0f, 1, 3}), t.size(), 1, &depth);
    EXPECT_LE(depth, 3 + 13);
    checkTree(Bvh(t, {16, 1.0f, 1.0f, 1, 0}), t.size(), 1, &depth);
    EXPECT_EQ(depth, 13);  // 5000 triangles, one per leaf: ceil(log2 5000)
}

// The nearest hit in double precision over every triangle (Moeller and Trumbore 1997), and
// whether the ray passes within `margin` of an edge or of a second hit (a tie either way).
struct Brute {
    int triangle = -1;
    double t = INFINITY;
    bool ambiguous = false;
};
Brute bruteNearest(const std::vector<BvhTriangle>& t, const BvhRay& r, bool castersOnly) {
    Brute best;
    const glm::dvec3 o(r.origin), d(r.dir);
    std::vector<double> ts;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (castersOnly && !t[i].has(kCaster)) continue;
        const glm::dvec3 p0(t[i].p0), e1 = glm::dvec3(t[i].p1) - p0, e2 = glm::dvec3(t[i].p2) - p0;
        const glm::dvec3 pv = glm::cross(d, e2);
        const double det = glm::dot(e1, pv);
        if (det == 0.0) continue;
        const glm::dvec3 s = o - p0, q = glm::cross(s, e1);
        const double u = glm::dot(s, pv) / det, v = glm::dot(d, q) / det;
        const double tt = glm::dot(e2, q) / det;
        const double edge = std::min({u, v, 1.0 - u - v});
        if (edge < -1e-5 || !(tt > r.tnear) || !(tt <= r.tfar)) continue;
        if (edge < 1e-5) best.ambiguous = true;
        ts.push_back(tt);
        if (tt < best.t) best = {int(i), tt, best.ambiguous};
    }
    for (const double x : ts)
        if (x != best.t && std::fabs(x - best.t) < 1e-5 * best.t) best.ambiguous = true;
    return best;
}

TEST(Bvh, FindsWhatEveryTriangleTestedFinds) {
    std::mt19937 rng(9);
    const std::vector<BvhTriangle> t = soup(3000, rng);
    const Bvh bvh(t);
    std::uniform_real_distribution<float> pos(-12.0f, 12.0f), len(1.0f, 40.0f);
    int hits = 0, occluded = 0, checked = 0;
    for (int i = 0; i < 3000; ++i) {
        const BvhRay r{{pos(rng), pos(rng), pos(rng)}, randomUnit(rng), 0.0f, len(rng)};
        const Brute all = bruteNearest(t, r, false), casters = bruteNearest(t, r, true);
        if (all.ambiguous || casters.ambiguous) continue;
        ++checked;
        const BvhHit h = bvh.nearest(r, nullptr, nullptr);
        ASSERT_EQ(h.hit(), all.triangle >= 0) << "ray " << i;
        const bool o = bvh.occluded(r, nullptr, nullptr);
        ASSERT_EQ(o, casters.triangle >= 0) << "ray " << i;
        occluded += o;
        if (!h.hit()) continue;
        ++hits;
        EXPECT_EQ(bvh.triangles()[h.triangle].primitive, t[std::size_t(all.triangle)].primitive);
        EXPECT_NEAR(h.t, all.t, 1e-5 * all.t + 1e-5);  // rounding grows with the coordinates
    }
    EXPECT_GT(checked, 2900);
    EXPECT_GT(hits, 300);
    EXPECT_GT(occluded, 200);
    EXPECT_LT(occluded, hits);  // some rays met only non-casters
}

// Filtered triangles: the nearest looks past the hits the filter turns down, and a shadow ray
// shows the filter each filtered caster it meets, once, until one stops it.
TEST(Bvh, FilterDecidesFilteredHits) {
    const std::uint32_t filtered = kCaster | BvhTriangle::kFiltered;
    const Bvh bvh({tri({-1, -1, 2}, {1, -1, 2}, {-1, 1, 2}, 0, filtered),
                   tri({-1, -1, 4}, {1, -1, 4}, {-1, 1, 4}, 1, filtered),
                   tri({-1, -1, 6}, {1, -1, 6}, {-1, 1, 6}, 2, kCaster),
                   tri({-1, -1, 8}, {1, -1, 8}, {-1, 1, 8}, 3, 0)});
    struct Seen {
        std::vector<int> prims;
        int stopAt = -1;
    };
    auto filter = [](void* ctx, const BvhTriangle& t, const BvhHit& h) {
        auto& s = *static_cast<Seen*>(ctx);
        EXPECT_NEAR(h.t, 2.0f * (t.primitive + 1.0f), 1e-5f);
        s.prims.push_back(int(t.primitive));
        return int(t.primitive) == s.stopAt;
    };
    const BvhRay ray{{-0.5f, -0.5f, 0.0f}, {0, 0, 1}, 0.0f, 100.0f};
    Seen pass;
    const BvhHit h = bvh.nearest(ray, filter, &pass);
    EXPECT_FLOAT_EQ(bvh.triangles()[h.triangle].primitive, 2.0f);
    Seen stopAt1{{}, 1};
    EXPECT_FLOAT_EQ(bvh.triangles()[bvh.nearest(ray, filter, &stopAt1).triangle].primitive, 1.0f);
    Seen shadow;
    EXPECT_TRUE(bvh.occluded(ray, filter, &shadow));  // the unfiltered caster at 6
    Seen shortRay;
    EXPECT_FALSE(bvh.occluded({ray.origin, ray.dir, 0.0f, 5.0f}, filter, &shortRay));
    std::sort(shortRay.prims.begin(), shortRay.prims.end());
    EXPECT_EQ(shortRay.prims, (std::vector<int>{0, 1}));
    // The non-caster at 8 is seen by view rays only.
    EXPECT_FLOAT_EQ(bvh.nearest({ray.origin, ray.dir, 7.0f, 100.0f}, nullptr, nullptr).t, 8.0f);
    EXPECT_FALSE(bvh.occluded({ray.origin, ray.dir, 7.0f, 100.0f}, nullptr, nullptr));
}

}  // namespace
}  // namespace gnomon::bvh
