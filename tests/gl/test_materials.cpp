// Real materials (issue: real scenes): base colour textures and their transforms in the main
// pass, alpha-masked casters cutting holes in their shadows, blended casters following
// --blend-shadows, and the ray-traced reference agreeing with all of it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "GlTest.h"
#include "scene/MeshBuilder.h"

namespace gnomon::test {
namespace {

constexpr int kSize = 256;
constexpr float kHalfView = 5.0f;  // the orthographic camera sees x, z in [-5, 5]

int column(float x) {
    return int((x + kHalfView) / (2.0f * kHalfView) * float(kSize));
}
constexpr int kMiddleRow = kSize / 2;  // z = 0

// A plate at height 2 over x in [-3, 3], z in [-2, 2], textured with two texels: the left
// one (u < 0.5) opaque red, the right one (u > 0.5) transparent green. A sun at 45 degrees
// shifts its shadow 2 units along +x: the left half shadows x in [-1, 2], the right half
// would shadow x in [2, 5]. The camera looks straight down.
Scene texturedPlate(AlphaMode mode, float alpha = 1.0f, bool textured = true) {
    Scene s;
    s.name = "textured plate";
    Material floor;
    floor.baseColour = glm::vec3(0.8f);
    floor.specular = 0.0f;
    s.materials.push_back(floor);
    Material plate;
    plate.baseColour = glm::vec3(1.0f);
    plate.specular = 0.0f;
    plate.doubleSided = true;
    plate.alphaMode = mode;
    plate.alpha = alpha;
    if (textured) {
        Texture t;
        t.name = "red | clear green";
        t.width = 2;
        t.height = 1;
        t.rgba = {255, 0, 0, 255, 0, 255, 0, 0};
        t.nearest = true;
        t.wrapS = t.wrapT = TextureWrap::Repeat;
        s.textures.push_back(t);
        plate.baseColourTexture = 0;
    }
    s.materials.push_back(plate);
    s.meshes.push_back(mesh::box("floor", {0.0f, -0.05f, 0.0f}, {12.0f, 0.1f, 12.0f}));
    Mesh m;
    m.name = "plate";
    m.positions = {{-3, 2, -2}, {-3, 2, 2}, {3, 2, 2}, {3, 2, -2}};
    m.normals.assign(4, glm::vec3(0, 1, 0));
    m.uvs = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    m.indices = {0, 1, 2, 0, 2, 3};
    s.meshes.push_back(m);
    s.objects.push_back({"floor", 0, 0, glm::mat4(1.0f), {}, true, true});
    s.objects.push_back({"plate", 1, 1, glm::mat4(1.0f), {}, true, true});
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f));
    sun.shadowMapSize = 1024;
    s.lights.push_back(sun);
    s.camera = lookingStraightDown(kHalfView);
    s.ambient = glm::vec3(0.05f);
    s.options.width = s.options.height = kSize;
    return s;
}

int lum(const Image& image, float x) {
    return luminance(image.at(column(x), kMiddleRow));
}

// Mean luminance over the floor patch x in [x0, x1], z in [-1, 1].
double patch(const Image& image, float x0, float x1) {
    double sum = 0.0;
    int n = 0;
    for (int y = kMiddleRow - kSize / 10; y <= kMiddleRow + kSize / 10; ++y) {
        for (int x = column(x0); x <= column(x1); ++x, ++n)
            sum += luminance(image.at(x, y));
    }
    return sum / n;
}

TEST(Materials, BaseColourTextureShowsInTheMainPass) {
    const Scene s = texturedPlate(AlphaMode::Mask);
    const Image image = sharedRenderer().render(s, s.options);
    const std::uint8_t* red = image.at(column(-1.5f), kMiddleRow);
    EXPECT_GT(red[0], 150) << "the plate's left half shows its red texel";
    EXPECT_LT(red[1], 20);
    EXPECT_LT(red[2], 20);
}

TEST(Materials, MaskedCasterCutsHolesInItsShadow) {
    const Scene s = texturedPlate(AlphaMode::Mask);
    const Image image = sharedRenderer().render(s, s.options);
    writePng(outputDir() + "/materials_mask.png", image);
    const int lit = lum(image, -4.5f);  // open floor left of everything
    EXPECT_LT(lum(image, 1.0f), lit / 3) << "under the opaque half: shadow";
    EXPECT_GT(lum(image, 3.5f), lit * 9 / 10) << "under the cut-away half: lit";
    EXPECT_GT(lum(image, 1.5f), 0);
    // The same plate drawn opaque shadows both halves: the test can tell them apart.
    const Scene opaque = texturedPlate(AlphaMode::Opaque);
    const Image all = sharedRenderer().render(opaque, opaque.options);
    EXPECT_LT(lum(all, 3.5f), lit / 3);
}

