// Ray-traced ground truth and the score metrics (issue 4), without GL: the reference shadow
// of a plate over a floor is the analytically computed outline; soft references are 0 in the
// umbra, 1 outside and fractional across the penumbra; a perfect visibility buffer scores 0
// and each kind of error lands in its own counter; the distance transform is exact; blended
// casters transmit their colour under coloured shadows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "scene/MeshBuilder.h"
#include "truth/AlphaRays.h"
#include "truth/Metrics.h"
#include "truth/Reference.h"
#include "truth/ShadowRays.h"

namespace gnomon {
namespace {

constexpr int kSize = 64;

// A 2 x 2 plate (a thin box) 2 above a 20 x 20 floor; an orthographic camera looks straight
// down on x, z in [-4, 4] (up = -z, so image rows run along +z); the sun comes down at
// 45 degrees along +x, so the plate's shadow is the plate moved by its height (2) along +x.
Scene plateOverFloor() {
    Scene s;
    s.name = "plate";
    Material m;
    s.materials.push_back(m);
    s.meshes.push_back(mesh::box("floor", {0.0f, -0.05f, 0.0f}, {20.0f, 0.1f, 20.0f}));
    s.meshes.push_back(mesh::box("plate", {-1.0f, 2.0f, 0.0f}, {2.0f, 0.02f, 2.0f}));
    s.objects.push_back({"floor", 0, 0, glm::mat4(1.0f), {}, true, true});
    s.objects.push_back({"plate", 1, 0, glm::mat4(1.0f), {}, true, true});
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f));
    s.lights.push_back(sun);
    s.camera.projection = Projection::Orthographic;
    s.camera.eye = {0.0f, 10.0f, 0.0f};
    s.camera.centre = {0.0f, 0.0f, 0.0f};
    s.camera.up = {0.0f, 0.0f, -1.0f};
    s.camera.left = s.camera.bottom = -4.0f;
    s.camera.right = s.camera.top = 4.0f;
    s.camera.near = 1.0f;
    s.camera.far = 20.0f;
    s.options.width = s.options.height = kSize;
    return s;
}

// World x, z of a pixel centre.
glm::vec2 worldOf(int x, int y) {
    return {-4.0f + (float(x) + 0.5f) * 8.0f / kSize, -4.0f + (float(y) + 0.5f) * 8.0f / kSize};
}

TEST(Truth, HardShadowIsTheAnalyticOutline) {
    const Scene s = plateOverFloor();
    const truth::Reference r = truth::traceReference(s, s.options, {});
    ASSERT_EQ(r.width, kSize);
    int shadowed = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const glm::vec2 p = worldOf(x, y);
            const bool onPlate = p.x > -2.0f && p.x < 0.0f && std::fabs(p.y) < 1.0f;
            // The plate spans heights 1.99..2.01 and x -2..0: a ray at 45 degrees from floor
            // point x meets it when x - h lies in [-2, 0] for some h in [1.99, 2.01], i.e. x
            // in [-0.01, 2.01]. (No pixel centre lies within 0.05 of either end.)
            const bool inShadow = p.x > -0.01f && p.x < 2.01f && std::fabs(p.y) < 1.0f;
            const std::size_t pixel = std::size_t(y) * kSize + std::size_t(x);
            ASSERT_EQ(r.object[pixel], onPlate ? 1 : 0) << x << ", " << y;
            ASSERT_TRUE(r.applies[r.at(x, y, 0)]) << x << ", " << y;
            if (onPlate) continue;
            EXPECT_EQ(r.hard[r.at(x, y, 0)], inShadow ? 0.0f : 1.0f) << x << ", " << y;
            shadowed += inShadow;
        }
    }
    EXPECT_GT(shadowed, 200);
    // Pixel footprint: 8 units over 64 pixels.
    EXPECT_FLOAT_EQ(r.pixelWorld[0], 0.125f);
}

