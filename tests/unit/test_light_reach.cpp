// What a light's range spares its shadow map: receivers and view samples beyond it are unlit
// and casters beyond it shadow nothing lit, so a ranged spot's or point light's map neither
// reaches nor draws past it; and large meshes cut into pieces (shadow/MeshPieces.h) so that a
// map draws only the pieces in its reach.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "ViewSamplesTestUtil.h"
#include "scene/CameraMath.h"
#include "shadow/MeshPieces.h"
#include "shadow/PlannedMap.h"
#include "shadow/ShadowMath.h"

namespace gnomon {
namespace {

// A flat grid of n x n quads (two triangles each) over [0, n] x [0, n] at z = 0, rows of
// quads in order.
void grid(int n, std::vector<glm::vec3>& positions, std::vector<std::uint32_t>& indices) {
    for (int y = 0; y <= n; ++y) {
        for (int x = 0; x <= n; ++x)
            positions.emplace_back(float(x), float(y), 0.0f);
    }
    auto at = [&](int x, int y) { return std::uint32_t(y * (n + 1) + x); };
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            for (std::uint32_t i : {at(x, y), at(x + 1, y), at(x + 1, y + 1), at(x, y),
                                    at(x + 1, y + 1), at(x, y + 1)})
                indices.push_back(i);
        }
    }
}

using Triangle = std::array<std::uint32_t, 3>;
std::vector<Triangle> sortedTriangles(const std::vector<std::uint32_t>& indices, std::size_t from,
                                      std::size_t to) {
    std::vector<Triangle> t;
    for (std::size_t i = from; i < to; i += 3)
        t.push_back({indices[i], indices[i + 1], indices[i + 2]});
    std::sort(t.begin(), t.end());
    return t;
}

TEST(MeshPieces, CutsALargeMeshIntoCompactPiecesKeepingEveryTriangleAndTheGroups) {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
    grid(100, positions, indices);  // 20 000 triangles
    const std::vector<std::uint32_t> before = indices;
    const std::size_t closed = 3 * 8000;  // the first 40 rows stand for the solids' group
    const std::vector<shadow::MeshPiece> pieces = shadow::cutIntoPieces(positions, indices, closed);
    // The same triangles in each group, in some order.
    EXPECT_EQ(sortedTriangles(indices, 0, closed), sortedTriangles(before, 0, closed));
    EXPECT_EQ(sortedTriangles(indices, closed, indices.size()),
              sortedTriangles(before, closed, before.size()));
    std::uint32_t next = 0;
    float area = 0.0f;
    for (const shadow::MeshPiece& p : pieces) {
        EXPECT_EQ(p.firstIndex, next);  // in order, one after another, covering all
        next += p.indexCount;
        EXPECT_LE(p.indexCount, 3 * shadow::kPieceTriangles);
        EXPECT_EQ(p.closed, p.firstIndex < closed);
        EXPECT_LE(p.firstIndex + p.indexCount <= closed, p.closed);  // no piece mixes groups
        for (std::uint32_t i = p.firstIndex; i < p.firstIndex + p.indexCount; ++i) {
            EXPECT_TRUE(glm::all(glm::greaterThanEqual(positions[indices[i]], p.bounds.min)));
            EXPECT_TRUE(glm::all(glm::lessThanEqual(positions[indices[i]], p.bounds.max)));
        }
        area += (p.bounds.max.x - p.bounds.min.x) * (p.bounds.max.y - p.bounds.min.y);
    }
    EXPECT_EQ(next, indices.size());
    EXPECT_GE(pieces.size(), 20u);
    // Compact: the pieces' boxes together cover the grid (10 000) a few times at most, where
    // runs of triangles in the file's order (rows of quads) would each span the grid's width.
    EXPECT_LT(area, 3.0f * 10000.0f);
}

TEST(MeshPieces, ASmallMeshStaysWholeAndInOrder) {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
    grid(10, positions, indices);  // 200 triangles, under two pieces' worth
    const std::vector<std::uint32_t> before = indices;
    const auto pieces = shadow::cutIntoPieces(positions, indices, 0);
    ASSERT_EQ(pieces.size(), 1u);
    EXPECT_EQ(pieces[0].indexCount, indices.size());
    EXPECT_EQ(indices, before);
}

Light rangedSpot(float range) {
    Light spot = test::wideSpot();
    spot.position = {0.0f, 1.5f, 0.0f};
    spot.range = range;
    return spot;
}

// The ground seen from the ground camera, a spot 1.5 above its centre: with a range of 2, its
// map stops at the range (far) and holds a smaller window of the ground, at finer texels, and
// still every sample within the range.
TEST(LightReach, ASpotsMapStopsAtItsRange) {
    shadow::ViewSamples samples;
    const Camera camera = test::groundCamera();
    const shadow::FitScene scene = test::groundWithPost(camera, samples);
    const Light unbounded = rangedSpot(0.0f), ranged = rangedSpot(2.0f);
    const auto wide = shadow::lightCameraFrame(unbounded, camera, scene, 1024);
    const auto near = shadow::lightCameraFrame(ranged, camera, scene, 1024);
    ASSERT_TRUE(wide.valid && near.valid);
    EXPECT_EQ(near.reach, 2.0f);
    EXPECT_EQ(wide.reach, 0.0f);
    EXPECT_LE(near.far, 2.0f * 1.01f);
    EXPECT_LT(near.texelWorldSize, 0.5f * wide.texelWorldSize);
    const glm::mat4 clip = near.clipFromWorld();
    int held = 0;
    for (const glm::vec4& p : samples.points) {
        if (glm::length(glm::vec3(p) - ranged.position) > 1.9f) continue;
        const glm::vec4 c = clip * glm::vec4(glm::vec3(p), 1.0f);
        EXPECT_TRUE(glm::all(glm::lessThanEqual(glm::abs(glm::vec3(c) / c.w), glm::vec3(1.0f))));
        ++held;
    }
    EXPECT_GT(held, 10);
}

