// Sample distribution fitting (Lauritzen et al. 2011) without GL: the reduced grid keeps
// each block's nearest and farthest depth, samples unproject onto the surface they came from, and
// directional light cameras fitted to samples cover every sample with a smaller map than the boxes
// give. Point and spot lights' frames are tested in test_light_samples.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "ViewSamplesTestUtil.h"
#include "shadow/ShadowMath.h"
#include "shadow/ViewSamples.h"

namespace gnomon {
namespace {

using test::groundCamera;
using test::groundRanges;
using test::groundWithPost;
using test::wideSpot;

TEST(ViewSamples, GridBlocksKeepTheCellsUnderTheLimit) {
    const shadow::SampleGrid wide = shadow::sampleGrid(1920, 1080, 128);
    EXPECT_EQ(wide.block, 15);
    EXPECT_EQ(wide.cells, glm::ivec2(128, 72));
    const shadow::SampleGrid odd = shadow::sampleGrid(129, 50, 128);
    EXPECT_EQ(odd.block, 2);
    EXPECT_EQ(odd.cells, glm::ivec2(65, 25));  // the last column of cells is half full
    const shadow::SampleGrid small = shadow::sampleGrid(100, 50, 128);
    EXPECT_EQ(small.block, 1);
    EXPECT_EQ(small.cells, glm::ivec2(100, 50));
}

// View depth of the ground plane's points seen at the view's lower border.
float lowerBorderDepth(const Camera& camera) {
    const float down = std::atan2(camera.eye.y, glm::length(glm::vec2(camera.eye.x, camera.eye.z)));
    const float lowerBorder = down + 0.5f * glm::radians(camera.fovyDegrees);
    return camera.eye.y / std::sin(lowerBorder) * std::cos(lowerBorder - down);
}

TEST(ViewSamples, DepthSamplesLandOnTheSurfaceTheyCameFrom) {
    const Camera camera = groundCamera();
    const shadow::SampleGrid grid = shadow::sampleGrid(64, 48, 128);  // one pixel per cell
    const float aspect = 4.0f / 3.0f;
    const std::vector<glm::vec2> ranges = groundRanges(camera, grid, aspect);
    shadow::ViewSamples samples;
    shadow::viewSamples(ranges, grid, camera, aspect, samples);
    std::size_t covered = 0;
    for (const glm::vec2& r : ranges)
        covered += r.x < 1.0f ? 1u : 0u;
    ASSERT_GT(covered, 100u);
    ASSERT_EQ(samples.points.size(), covered);  // one depth per cell: one point each
    const glm::mat4 view = gnomon::viewFromWorld(camera);
    for (const glm::vec4& p : samples.points) {
        EXPECT_NEAR(p.y, 0.0f, 2e-3f * p.w);
        EXPECT_NEAR(p.w, -(view * glm::vec4(glm::vec3(p), 1.0f)).z, 1e-3f * p.w);
        EXPECT_GE(p.w, samples.nearest);
        EXPECT_LE(p.w, samples.farthest);
    }
    // The bottom row's centres are half a pixel above the view's lower border: the nearest
    // ground the view shows lies between the nearest sample and a pad before it.
    const float border = lowerBorderDepth(camera);
    EXPECT_LE(samples.nearest - samples.pad(samples.nearest), border);
    EXPECT_GE(samples.nearest, border);
}

TEST(ViewSamples, BlocksKeepTheirNearestAndFarthestPixels) {
    // 8 x 8 pixel blocks: the farthest ground pixel before the horizon is not lost between
    // two samples, and the view's nearest ground is within a pad of the nearest sample.
    Camera camera = groundCamera();
    const float aspect = 4.0f / 3.0f;
    const shadow::SampleGrid fine = shadow::sampleGrid(256, 192, 256);
    const shadow::SampleGrid coarse = shadow::sampleGrid(256, 192, 32);
    ASSERT_EQ(coarse.block, 8);
    shadow::ViewSamples all, blocks;
    shadow::viewSamples(groundRanges(camera, fine, aspect), fine, camera, aspect, all);
    shadow::viewSamples(groundRanges(camera, coarse, aspect), coarse, camera, aspect, blocks);
    EXPECT_FLOAT_EQ(blocks.farthest, all.farthest);
    EXPECT_FLOAT_EQ(blocks.nearest, all.nearest);
    EXPECT_GT(blocks.points.size(), std::size_t(coarse.cells.x * coarse.cells.y) / 4);
    EXPECT_LT(blocks.points.size(), all.points.size() / 16);
    // Every pixel's point lies within a pad of a block point: the light-space box of the
    // blocks' points holds every pixel's.
    const Aabb coarseBox = shadow::samplesInLight(blocks, glm::mat4(1.0f), 0.0f, 1e9f);
    for (const glm::vec4& p : all.points) {
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(glm::vec3(p), coarseBox.min)) &&
                    glm::all(glm::lessThanEqual(glm::vec3(p), coarseBox.max)))
            << p.x << " " << p.y << " " << p.z;
    }
}