// Each pixel's view ray passes through its centre, as the raster samples, whatever the
// camera's near and far: glTF files give znear 0.05 and zfar 10^6 (assimp's 2CylinderEngine).
// The floor's points seen from 1 600 units away through a narrow view must lie on the exact
// rays, computed in double precision, to a hundredth of a pixel.
TEST(Truth, ViewRaysPassThroughPixelCentresWithExtremeNearAndFar) {
    Scene s = plateOverFloor();
    s.camera = Camera{};
    s.camera.eye = {800.0f, 600.0f, 1200.0f};
    s.camera.centre = {0.0f, 0.0f, 0.0f};
    s.camera.fovyDegrees = 0.6f;
    s.camera.near = 0.05f;
    s.camera.far = 1e6f;
    const truth::Reference r = truth::traceReference(s, s.options, {});
    const glm::dvec3 eye(s.camera.eye);
    const glm::dvec3 ahead = glm::normalize(-eye);
    const glm::dvec3 right = glm::normalize(glm::cross(ahead, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 up = glm::cross(right, ahead);
    const double tanHalf = std::tan(0.5 * glm::radians(double(s.camera.fovyDegrees)));
    const double pixel = 2.0 * tanHalf * glm::length(eye) / kSize;
    int floorPixels = 0;
    double worst = 0.0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const std::size_t p = std::size_t(y) * kSize + std::size_t(x);
            if (r.object[p] != 0 || r.surfaceNormal[p].y < 0.99f) continue;  // the top only
            const double nx = (x + 0.5) / kSize * 2.0 - 1.0, ny = 1.0 - (y + 0.5) / kSize * 2.0;
            const glm::dvec3 dir = ahead + right * (nx * tanHalf) + up * (ny * tanHalf);
            const glm::dvec3 expected = eye + dir * (-eye.y / dir.y);  // on the floor's top, y 0
            const glm::dvec3 got = glm::dvec3(r.surfacePoint[p]) + glm::dvec3(r.rays->origin());
            worst = std::max(worst, glm::length(got - expected));
            ++floorPixels;
        }
    }
    EXPECT_GT(floorPixels, kSize * kSize / 4);
    EXPECT_LT(worst, 0.01 * pixel) << "a pixel is " << pixel;
}

// With a contact range, the shadowed cells whose occluder lies within it along the shadow ray
// are marked, and the score counts the leak over them alone. The plate is 1.99 x sqrt(2) =
// 2.81 from the floor along the sun's 45-degree rays.
TEST(Truth, OccludersWithinTheContactRangeAreMarked) {
    const Scene s = plateOverFloor();
    EXPECT_TRUE(truth::traceReference(s, s.options, {}).nearOccluder.empty());
    truth::ReferenceOptions within;
    within.contactRange = 3.0f;
    const truth::Reference r = truth::traceReference(s, s.options, within);
    ASSERT_EQ(r.nearOccluder.size(), r.hard.size());
    long near = 0;
    for (std::size_t c = 0; c < r.hard.size(); ++c) {
        ASSERT_EQ(r.nearOccluder[c] != 0, r.applies[c] && r.hard[c] < 0.5f) << c;
        near += r.nearOccluder[c];
    }
    EXPECT_GT(near, 200);
    truth::ReferenceOptions short_;
    short_.contactRange = 2.5f;
    const truth::Reference farther = truth::traceReference(s, s.options, short_);
    for (std::uint8_t n : farther.nearOccluder)
        ASSERT_EQ(n, 0);

    std::vector<float> visibility = r.hard;
    auto column = [](float wx) { return int((wx + 4.0f) / 8.0f * kSize); };
    visibility[r.at(column(1.0f), 32, 0)] = 1.0f;  // two leaks in the plate's shadow
    visibility[r.at(column(1.0f), 33, 0)] = 1.0f;
    const std::vector<std::uint8_t> band(r.hard.size(), 0);
    const truth::Scores scores = truth::scoreVisibility(s, r, visibility, band, false);
    EXPECT_EQ(scores.overall.contactPixels, near);
    EXPECT_DOUBLE_EQ(scores.overall.contactLeak, 2.0 / double(near));
}