TEST(Materials, MaskedCastersCutHolesInEveryKindOfMap) {
    // The alpha-tested depth programs: 2D maps of colour and native formats, and cubes.
    for (bool point : {false, true}) {
        for (DepthFormat f : {DepthFormat::R8, DepthFormat::Depth16, DepthFormat::Depth32F}) {
            Scene s = texturedPlate(AlphaMode::Mask);
            if (point) {
                // From (-6, 8, 0) the left half shadows x in [-2, 2], the right [2, 6].
                s.lights[0].type = LightType::Point;
                s.lights[0].position = {-6.0f, 8.0f, 0.0f};
            }
            RenderOptions o = s.options;
            o.shadow.depthFormat = f;
            const Image image = sharedRenderer().render(s, o);
            o.shadow.enabled = false;
            const Image unshadowed = sharedRenderer().render(s, o);
            SCOPED_TRACE(std::string(point ? "point light, " : "sun, ") + toString(f));
            EXPECT_LT(lum(image, 1.0f), lum(unshadowed, 1.0f) / 2) << "under the opaque half";
            EXPECT_GT(lum(image, 3.5f), lum(unshadowed, 3.5f) * 9 / 10) << "under the cut half";
        }
    }
}

TEST(Materials, TextureTransformMovesTheCut) {
    Scene s = texturedPlate(AlphaMode::Mask);
    // KHR_texture_transform offset (0.5, 0): the left half now reads the clear texel.
    s.materials[1].uvTransform = glm::mat3(1, 0, 0, 0, 1, 0, 0.5f, 0, 1);
    const Image image = sharedRenderer().render(s, s.options);
    const int lit = lum(image, -4.5f);
    EXPECT_LT(image.at(column(-1.5f), kMiddleRow)[0], 230) << "left half cut away: floor";
    EXPECT_GT(image.at(column(1.5f), kMiddleRow)[0], 150) << "right half: red";
    EXPECT_GT(lum(image, -0.5f), lit * 9 / 10) << "the left half casts nothing";
    EXPECT_LT(lum(image, 3.5f), lit / 3) << "the right half casts";
}

TEST(Materials, BlendedCastersFollowTheBlendShadowRule) {
    const Scene s = texturedPlate(AlphaMode::Blend, 0.5f, false);
    RenderOptions o = s.options;
    o.shadow.shadowRays = ShadowRayMode::Off;  // a ray meets the dithered plate whole
    o.shadow.blendShadows = BlendShadows::None;
    const double none = patch(sharedRenderer().render(s, o), 3.4f, 4.6f);
    o.shadow.blendShadows = BlendShadows::Opaque;
    const double full = patch(sharedRenderer().render(s, o), 3.4f, 4.6f);
    o.shadow.blendShadows = BlendShadows::Dithered;
    const Image dithered = sharedRenderer().render(s, o);
    writePng(outputDir() + "/materials_dithered.png", dithered);
    const double half = patch(dithered, 3.4f, 4.6f);
    std::printf("blend shadows at alpha 0.5: none %.1f, dithered %.1f, opaque %.1f\n", none, half,
                full);
    EXPECT_GT(none, 2.0 * full);
    const double t = (half - full) / (none - full);
    EXPECT_GT(t, 0.3) << "dithered: about half the light passes";
    EXPECT_LT(t, 0.7);
}

TEST(Materials, BlendedSurfaceIsSeenThrough) {
    const Scene s = texturedPlate(AlphaMode::Blend, 0.5f, false);
    RenderOptions o = s.options;
    o.shadow.enabled = false;
    const Image image = sharedRenderer().render(s, o);
    Scene hidden = s;
    hidden.objects.pop_back();
    const Image floorOnly = sharedRenderer().render(hidden, o);
    // Half the plate (white, lit) over half the floor (grey, lit): brighter than the floor
    // alone, and not the plate alone.
    const int mixed = lum(image, -1.5f), floor = lum(floorOnly, -1.5f);
    EXPECT_GT(mixed, floor);
    EXPECT_LT(mixed, 3 * 255 - 10);
    // Exactly the alpha-weighted mix of the plate drawn opaque and the floor alone (8-bit
    // rounding of three channels aside).
    Scene opaque = s;
    opaque.materials[1].alphaMode = AlphaMode::Opaque;
    const int plate = lum(sharedRenderer().render(opaque, o), -1.5f);
    EXPECT_NEAR(mixed, 0.5 * plate + 0.5 * floor, 4.0);
}

TEST(Materials, ReferenceAgreesWithMaskedAndDitheredShadows) {
    const Scene mask = texturedPlate(AlphaMode::Mask);
    RenderOptions o = mask.options;
    o.width = o.height = 128;
    ScoreOptions so;
    so.softSamples = 1;  // scored against the hard reference (the filter is not pcss)
    const ScoreResult m = score(sharedRenderer(), mask, o, so);
    std::printf("masked plate: %.4f%% misclassified, %.4f%% outside the band\n",
                100.0 * m.overall.misclassified,
                100.0 * (m.overall.falseShadowOutsideBand + m.overall.leakOutsideBand));
    EXPECT_LT(m.overall.falseShadowOutsideBand + m.overall.leakOutsideBand, 0.002);
    // Scored as if opaque, the cut-away half's missing shadow would be a leak: it is not.
    EXPECT_LT(m.overall.leak, 0.01);

    const Scene blend = texturedPlate(AlphaMode::Blend, 0.3f, false);
    o.shadow.blendShadows = BlendShadows::Dithered;
    const ScoreResult b = score(sharedRenderer(), blend, o, so);
    std::printf("dithered plate at alpha 0.3: mean |error| %.4f\n", b.overall.meanAbsError);
    EXPECT_LT(b.overall.meanAbsError, 0.08);
}