TEST(ViewSamples, LightSpaceBoxHoldsTheWindowsSamplesWithTheirPad) {
    shadow::ViewSamples samples;
    samples.points = {{0.0f, 0.0f, 0.0f, 1.0f}, {4.0f, 0.0f, 0.0f, 2.0f}, {8.0f, 0.0f, 0.0f, 9.0f}};
    samples.padPerDepth = 0.1f;
    const Aabb near = shadow::samplesInLight(samples, glm::mat4(1.0f), 0.0f, 3.0f);
    EXPECT_FLOAT_EQ(near.min.x, -0.1f);
    EXPECT_FLOAT_EQ(near.max.x, 4.2f);
    EXPECT_TRUE(shadow::samplesInLight(samples, glm::mat4(1.0f), 3.0f, 8.0f).empty());
}

TEST(ViewSamples, AutoCascadesCountFactorsOfEightInDepth) {
    EXPECT_EQ(shadow::autoCascadeCount(1.0f, 7.9f), 1);
    EXPECT_EQ(shadow::autoCascadeCount(1.0f, 8.1f), 2);
    EXPECT_EQ(shadow::autoCascadeCount(1.0f, 100.0f), 3);
    EXPECT_EQ(shadow::autoCascadeCount(0.1f, 1.0e4f), 4);
    EXPECT_EQ(shadow::autoCascadeCount(0.0f, 5.0f), 1);
    EXPECT_EQ(shadow::autoCascadeCount(5.0f, 5.0f), 1);
}

// Every sample, projected through the frame, lands inside the map and its depth range.
void expectCovers(const shadow::LightCameraFrame& f, const shadow::ViewSamples& samples) {
    for (const glm::vec4& p : samples.points) {
        const glm::vec4 c = f.clipFromWorld() * glm::vec4(glm::vec3(p), 1.0f);
        EXPECT_LE(std::abs(c.x), c.w) << p.x << " " << p.z;
        EXPECT_LE(std::abs(c.y), c.w) << p.x << " " << p.z;
        EXPECT_LE(std::abs(c.z), c.w) << p.x << " " << p.z;
    }
}

TEST(ViewSamples, SunFittedToSamplesCoversThemWithSmallerTexels) {
    // A 200 x 200 ground with a post on it, seen close up: the boxes span the whole ground.
    Camera camera = groundCamera();
    camera.far = 30.0f;
    shadow::ViewSamples samples;
    shadow::FitScene scene = groundWithPost(camera, samples, 100.0f);
    scene.samples = nullptr;  // first from the boxes alone
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    const shadow::LightCameraFrame boxes = shadow::lightCameraFrame(sun, camera, scene, 1024);
    scene.samples = &samples;
    const shadow::LightCameraFrame sampled = shadow::lightCameraFrame(sun, camera, scene, 1024);
    ASSERT_TRUE(boxes.valid);
    ASSERT_TRUE(sampled.valid);
    EXPECT_LT(sampled.texelWorldSize, 0.5f * boxes.texelWorldSize);
    expectCovers(sampled, samples);

    // Cascades: each covers the samples of its window; an empty window has no frame.
    const float middle = 0.5f * (samples.nearest + samples.farthest);
    const shadow::LightCameraFrame first =
        shadow::sampledCascadeFrame(sun.direction, scene, 0.0f, middle, 1024);
    ASSERT_TRUE(first.valid);
    EXPECT_LT(first.texelWorldSize, sampled.texelWorldSize);
    shadow::ViewSamples firstHalf = samples;
    std::erase_if(firstHalf.points, [&](const glm::vec4& p) { return p.w > middle; });
    expectCovers(first, firstHalf);
    EXPECT_FALSE(shadow::sampledCascadeFrame(sun.direction, scene, samples.farthest + 1.0f,
                                             samples.farthest + 2.0f, 1024)
                     .valid);
}

