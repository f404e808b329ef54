// Light frames fitted to what the view sees, without GL: point lights' frustums and cube
// faces, spots' windows, maps narrowed to where casters can shadow, and the share of a map
// the view's samples use. The scene is the ground with a post (ViewSamplesTestUtil.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "ViewSamplesTestUtil.h"
#include "shadow/ShadowMath.h"
#include "shadow/ViewSamples.h"

namespace gnomon {
namespace {

using test::groundCamera;
using test::groundWithPost;
using test::wideSpot;

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