// Where the light reaches a surface, the reference keeps the cosine between its geometric
// normal and the light; a surface facing away from the light (its attached shadow, where no
// light applies) is marked with cosine 0, which the aliasing band reads as the terminator.
TEST(Truth, SurfacesFacingAwayFromTheLightAreMarked) {
    Scene s = plateOverFloor();
    const truth::Reference lit = truth::traceReference(s, s.options, {});
    const std::size_t floorPixel = lit.at(kSize - 2, kSize / 2, 0);  // world x ~ 3.9: the floor
    ASSERT_TRUE(lit.applies[floorPixel]);
    EXPECT_NEAR(lit.lightCosine[floorPixel], std::sqrt(0.5f), 1e-5f);
    s.lights[0].direction = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));  // from below
    const truth::Reference below = truth::traceReference(s, s.options, {});
    for (std::size_t c = 0; c < below.applies.size(); ++c) {
        ASSERT_FALSE(below.applies[c]) << c;
        ASSERT_EQ(below.lightCosine[c], 0.0f) << c;
    }
}

// A light that only grazes a surface (under 0.06 degrees, where the lookups call a plane
// edge-on) leaves it edge-on, in its own attached shadow, whichever side the rounding of the
// light's direction puts it on (cos 90 degrees is -4.4e-8 in float): here 1e-7 above the
// floor's plane, and 0.05 degrees above it. A light 0.1 degrees above it does light the
// floor.
TEST(Truth, SurfacesEdgeOnToTheLightAreMarked) {
    Scene s = plateOverFloor();
    for (const float grazing : {1e-7f, std::sin(glm::radians(0.05f))}) {
        s.lights[0].direction = -glm::vec3(std::sqrt(1.0f - grazing * grazing), grazing, 0.0f);
        const truth::Reference grazed = truth::traceReference(s, s.options, {});
        const std::size_t pixel = grazed.at(kSize - 2, kSize / 2, 0);
        EXPECT_FALSE(grazed.applies[pixel]) << grazing;
        EXPECT_EQ(grazed.lightCosine[pixel], 0.0f) << grazing;
    }
    const float tenth = glm::radians(0.1f);
    s.lights[0].direction = -glm::vec3(std::cos(tenth), std::sin(tenth), 0.0f);
    const truth::Reference low = truth::traceReference(s, s.options, {});
    const std::size_t floorPixel = low.at(kSize - 2, kSize / 2, 0);
    EXPECT_TRUE(low.applies[floorPixel]);
    EXPECT_NEAR(low.lightCosine[floorPixel], std::sin(tenth), 1e-6f);
}

TEST(Truth, SoftShadowIsFractionalOnlyAcrossThePenumbra) {
    Scene s = plateOverFloor();
    RenderOptions o = s.options;
    o.shadow.lightAngle = 5.0f;
    truth::ReferenceOptions ro;
    ro.softSamples = 256;
    const truth::Reference r = truth::traceReference(s, o, ro);
    // The penumbra along x around an edge at distance d (along the ray, 2 sqrt 2) spans
    // +-d tan(5 deg) across the ray, sqrt 2 times that on the floor: +-0.35.
    const int row = kSize / 2;
    for (int x = 0; x < kSize; ++x) {
        const glm::vec2 p = worldOf(x, row);
        if (p.x < 0.0f) continue;  // the plate
        const float v = r.soft[r.at(x, row, 0)];
        if (p.x > 0.4f && p.x < 1.6f) {
            EXPECT_EQ(v, 0.0f) << "umbra at x = " << p.x;
        }
        if (p.x > 2.4f) {
            EXPECT_EQ(v, 1.0f) << "lit at x = " << p.x;
        }
        if (std::fabs(p.x - 2.0f) < 0.1f) {
            EXPECT_GT(v, 0.25f) << "penumbra at x = " << p.x;
            EXPECT_LT(v, 0.75f) << "penumbra at x = " << p.x;
        }
    }
}

TEST(Truth, NonCastersAndNonReceivers) {
    Scene s = plateOverFloor();
    s.objects[1].castsShadows = false;
    truth::Reference r = truth::traceReference(s, s.options, {});
    for (float h : r.hard)
        EXPECT_EQ(h, 1.0f);
    s = plateOverFloor();
    s.objects[0].receivesShadows = false;
    r = truth::traceReference(s, s.options, {});
    EXPECT_FALSE(r.applies[r.at(50, 32, 0)]);  // floor pixel
    EXPECT_TRUE(r.applies[r.at(16, 32, 0)]);   // plate pixel
}