// The ground close up (|x|, |z| <= 10) with a post on it, and its view's samples.
class ViewSamplesOnGround : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_FALSE(samples.empty()); }
    const Camera camera = groundCamera();
    shadow::ViewSamples samples;
    shadow::FitScene scene = groundWithPost(camera, samples);
};

TEST_F(ViewSamplesOnGround, PointLightOverWhatTheViewSeesGetsOneFrustumNotACube) {
    // Lit by a point light.
    Light lamp;
    lamp.type = LightType::Point;
    // High above: everything the view sees lies in a narrow window, one frustum holds it
    // with texels finer than a cube face's (2 / 1024 at distance 1).
    lamp.position = {1.0f, 40.0f, 2.0f};
    const shadow::LightCameraFrame high = shadow::lightCameraFrame(lamp, camera, scene, 1024);
    ASSERT_TRUE(high.valid);
    EXPECT_EQ(high.kind, shadow::FrameKind::Perspective);
    EXPECT_LT(high.texelWorldSize, 0.5f * 2.0f / 1024.0f);
    expectCovers(high, samples);
    // Just above the ground: the samples spread over more than a cube face; a cube.
    lamp.position = {0.0f, 0.5f, 0.0f};
    EXPECT_EQ(shadow::lightCameraFrame(lamp, camera, scene, 1024).kind, shadow::FrameKind::Cube);
    // Without samples (fit to boxes): always the cube.
    lamp.position = {1.0f, 40.0f, 2.0f};
    scene.samples = nullptr;
    EXPECT_EQ(shadow::lightCameraFrame(lamp, camera, scene, 1024).kind, shadow::FrameKind::Cube);
}

TEST_F(ViewSamplesOnGround, SpotLightMapsOnlyThePartOfItsConeTheViewSees) {
    // Under a wide spot whose cone reaches far past what the camera sees.
    const Light spot = wideSpot();
    const float coneTexel = 2.0f * std::tan(glm::radians(70.0f)) / 1024.0f;
    const shadow::LightCameraFrame fitted = shadow::lightCameraFrame(spot, camera, scene, 1024);
    ASSERT_TRUE(fitted.valid);
    EXPECT_EQ(fitted.kind, shadow::FrameKind::Perspective);
    EXPECT_LT(fitted.texelWorldSize, 0.5f * coneTexel);
    expectCovers(fitted, samples);  // every sample lies in the cone here
    // Without samples (fit to boxes): the whole cone.
    scene.samples = nullptr;
    EXPECT_FLOAT_EQ(shadow::lightCameraFrame(spot, camera, scene, 1024).texelWorldSize, coneTexel);
}

// The two sides of an orthographic frame's box across the light, world units.
glm::vec2 orthographicSides(const shadow::LightCameraFrame& f) {
    return {2.0f / f.clipFromLight[0][0], 2.0f / f.clipFromLight[1][1]};
}

// A low sun stretches what the view sees along the light. A still frame quantises the box's
// short side on its own, so its texels across it are finer; frames that follow a moving
// view keep that side the long one over a power of two (fewer steps as the view moves).
// Both cover every sample.
TEST(ViewSamples, StillFramesFitTheShortSideTighterThanFollowingOnes) {
    const Camera camera = groundCamera();
    shadow::ViewSamples samples;
    const shadow::FitScene scene = groundWithPost(camera, samples);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.9f, -0.3f, 0.2f));
    shadow::HeldExtent held;
    const shadow::LightCameraFrame still = shadow::lightCameraFrame(sun, camera, scene, 1024);
    const shadow::LightCameraFrame following =
        shadow::lightCameraFrame(sun, camera, scene, 1024, &held);
    ASSERT_TRUE(still.valid && following.valid);
    expectCovers(still, samples);
    expectCovers(following, samples);
    const glm::vec2 a = orthographicSides(still), b = orthographicSides(following);
    const int shortAxis = b.x < b.y ? 0 : 1;
    EXPECT_FLOAT_EQ(a[1 - shortAxis], b[1 - shortAxis]);  // the long side: one rule
    const float powers = std::log2(b[1 - shortAxis] / b[shortAxis]);
    EXPECT_FLOAT_EQ(powers, std::round(powers));
    EXPECT_LT(a[shortAxis], 0.8f * b[shortAxis]) << a[shortAxis] << " " << b[shortAxis];
}

}  // namespace
}  // namespace gnomon