// Shadow rays meet masked and blended casters as the maps and the reference do: the masked
// plate's clear texel lets the ray through, a texture transform moves the cut, and a blended
// plate blocks by its rule (whole under opaque; under coloured where a texel is opaque; under
// dithered from alpha one half; never under none).
TEST(Materials, ShadowRaysKeepTheCutOuts) {
    auto rays = [](const Scene& s, BlendShadows blend = BlendShadows::Coloured) {
        RenderOptions o = s.options;
        o.shadow.shadowRays = ShadowRayMode::All;
        o.shadow.blendShadows = blend;
        return sharedRenderer().render(s, o);
    };
    Scene s = texturedPlate(AlphaMode::Mask);
    Image image = rays(s);
    const int lit = lum(image, -4.5f);
    EXPECT_LT(lum(image, 1.0f), lit / 3) << "under the opaque half: shadow";
    EXPECT_GT(lum(image, 3.5f), lit * 9 / 10) << "under the cut-away half: lit";
    s.materials[1].uvTransform = glm::mat3(1, 0, 0, 0, 1, 0, 0.5f, 0, 1);
    s.revision.bump();  // an edit of a scene already drawn
    image = rays(s);
    EXPECT_GT(lum(image, -0.5f), lit * 9 / 10) << "moved cut: the left half casts nothing";
    EXPECT_LT(lum(image, 3.5f), lit / 3) << "moved cut: the right half casts";

    // Two texels, opaque red | clear green, blended: under coloured only the red one blocks.
    const Scene blended = texturedPlate(AlphaMode::Blend);
    image = rays(blended, BlendShadows::Coloured);
    EXPECT_LT(lum(image, 1.0f), lit / 3);
    EXPECT_GT(lum(image, 3.5f), lit * 9 / 10);
    // Untextured at alpha 0.3: blocks whole under opaque only.
    const Scene faint = texturedPlate(AlphaMode::Blend, 0.3f, false);
    EXPECT_LT(lum(rays(faint, BlendShadows::Opaque), 3.5f), lit / 3);
    for (BlendShadows b : {BlendShadows::Dithered, BlendShadows::None})
        EXPECT_GT(lum(rays(faint, b), 3.5f), lit * 9 / 10) << toString(b);

    // Scored against the reference, the masked plate's rays agree everywhere.
    RenderOptions o = texturedPlate(AlphaMode::Mask).options;
    o.width = o.height = 128;
    o.shadow.shadowRays = ShadowRayMode::All;
    const ScoreResult r = score(sharedRenderer(), texturedPlate(AlphaMode::Mask), o);
    std::printf("masked plate, rays: %.4f%% misclassified\n", 100.0 * r.overall.misclassified);
    EXPECT_LE(r.overall.misclassified * double(r.overall.pixels),
              0.00005 * double(r.overall.pixels) + 1.0);
    // So do the rays of the pixels a coarse map is unsure of (its edges, the cut's among them),
    // traced in a pass of their own.
    o.shadow.shadowRays = ShadowRayMode::Uncertain;
    o.shadow.mapSize = 64;
    const ScoreResult u = score(sharedRenderer(), texturedPlate(AlphaMode::Mask), o);
    std::printf("masked plate, uncertain: %.4f%% misclassified, %.2f%% traced\n",
                100.0 * u.overall.misclassified, 100.0 * u.overall.traced);
    EXPECT_GT(u.overall.traced, 0.0);
    EXPECT_LE(u.overall.misclassified * double(u.overall.pixels),
              0.00005 * double(u.overall.pixels) + 1.0);
}

TEST(Materials, SrgbOutputEncodesTheLinearColours) {
    const Scene s = texturedPlate(AlphaMode::Mask);
    RenderOptions o = s.options;
    const Image linear = sharedRenderer().render(s, o);
    o.shading.output = OutputEncoding::Srgb;
    const Image srgb = sharedRenderer().render(s, o);
    auto encode = [](double c) {
        return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    };
    int checked = 0;
    for (float x : {-4.5f, 1.0f, 3.5f}) {
        const std::uint8_t* l = linear.at(column(x), kMiddleRow);
        const std::uint8_t* e = srgb.at(column(x), kMiddleRow);
        for (int c = 0; c < 3; ++c, ++checked) {
            EXPECT_NEAR(double(e[c]), 255.0 * encode(l[c] / 255.0), 3.0)
                << "x " << x << ", channel " << c;
        }
    }
    EXPECT_EQ(checked, 9);
    EXPECT_GT(srgb.at(column(1.0f), kMiddleRow)[0], linear.at(column(1.0f), kMiddleRow)[0]);
}

}  // namespace
}  // namespace gnomon::test