TEST(Truth, BlendedSurfacesTransmitTheirColour) {
    // The rule: the share 1 - alpha, filtered by the colour as strongly as it is opaque.
    EXPECT_EQ(truth::tintThrough({1, 1, 1}, 0.5f), glm::vec3(0.5f));
    EXPECT_EQ(truth::tintThrough({1, 0, 0}, 0.0f), glm::vec3(1.0f));
    EXPECT_EQ(truth::tintThrough({1, 0, 0}, 1.0f), glm::vec3(0.0f));
    const glm::vec3 red = truth::tintThrough({1, 0, 0}, 0.5f);
    EXPECT_FLOAT_EQ(red.r, 0.5f);
    EXPECT_FLOAT_EQ(red.g, 0.25f);
    EXPECT_FLOAT_EQ(red.b, 0.25f);

    // The plate blended red at alpha 0.5: under --blend-shadows coloured its shadow is red
    // light (hard 1, tint as above), under dithered half the light, untinted.
    Scene s = plateOverFloor();
    Material glass;
    glass.baseColour = {1.0f, 0.0f, 0.0f};
    glass.alpha = 0.5f;
    glass.alphaMode = AlphaMode::Blend;
    s.materials.push_back(glass);
    s.objects[1].material = 1;
    RenderOptions o = s.options;
    o.shadow.blendShadows = BlendShadows::Coloured;
    const truth::Reference r = truth::traceReference(s, o, {});
    ASSERT_EQ(r.tint.size(), r.hard.size());
    // Floor at x = 1 (under the plate's shadow: both faces of the thin box, so the light
    // passes two surfaces) and at x = -3 (open).
    const int under = 40, open = 8, row = 32;
    EXPECT_EQ(r.object[std::size_t(row) * kSize + under], 0);
    EXPECT_EQ(r.hard[r.at(under, row, 0)], 1.0f);
    const glm::vec3 twice = red * red;
    EXPECT_NEAR(r.tint[r.at(under, row, 0)].r, twice.r, 1e-6f);
    EXPECT_NEAR(r.tint[r.at(under, row, 0)].g, twice.g, 1e-6f);
    EXPECT_EQ(r.tint[r.at(open, row, 0)], glm::vec3(1.0f));
    o.shadow.blendShadows = BlendShadows::Dithered;
    const truth::Reference d = truth::traceReference(s, o, {});
    EXPECT_TRUE(d.tint.empty());
    EXPECT_NEAR(d.hard[d.at(under, row, 0)], 0.25f, 1e-6f);

    // Fully opaque, the blended plate blocks the light as an opaque one does.
    s.materials[1].alpha = 1.0f;
    o.shadow.blendShadows = BlendShadows::Coloured;
    const truth::Reference full = truth::traceReference(s, o, {});
    EXPECT_EQ(full.hard[full.at(under, row, 0)], 0.0f);
    EXPECT_EQ(full.tint[full.at(open, row, 0)], glm::vec3(1.0f));
}

TEST(Metrics, DistanceTransformIsExact) {
    const int w = 37, h = 23;
    std::mt19937 rng(5);
    std::vector<std::uint8_t> seeds(std::size_t(w * h), 0);
    for (int i = 0; i < 12; ++i)
        seeds[rng() % seeds.size()] = 1;
    const std::vector<float> d = truth::squaredDistance(seeds, w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            float best = 1e30f;
            for (int sy = 0; sy < h; ++sy)
                for (int sx = 0; sx < w; ++sx)
                    if (seeds[std::size_t(sy * w + sx)])
                        best = std::min(best, float((x - sx) * (x - sx) + (y - sy) * (y - sy)));
            ASSERT_EQ(d[std::size_t(y * w + x)], best) << x << ", " << y;
        }
    }
}

