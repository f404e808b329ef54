// Sample distribution fitting (Lauritzen et al. 2011) without GL: the sample grid reaches the
// view's borders, depth samples unproject onto the surface they came from, and directional
// light cameras fitted to samples cover every sample with a smaller map than the boxes give.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "shadow/ShadowMath.h"
#include "shadow/ViewSamples.h"

namespace gnomon {
namespace {

TEST(ViewSamples, GridKeepsTheOutputShapeUpToTheLimit) {
    EXPECT_EQ(shadow::sampleGridSize(1920, 1080, 256), glm::ivec2(256, 144));
    EXPECT_EQ(shadow::sampleGridSize(1080, 1920, 256), glm::ivec2(144, 256));
    EXPECT_EQ(shadow::sampleGridSize(100, 50, 256), glm::ivec2(100, 50));
    EXPECT_EQ(shadow::sampleGridSize(1, 1, 256), glm::ivec2(2, 2));
}

TEST(ViewSamples, GridScalePutsTheOuterPixelCentresOnTheBorders) {
    const glm::ivec2 grid(4, 8);
    const glm::mat4 s = shadow::sampleGridScale(grid);
    // The first pixel centre of an n-pixel viewport is at NDC 1/n - 1: the border maps there.
    const glm::vec4 corner = s * glm::vec4(-1.0f, 1.0f, 0.3f, 1.0f);
    EXPECT_FLOAT_EQ(corner.x, 1.0f / 4.0f - 1.0f);
    EXPECT_FLOAT_EQ(corner.y, 1.0f - 1.0f / 8.0f);
    EXPECT_FLOAT_EQ(corner.z, 0.3f);
}

Camera groundCamera() {
    Camera c;
    c.eye = {0.0f, 2.0f, 6.0f};
    c.centre = {0.0f, 0.0f, 0.0f};
    c.fovyDegrees = 60.0f;
    c.near = 0.1f;
    c.far = 100.0f;
    return c;
}

// The depth buffer of the ground plane y = 0 (|x|, |z| <= 10) seen by `camera` through the
// sample grid, as the view depth pass would draw it.
std::vector<float> groundDepth(const Camera& camera, glm::ivec2 grid, float aspect) {
    const glm::mat4 clip = shadow::sampleGridScale(grid) * shadow::clipFromView(camera, aspect) *
                           shadow::viewFromWorld(camera);
    const glm::mat4 worldFromClip = glm::inverse(clip);
    std::vector<float> depth(std::size_t(grid.x * grid.y), 1.0f);
    for (int y = 0; y < grid.y; ++y) {
        for (int x = 0; x < grid.x; ++x) {
            const glm::vec2 ndc((2.0f * x + 1.0f) / grid.x - 1.0f,
                                (2.0f * y + 1.0f) / grid.y - 1.0f);
            glm::vec4 a = worldFromClip * glm::vec4(ndc, -1.0f, 1.0f);
            glm::vec4 b = worldFromClip * glm::vec4(ndc, 1.0f, 1.0f);
            const glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
            if (!(p0.y > 0.0f && p1.y < 0.0f)) continue;  // the ray misses the ground
            const glm::vec3 hit = p0 + (p1 - p0) * (p0.y / (p0.y - p1.y));
            if (std::abs(hit.x) > 10.0f || std::abs(hit.z) > 10.0f) continue;
            const glm::vec4 c = clip * glm::vec4(hit, 1.0f);
            depth[std::size_t(y * grid.x + x)] = 0.5f * c.z / c.w + 0.5f;
        }
    }
    return depth;
}

TEST(ViewSamples, DepthSamplesLandOnTheSurfaceTheyCameFrom) {
    const Camera camera = groundCamera();
    const glm::ivec2 grid(64, 48);
    const float aspect = 4.0f / 3.0f;
    const std::vector<float> depth = groundDepth(camera, grid, aspect);
    shadow::ViewSamples samples;
    shadow::viewSamples(depth, grid, camera, aspect, samples);
    std::size_t covered = 0;
    for (float d : depth)
        covered += d < 1.0f ? 1u : 0u;
    ASSERT_GT(covered, 100u);
    ASSERT_EQ(samples.points.size(), covered);
    const glm::mat4 view = shadow::viewFromWorld(camera);
    for (const glm::vec4& p : samples.points) {
        EXPECT_NEAR(p.y, 0.0f, 2e-3f * p.w);
        EXPECT_NEAR(p.w, -(view * glm::vec4(glm::vec3(p), 1.0f)).z, 1e-3f * p.w);
        EXPECT_GE(p.w, samples.nearest);
        EXPECT_LE(p.w, samples.farthest);
    }
    // The bottom row looks at the ground just in front of the camera: the nearest sample is
    // where the view's lower border meets the ground.
    const float lowerBorder = std::atan(2.0f / 6.0f) + glm::radians(30.0f);
    const float nearestAlongRay = 2.0f / std::sin(lowerBorder);
    const float nearestDepth = nearestAlongRay * std::cos(lowerBorder - std::atan(2.0f / 6.0f));
    EXPECT_NEAR(samples.nearest, nearestDepth, 0.01f * nearestDepth);
    EXPECT_GT(samples.pad(samples.farthest), samples.pad(samples.nearest));
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
    const glm::ivec2 grid(64, 48);
    const float aspect = 4.0f / 3.0f;
    shadow::ViewSamples samples;
    shadow::viewSamples(groundDepth(camera, grid, aspect), grid, camera, aspect, samples);
    shadow::FitScene scene;
    scene.receivers = {Aabb{{-100.0f, 0.0f, -100.0f}, {100.0f, 0.0f, 100.0f}}};
    scene.casters = {scene.receivers[0], Aabb{{-0.2f, 0.0f, -0.2f}, {0.2f, 3.0f, 0.2f}}};
    scene.viewKnown = true;
    scene.viewClipFromWorld = shadow::clipFromView(camera, aspect) * shadow::viewFromWorld(camera);
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

TEST(ViewSamples, MapShareCountsTheSquaresTheSamplesLandOn) {
    // An orthographic map over x, y in [-1, 1] looking down -z; samples over its left half.
    shadow::LightCameraFrame frame;
    frame.kind = shadow::FrameKind::Orthographic;
    frame.orthographic = true;
    frame.clipFromLight = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.0f, 10.0f);
    frame.texelWorldSize = 2.0f / 256.0f;
    shadow::ViewSamples samples;
    samples.padConstant = 0.001f;
    for (int y = 0; y < 200; ++y) {
        for (int x = 0; x < 100; ++x)
            samples.points.emplace_back(-0.999f + 0.00998f * x, -0.999f + 0.00998f * y, -5.0f,
                                        float(x));
    }
    EXPECT_NEAR(shadow::mapShareUsed(samples, frame, 256, 0.0f, 1e9f, 64), 0.5f, 0.02f);
    // Only the samples of view depths 0..49: a quarter.
    EXPECT_NEAR(shadow::mapShareUsed(samples, frame, 256, 0.0f, 49.5f, 64), 0.25f, 0.02f);
    // Outside the map's depth range: nothing.
    for (glm::vec4& p : samples.points)
        p.z = 5.0f;
    EXPECT_EQ(shadow::mapShareUsed(samples, frame, 256, 0.0f, 1e9f, 64), 0.0f);
}

}  // namespace
}  // namespace gnomon
