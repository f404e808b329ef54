// Sample distribution fitting (Lauritzen et al. 2011) without GL: the reduced grid keeps
// each block's nearest and farthest depth, samples unproject onto the surface they came from, and
// directional light cameras fitted to samples cover every sample with a smaller map than the boxes
// give.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "shadow/ShadowMath.h"
#include "shadow/ViewSamples.h"

namespace gnomon {
namespace {

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

Camera groundCamera() {
    Camera c;
    c.eye = {0.0f, 2.0f, 6.0f};
    c.centre = {0.0f, 0.0f, 0.0f};
    c.fovyDegrees = 60.0f;
    c.near = 0.1f;
    c.far = 100.0f;
    return c;
}

// The depth buffer of the ground plane y = 0 (|x|, |z| <= 10) seen by `camera` at `size`,
// reduced to (nearest, farthest) per block as the view depth pass's reduction does.
std::vector<glm::vec2> groundRanges(const Camera& camera, const shadow::SampleGrid& grid,
                                    float aspect) {
    const glm::mat4 clip = shadow::clipFromView(camera, aspect) * shadow::viewFromWorld(camera);
    const glm::mat4 worldFromClip = glm::inverse(clip);
    std::vector<glm::vec2> ranges(std::size_t(grid.cells.x * grid.cells.y), glm::vec2(1.0f, 0.0f));
    for (int y = 0; y < grid.size.y; ++y) {
        for (int x = 0; x < grid.size.x; ++x) {
            const glm::vec2 ndc((2.0f * x + 1.0f) / grid.size.x - 1.0f,
                                (2.0f * y + 1.0f) / grid.size.y - 1.0f);
            glm::vec4 a = worldFromClip * glm::vec4(ndc, -1.0f, 1.0f);
            glm::vec4 b = worldFromClip * glm::vec4(ndc, 1.0f, 1.0f);
            const glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
            if (!(p0.y > 0.0f && p1.y < 0.0f)) continue;  // the ray misses the ground
            const glm::vec3 hit = p0 + (p1 - p0) * (p0.y / (p0.y - p1.y));
            if (std::abs(hit.x) > 10.0f || std::abs(hit.z) > 10.0f) continue;
            const glm::vec4 c = clip * glm::vec4(hit, 1.0f);
            const float d = 0.5f * c.z / c.w + 0.5f;
            glm::vec2& r = ranges[std::size_t((y / grid.block) * grid.cells.x + x / grid.block)];
            r = glm::vec2(std::min(r.x, d), std::max(r.y, d));
        }
    }
    for (glm::vec2& r : ranges) {
        if (r.x >= 1.0f) r = glm::vec2(1.0f);
    }
    return ranges;
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
    const glm::mat4 view = shadow::viewFromWorld(camera);
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
    const shadow::SampleGrid grid = shadow::sampleGrid(128, 96, 64);
    const float aspect = 4.0f / 3.0f;
    shadow::ViewSamples samples;
    shadow::viewSamples(groundRanges(camera, grid, aspect), grid, camera, aspect, samples);
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

// The ground (|x|, |z| <= 10) with a post on it, seen by `camera` at 128 x 96 reduced to
// 64-cell rows: `samples` filled from its depth, the fit scene pointing at them.
shadow::FitScene groundWithPost(const Camera& camera, shadow::ViewSamples& samples) {
    const shadow::SampleGrid grid = shadow::sampleGrid(128, 96, 64);
    const float aspect = 4.0f / 3.0f;
    shadow::viewSamples(groundRanges(camera, grid, aspect), grid, camera, aspect, samples);
    shadow::FitScene scene;
    scene.receivers = {Aabb{{-10.0f, 0.0f, -10.0f}, {10.0f, 0.0f, 10.0f}}};
    scene.casters = {scene.receivers[0], Aabb{{-0.2f, 0.0f, -0.2f}, {0.2f, 3.0f, 0.2f}}};
    scene.viewKnown = true;
    scene.viewClipFromWorld = shadow::clipFromView(camera, aspect) * shadow::viewFromWorld(camera);
    scene.samples = &samples;
    return scene;
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

// A wide spot straight above the ground's centre, its cone reaching far past what the ground
// camera sees.
Light wideSpot() {
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0.0f, 10.0f, 0.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.outerConeDegrees = 70.0f;
    return spot;
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

// Frames that follow one another (the viewer, a scored path): a point light's frustum and a
// spot's window are held while they still hold what the view sees, so a camera moving a
// little leaves the map, texel grid and all, exactly as it was.
TEST(ViewSamples, HeldFrustumsStayPutWhileTheCameraMovesALittle) {
    Light lamp;
    lamp.type = LightType::Point;
    lamp.position = {1.0f, 40.0f, 2.0f};
    for (const Light& light : {lamp, wideSpot()}) {
        shadow::HeldExtent held;
        Camera camera = groundCamera();
        shadow::ViewSamples samples;
        const shadow::FitScene first = groundWithPost(camera, samples);
        const shadow::LightCameraFrame a =
            shadow::lightCameraFrame(light, camera, first, 1024, &held);
        ASSERT_TRUE(a.valid && held.valid);
        camera.eye += glm::vec3(0.02f, 0.0f, -0.05f);  // a step of a dolly
        shadow::ViewSamples moved;
        const shadow::FitScene second = groundWithPost(camera, moved);
        const shadow::LightCameraFrame b =
            shadow::lightCameraFrame(light, camera, second, 1024, &held);
        ASSERT_TRUE(b.valid);
        EXPECT_EQ(a.clipFromWorld(), b.clipFromWorld()) << int(light.type);
        // Without the held extent the same step refits: the mean direction (point) or the
        // window (spot) moves with the view.
        EXPECT_NE(shadow::lightCameraFrame(light, camera, second, 1024, nullptr).clipFromWorld(),
                  a.clipFromWorld());
    }
}

// The cube face (0..5: +X, -X, +Y, -Y, +Z, -Z) a direction from the light leaves through.
int cubeFaceOf(const glm::vec3& d) {
    const glm::vec3 a = glm::abs(d);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    return 2 * axis + (d[axis] < 0.0f ? 1 : 0);
}

// A lamp low over the ground, which the view sees all around it: a cube. Each face the view
// looks up, as a map of its own, holds every sample whose direction from the lamp leaves
// through that face, within its clip volume; a face the view sees whole is no coarser than
// the cube's (but for the margin its rim reads past), and the downward face, which the view
// sees part of, is finer.
TEST(ViewSamples, PointLightFacesHoldTheirSamples) {
    Light lamp;
    lamp.type = LightType::Point;
    lamp.position = {0.5f, 1.5f, 4.5f};  // its downward face partly behind the camera
    const Camera camera = groundCamera();
    shadow::ViewSamples samples;
    const shadow::FitScene scene = groundWithPost(camera, samples);
    ShadowOptions options;
    const int size = 1024;
    const shadow::LightCameraFrame cube = shadow::lightCameraFrame(lamp, camera, scene, size);
    ASSERT_EQ(cube.kind, shadow::FrameKind::Cube);
    float finest = 1e9f;
    for (int face = 0; face < 6; ++face) {
        const shadow::LightCameraFrame f = shadow::pointFaceFrame(lamp, face, options, scene, size);
        int held = 0;
        for (const glm::vec4& p : samples.points) {
            if (cubeFaceOf(glm::vec3(p) - lamp.position) != face) continue;
            ASSERT_TRUE(f.valid) << "face " << face;
            ++held;
            const glm::vec4 c = f.clipFromWorld() * glm::vec4(glm::vec3(p), 1.0f);
            EXPECT_GT(c.w, 0.0f);
            EXPECT_LE(std::abs(c.x), c.w) << "face " << face;
            EXPECT_LE(std::abs(c.y), c.w) << "face " << face;
            // A sample stands for the surface within its pad (here up to a cell below it).
            EXPECT_LE(c.w, f.far + samples.pad(p.w)) << "beyond far, face " << face;
        }
        if (!held) continue;
        EXPECT_EQ(f.kind, shadow::FrameKind::Perspective);
        EXPECT_LE(f.texelWorldSize, 1.05f * cube.texelWorldSize) << "face " << face;
        finest = std::min(finest, f.texelWorldSize);
    }
    EXPECT_LT(finest, 0.9f * cube.texelWorldSize);
}

// Whether the segment from `a` to `b` passes through `box` (slabs).
bool segmentCrosses(const glm::vec3& a, const glm::vec3& b, const Aabb& box) {
    float from = 0.0f, to = 1.0f;
    for (int k = 0; k < 3; ++k) {
        const float d = b[k] - a[k];
        if (std::abs(d) < 1e-9f) {
            if (a[k] < box.min[k] || a[k] > box.max[k]) return false;
            continue;
        }
        float t0 = (box.min[k] - a[k]) / d, t1 = (box.max[k] - a[k]) / d;
        if (t0 > t1) std::swap(t0, t1);
        from = std::max(from, t0);
        to = std::min(to, t1);
    }
    return from <= to;
}

// Over a ground that casts nothing (a receiver only), a light's map need only hold what the
// post can shadow: a point seen from the light beside every caster is lit, as a lookup
// outside the map reads it. The lamp's face towards the post maps a window around the post,
// several times finer than over all it sees; its downward face, with no caster between it
// and the ground it sees, gets no map; every sample whose way to the lamp crosses the post
// lies in the map of the face it leaves through. A spot over the ground narrows the same way.
TEST(ViewSamples, MapsNarrowToWhereCastersCanShadow) {
    const Camera camera = groundCamera();
    shadow::ViewSamples samples;
    shadow::FitScene scene = groundWithPost(camera, samples);
    const Aabb post = scene.casters[1];
    shadow::FitScene postOnly = scene;
    postOnly.casters = {post};
    Light lamp;
    lamp.type = LightType::Point;
    lamp.position = {0.5f, 1.5f, 4.5f};
    ShadowOptions options;
    const int size = 1024;
    int crossing = 0;
    for (int face = 0; face < 6; ++face) {
        const shadow::LightCameraFrame all =
            shadow::pointFaceFrame(lamp, face, options, scene, size);
        const shadow::LightCameraFrame narrow =
            shadow::pointFaceFrame(lamp, face, options, postOnly, size);
        if (face == 5) {  // -Z, towards the post
            ASSERT_TRUE(all.valid && narrow.valid);
            EXPECT_LT(narrow.texelWorldSize, 0.5f * all.texelWorldSize);
        }
        if (face == 3) {  // -Y: the ground around the lamp, nothing above it
            EXPECT_TRUE(all.valid);
            EXPECT_FALSE(narrow.valid);
        }
        for (const glm::vec4& p : samples.points) {
            if (cubeFaceOf(glm::vec3(p) - lamp.position) != face) continue;
            if (!segmentCrosses(glm::vec3(p), lamp.position, post)) continue;
            ++crossing;
            ASSERT_TRUE(narrow.valid) << "face " << face;
            const glm::vec4 c = narrow.clipFromWorld() * glm::vec4(glm::vec3(p), 1.0f);
            EXPECT_LE(std::abs(c.x), c.w) << "face " << face;
            EXPECT_LE(std::abs(c.y), c.w) << "face " << face;
        }
    }
    EXPECT_GT(crossing, 20);  // the post's shadow is in view
    const Light spot = wideSpot();
    const shadow::LightCameraFrame wide = shadow::lightCameraFrame(spot, camera, scene, size);
    const shadow::LightCameraFrame narrow = shadow::lightCameraFrame(spot, camera, postOnly, size);
    ASSERT_TRUE(wide.valid && narrow.valid);
    EXPECT_LT(narrow.texelWorldSize, 0.5f * wide.texelWorldSize);
    // With its one caster in the cone but behind the camera (its shadow falls further away),
    // the spot can shadow nothing the view sees: no map, where the whole cone was mapped.
    shadow::FitScene farCaster = postOnly;
    farCaster.casters = {Aabb{{-9.5f, 0.0f, 8.0f}, {-9.0f, 0.5f, 9.0f}}};
    EXPECT_FALSE(shadow::lightCameraFrame(spot, camera, farCaster, size).valid);
}

TEST(ViewSamples, WindowHoldsEverySampleWithItsPad) {
    shadow::ViewSamples samples;
    samples.points = {{1.0f, 0.0f, -2.0f, 1.0f}, {-1.0f, 0.5f, -4.0f, 1.0f}};
    samples.padConstant = 0.1f;
    glm::vec3 axis(0.0f);
    ASSERT_TRUE(shadow::samplesDirection(samples, glm::vec3(0.0f), axis));
    EXPECT_LT(axis.z, -0.9f);
    shadow::SampleWindow w;
    ASSERT_TRUE(shadow::samplesWindow(samples, glm::mat4(1.0f), w));
    // Each padded sample's corners project inside the window (the bound is exact at the
    // nearest corners: up to float rounding).
    const float e = 1e-6f;
    for (const glm::vec4& p : samples.points) {
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 q =
                glm::vec3(p) +
                0.1f * glm::vec3(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
            const glm::vec2 t = glm::vec2(q) / -q.z;
            EXPECT_GE(t.x, w.lo.x - e);
            EXPECT_LE(t.x, w.hi.x + e);
            EXPECT_GE(t.y, w.lo.y - e);
            EXPECT_LE(t.y, w.hi.y + e);
        }
    }
    EXPECT_FLOAT_EQ(w.farthest, 4.1f);
    // Within a limit (a spot's cone) that only the first sample's footprint overlaps: the
    // second is left out, and the window is clipped to the limit.
    const shadow::SampleWindow limit{{0.45f, -1.0f}, {1.0f, 1.0f}, 0.0f};
    ASSERT_TRUE(shadow::samplesWindow(samples, glm::mat4(1.0f), w, &limit));
    EXPECT_FLOAT_EQ(w.lo.x, 0.45f);
    EXPECT_NEAR(w.hi.x, 0.5f + 0.15f / 1.9f, 1e-6f);
    EXPECT_FLOAT_EQ(w.farthest, 2.1f);
    const shadow::SampleWindow elsewhere{{2.0f, 2.0f}, {3.0f, 3.0f}, 0.0f};
    EXPECT_FALSE(shadow::samplesWindow(samples, glm::mat4(1.0f), w, &elsewhere));
    // A sample within its pad of the camera's plane: no window.
    samples.points.emplace_back(2.0f, 0.0f, -0.05f, 1.0f);
    EXPECT_FALSE(shadow::samplesWindow(samples, glm::mat4(1.0f), w));
    // Unless a limit leaves it out: beside a point light's face (|x| <= |z|, widened a
    // little), the sample near the plane belongs to another face and this one still fits.
    const shadow::SampleWindow face{glm::vec2(-1.05f), glm::vec2(1.05f), 0.0f};
    ASSERT_TRUE(shadow::samplesWindow(samples, glm::mat4(1.0f), w, &face));
    EXPECT_FLOAT_EQ(w.farthest, 4.1f);
    EXPECT_LT(w.hi.x, 1.0f);
    // Near the plane and within the face's sides (its pad reaches into the face): no window.
    samples.points.back() = {0.02f, 0.0f, -0.05f, 1.0f};
    EXPECT_FALSE(shadow::samplesWindow(samples, glm::mat4(1.0f), w, &face));
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