TEST(Metrics, PerfectVisibilityScoresZeroAndEachErrorCountsOnce) {
    const Scene s = plateOverFloor();
    const truth::Reference r = truth::traceReference(s, s.options, {});
    std::vector<float> visibility = r.hard;
    // One map texel = one pixel: the band is max(1 pixel, 2 texels) = 2 pixels.
    const std::vector<float> texel(r.hard.size(), 0.125f);
    const std::vector<std::uint8_t> band = truth::aliasingBand(r, texel, 2.0f, false);
    truth::Scores perfect = truth::scoreVisibility(s, r, visibility, band, false);
    ASSERT_EQ(perfect.lights.size(), 1u);
    EXPECT_EQ(perfect.overall.pixels, long(kSize * kSize));
    EXPECT_EQ(perfect.overall.misclassified, 0.0);
    EXPECT_EQ(perfect.overall.meanAbsError, 0.0);
    EXPECT_GT(perfect.overall.bandPixels, 0);

    // Acne far from any boundary (x = 3.5 on the lit floor), a leak in the middle of the
    // shadow (x = 1, outside the band), and a leak on the shadow's edge (inside the band).
    auto column = [](float wx) { return int((wx + 4.0f) / 8.0f * kSize); };
    visibility[r.at(column(3.5f), 50, 0)] = 0.0f;
    visibility[r.at(column(1.0f), 32, 0)] = 1.0f;
    visibility[r.at(column(1.9f), 32, 0)] = 1.0f;
    const truth::Scores one = truth::scoreVisibility(s, r, visibility, band, false);
    const double n = double(kSize * kSize);
    EXPECT_DOUBLE_EQ(one.overall.falseShadow, 1.0 / n);
    EXPECT_DOUBLE_EQ(one.overall.falseShadowOutsideBand, 1.0 / n);
    EXPECT_DOUBLE_EQ(one.overall.leak, 2.0 / n);
    EXPECT_DOUBLE_EQ(one.overall.leakOutsideBand, 1.0 / n);
    EXPECT_DOUBLE_EQ(one.overall.misclassified, 3.0 / n);
    EXPECT_DOUBLE_EQ(one.overall.meanAbsError, 3.0 / n);
}

// A strip `width` x 4 pixels of one light, lit everywhere, each pixel a map texel wide (0.01),
// its receiver at `cosine` to the light.
truth::Reference litStrip(int width, float cosine) {
    truth::Reference r;
    r.width = width;
    r.height = 4;
    r.lights = 1;
    const std::size_t n = std::size_t(r.width * r.height);
    r.object.assign(n, 0);
    r.pixelWorld.assign(n, 0.01f);
    r.applies.assign(n, 1);
    r.hard.assign(n, 1.0f);
    r.lightCosine.assign(n, cosine);
    return r;
}

// A shadow edge down the middle of a strip whose pixels are one map texel each: the band
// reaches 2 texels from the edge on a receiver facing the light, 2 / cos(theta) on one
// tilted by theta, and no more than kBandMaxStretch times 2 however grazing.
TEST(Metrics, AliasingBandStretchesOnReceiversTiltedToTheLight) {
    auto bandWidth = [](float cosine) {
        truth::Reference r = litStrip(64, cosine);
        const std::size_t n = r.hard.size();
        for (int y = 0; y < r.height; ++y)
            for (int x = 0; x < 32; ++x)
                r.hard[r.at(x, y, 0)] = 0.0f;
        const std::vector<float> texel(n, 0.01f);
        const std::vector<std::uint8_t> band = truth::aliasingBand(r, texel, 2.0f, false);
        int inBand = 0;
        for (int x = 0; x < r.width; ++x)
            inBand += band[r.at(x, 1, 0)];
        return inBand;
    };
    // The edge's seeds are pixels 31 and 32; the band holds those within the radius of one.
    EXPECT_EQ(bandWidth(1.0f), 2 + 2 * 2);
    EXPECT_EQ(bandWidth(0.5f), 2 + 2 * 4);
    EXPECT_EQ(bandWidth(0.05f), 2 + 2 * int(2.0f * truth::kBandMaxStretch));
}

// The terminator is a shadow edge: a lit strip whose right half faces away from the light
// (no light applies there) has a band along the turn, as an occluded right half would; a
// right half with no surface at all (the background) has none.
TEST(Metrics, AliasingBandFollowsTheTerminator) {
    auto bandAt = [](float rightCosine) {
        truth::Reference r = litStrip(16, 1.0f);
        const std::size_t n = r.hard.size();
        for (int y = 0; y < r.height; ++y)
            for (int x = 8; x < r.width; ++x) {
                r.applies[r.at(x, y, 0)] = 0;
                r.lightCosine[r.at(x, y, 0)] = rightCosine;
            }
        const std::vector<float> texel(n, 0.01f);
        const std::vector<std::uint8_t> band = truth::aliasingBand(r, texel, 2.0f, false);
        std::vector<int> row;
        for (int x = 0; x < 8; ++x)
            row.push_back(band[r.at(x, 1, 0)]);
        return row;
    };
    // Faces away (cosine 0): the seed is pixel 7, and pixels within 2 of it are in the band.
    EXPECT_EQ(bandAt(0.0f), (std::vector<int>{0, 0, 0, 0, 0, 1, 1, 1}));
    // No surface there (cosine left at its default): no edge, no band.
    EXPECT_EQ(bandAt(1.0f), (std::vector<int>{0, 0, 0, 0, 0, 0, 0, 0}));
}