// Casters wholly beyond the range are culled from the map, those reaching into it are kept.
TEST(LightReach, CastersBeyondTheRangeAreNotDrawn) {
    shadow::ViewSamples samples;
    const Camera camera = test::groundCamera();
    const shadow::FitScene scene = test::groundWithPost(camera, samples);
    shadow::ShadowedLight sl;
    sl.frame = shadow::lightCameraFrame(rangedSpot(2.0f), camera, scene, 1024);
    sl.depthClamp = true;
    ASSERT_TRUE(sl.frame.valid);
    const shadow::LightVolume volume(sl);
    EXPECT_TRUE(volume.outside(Aabb{{1.5f, 0.0f, 1.5f}, {2.0f, 0.5f, 2.0f}}));     // 2.35 away
    EXPECT_FALSE(volume.outside(Aabb{{0.5f, 0.0f, 0.5f}, {0.9f, 0.5f, 0.9f}}));    // 1.2 away
    EXPECT_FALSE(volume.outside(Aabb{{-0.2f, 0.0f, -0.2f}, {0.2f, 3.0f, 0.2f}}));  // the post
}

// A point light whose range holds no receiver, or none the view sees, has no map; one that does,
// a map no deeper than its range.
TEST(LightReach, APointLightsMapEndsAtItsRangeAndIsNoneWhenItLightsNothing) {
    shadow::ViewSamples samples;
    const Camera camera = test::groundCamera();
    const shadow::FitScene scene = test::groundWithPost(camera, samples);
    Light lamp;
    lamp.type = LightType::Point;
    lamp.position = {1.0f, 1.0f, 1.0f};
    lamp.range = 1.5f;
    const auto lit = shadow::lightCameraFrame(lamp, camera, scene, 1024);
    ASSERT_TRUE(lit.valid);
    EXPECT_LE(lit.far, 1.5f * 1.01f);
    lamp.position = {9.0f, 0.5f, 9.0f};  // over the ground behind the camera: lights only
    EXPECT_FALSE(shadow::lightCameraFrame(lamp, camera, scene, 1024).valid);  // what is unseen
    lamp.position.y = 4.0f;  // 4 above the ground, 1 above the post's top: nothing within 1.5
    lamp.position.x = lamp.position.z = 3.0f;
    EXPECT_FALSE(shadow::lightCameraFrame(lamp, camera, scene, 1024).valid);
}

// Whether sample i (with its cell's other end) is wholly beyond `reach` of `apex`, tested
// directly: the segment's nearest point to the apex, less the larger pad.
bool beyondByHand(const shadow::ViewSamples& s, std::size_t i, const glm::vec3& apex, float reach) {
    std::size_t j = i;
    if (i + 1 < s.points.size() && s.farthestNext[i]) j = i + 1;
    if (i > 0 && s.farthestNext[i - 1]) j = i - 1;
    const glm::vec3 a = glm::vec3(s.points[i]) - apex,
                    d = glm::vec3(s.points[j]) - glm::vec3(a + apex);
    const float t =
        glm::dot(d, d) > 0.0f ? std::clamp(-glm::dot(a, d) / glm::dot(d, d), 0.0f, 1.0f) : 0.0f;
    const float pad = std::max(s.pad(s.points[i].w), s.pad(s.points[j].w));
    return glm::length(a + t * d) - pad > reach;
}

TEST(LightReach, ALightsSamplesAreThoseWithinItsRangeWithTheirPairsWhole) {
    shadow::ViewSamples samples;
    const Camera camera = test::groundCamera();
    test::groundWithPost(camera, samples);
    ASSERT_FALSE(samples.chunks.empty());  // viewSamples boxes its points in chunks
    shadow::ViewSamples within, walked;
    for (const glm::vec3 apex : {glm::vec3(1, 1, 1), glm::vec3(-4, 0.5f, -6), glm::vec3(0, 9, 0)}) {
        for (const float reach : {0.5f, 1.5f, 4.0f, 40.0f}) {
            shadow::samplesWithin(samples, apex, reach, within);
            std::vector<glm::vec4> expected;
            for (std::size_t i = 0; i < samples.points.size(); ++i) {
                if (!beyondByHand(samples, i, apex, reach)) expected.push_back(samples.points[i]);
            }
            EXPECT_EQ(within.points, expected) << "reach " << reach;
            for (std::size_t i = 0; i + 1 < within.points.size(); ++i) {
                if (within.farthestNext[i]) {
                    EXPECT_FALSE(within.farthestNext[i + 1]);
                }
            }
            EXPECT_EQ(shadow::anySampleWithin(samples, apex, reach), !expected.empty());
            // Without the chunks' boxes, point by point: the same points.
            shadow::ViewSamples plain = samples;
            plain.chunks.clear();
            plain.chunkPads.clear();
            shadow::samplesWithin(plain, apex, reach, walked);
            EXPECT_EQ(walked.points, within.points);
            // Fits read the same window from the subset as from all samples with the range.
            const glm::mat4 look = safeLookAt(apex, glm::vec3(0.0f), glm::vec3(0, 0, 1));
            shadow::SampleWindow all, some;
            const bool a = shadow::samplesWindow(samples, look, all, nullptr, reach);
            ASSERT_EQ(shadow::samplesWindow(within, look, some, nullptr, reach), a);
            if (a) {
                EXPECT_EQ(all.lo, some.lo);
                EXPECT_EQ(all.hi, some.hi);
                EXPECT_EQ(all.farthest, some.farthest);
            }
        }
    }
}

}  // namespace
}  // namespace gnomon