// The band along the surface: with every floor pixel of the plate scene wrong and no band
// from the screen, the floor's pixels within the band's reach (2 texels of 0.1 stretched by
// 1 / cos 45 degrees: 0.28) of a reference shadow boundary join the band, and no others. The
// boundary at x = -0.01 lies under the plate, out of the camera's sight; it is found too.
TEST(Metrics, BandExtendsToBoundariesAlongTheSurface) {
    const Scene s = plateOverFloor();
    const truth::Reference r = truth::traceReference(s, s.options, {});
    ASSERT_TRUE(r.rays);
    std::vector<float> visibility(r.hard.size());
    for (std::size_t c = 0; c < r.hard.size(); ++c)
        visibility[c] = 1.0f - r.hard[c];
    const std::vector<float> texel(r.hard.size(), 0.1f);
    std::vector<std::uint8_t> band(r.hard.size(), 0);
    truth::extendBandAlongSurfaces(s, r, visibility, texel, 2.0f, band);
    int checked = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const glm::vec2 p = worldOf(x, y);
            const std::size_t pixel = std::size_t(y) * kSize + std::size_t(x);
            if (r.object[pixel] != 0 || std::fabs(p.y) > 0.6f) continue;  // the floor, |z| < 0.6
            const float toEdge = std::min(std::fabs(p.x + 0.01f), std::fabs(p.x - 2.01f));
            if (toEdge < 0.25f) {
                EXPECT_TRUE(band[r.at(x, y, 0)]) << x << ", " << y;
            } else if (toEdge > 0.32f) {
                EXPECT_FALSE(band[r.at(x, y, 0)]) << x << ", " << y;
            }
            ++checked;
        }
    }
    EXPECT_GT(checked, 400);
    // Right where the render is right: nothing to excuse, nothing added.
    std::vector<std::uint8_t> none(r.hard.size(), 0);
    truth::extendBandAlongSurfaces(s, r, r.hard, texel, 2.0f, none);
    EXPECT_EQ(std::count(none.begin(), none.end(), 1), 0);
}

// The transmitted light's error counts every pair either side tints; its colour alone only
// the pairs where both let light past the opaque casters. On a lit strip of four pixels
// tinted (0.5, 0.5, 0.5) by the reference: the renderer's tint off by 0.1 where both pass
// light, and lit with the right tint where the reference is shadowed (an opaque shadow's
// edge, which misclassification counts already).
TEST(Metrics, TheTintsColourIsScoredWhereBothPassLight) {
    truth::Reference r;
    r.width = 4;
    r.height = 1;
    r.lights = 1;
    r.applies.assign(4, 1);
    r.hard = {1.0f, 1.0f, 0.0f, 1.0f};
    r.tint.assign(4, glm::vec3(0.5f));
    r.tint[3] = glm::vec3(1.0f);  // untinted on both sides: not scored
    const std::vector<float> visibility = {1.0f, 1.0f, 1.0f, 1.0f};
    std::vector<float> tint = {0.6f, 0.6f, 0.6f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 1, 1, 1};
    const std::vector<std::uint8_t> band(4, 0);
    const TintScore t = truth::scoreTint(r, visibility, tint, band, false);
    EXPECT_EQ(t.cells, 3);
    EXPECT_NEAR(t.meanError, (0.1 + 0.0 + 0.5) / 3.0, 1e-6);
    EXPECT_EQ(t.cellsBothLit, 2);
    EXPECT_NEAR(t.meanColourError, (0.1 + 0.0) / 2.0, 1e-6);
}

}  // namespace
}  // namespace gnomon
