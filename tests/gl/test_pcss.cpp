// PCSS (contact hardening): the penumbra grows with the distance between caster
// and receiver, as wide as a light of the given size makes it, while the umbra stays dark
// and open floor stays lit; PCF's penumbra does not depend on that distance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "GlTest.h"
#include "scene/MeshBuilder.h"

namespace gnomon::test {
namespace {

constexpr int kSize = 256;
constexpr float kHalfView = 5.0f;  // the orthographic camera sees x, z in [-5, 5]

// Two thin plates over a floor, lit by a sun from the upper left at 45 degrees: plate A just
// above the floor (height 0.3) at z < 0, plate B high (height 3) at z > 0. Their shadows'
// right edges (+x) cross the floor where a camera looking straight down sees them.
Scene platesOverFloor(float sunAngleDegrees) {
    Scene s;
    s.name = "pcss plates";
    Material grey;
    grey.baseColour = glm::vec3(0.8f);
    grey.specular = 0.0f;
    s.materials.push_back(grey);
    s.meshes.push_back(mesh::box("floor", {0.0f, -0.05f, 0.0f}, {12.0f, 0.1f, 12.0f}));
    s.meshes.push_back(mesh::box("low plate", {-2.3f, 0.3f, -2.5f}, {2.0f, 0.04f, 3.0f}));
    s.meshes.push_back(mesh::box("high plate", {-4.0f, 3.0f, 2.5f}, {2.0f, 0.04f, 3.0f}));
    for (std::uint32_t i = 0; i < 3; ++i)
        s.objects.push_back({s.meshes[i].name, i, 0, glm::mat4(1.0f), {}, true, true});
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f));
    sun.shadowMapSize = 1024;
    s.lights.push_back(sun);
    s.camera = lookingStraightDown(kHalfView);
    s.ambient = glm::vec3(0.05f);
    s.options.width = s.options.height = kSize;
    s.options.shadow.lightAngle = sunAngleDegrees;
    return s;
}

// Width in world units of the shadow's edge along x on image row `row`, between 10% and
// 90% of the way from the shadow's darkest to the floor's lit value, looking right from
// `fromX` (a pixel inside the umbra).
float edgeWidth(const Image& image, int row, int fromX) {
    const int dark = luminance(image.at(fromX, row));
    const int lit = luminance(image.at(kSize - 2, row));
    EXPECT_GT(lit - dark, 100) << "row " << row << ": no shadow to measure";
    int first = -1, last = -1;
    for (int x = fromX; x < kSize; ++x) {
        const float t = float(luminance(image.at(x, row)) - dark) / float(lit - dark);
        if (t > 0.1f && first < 0) first = x;
        if (t < 0.9f) last = x;
    }
    return float(last - first + 1) * (2.0f * kHalfView / float(kSize));
}

int column(float x) {
    return int((x + kHalfView) / (2.0f * kHalfView) * float(kSize));
}
int row(float z) {  // up = -z: the top row is z = -5
    return int((z + kHalfView) / (2.0f * kHalfView) * float(kSize));
}

TEST(Pcss, PenumbraGrowsWithDistanceFromTheCaster) {
    const float angle = 3.0f;
    const Scene s = platesOverFloor(angle);
    RenderOptions o = s.options;
    o.shadow.filter = ShadowFilter::Pcss;
    const Image pcss = sharedRenderer().render(s, o);
    writePng(outputDir() + "/pcss_plates.png", pcss);
    // Shadow edges: plate A's right edge x = -1.3 moves by its height 0.3 to x = -1.0 (the
    // camera sees the strip from -1.3 to -1.0 beside the plate); plate B's right edge x = -3
    // by 3 to x = 0. Umbra pixels a little left of each.
    const float low = edgeWidth(pcss, row(-2.5f), column(-1.2f));
    const float high = edgeWidth(pcss, row(2.5f), column(-1.0f));
    // The penumbra on the floor of a sun of angular radius a, for a caster h above, with
    // rays at 45 degrees: the ray runs h sqrt(2) to the floor, the penumbra is 2 a that long
    // across the ray and sqrt(2) times that along the floor: 4 h tan(a); its 10-90% part
    // about 0.8 of it.
    const float expectHigh = 0.8f * 4.0f * 3.0f * std::tan(glm::radians(angle));
    EXPECT_GT(high, 3.0f * low) << "high plate " << high << ", low plate " << low;
    EXPECT_GT(high, 0.5f * expectHigh) << "high plate " << high << ", expected ~" << expectHigh;
    EXPECT_LT(high, 1.6f * expectHigh) << "high plate " << high << ", expected ~" << expectHigh;

    // The same scene with PCF: both edges as narrow as the kernel.
    o.shadow.filter = ShadowFilter::Pcf;
    const Image pcf = sharedRenderer().render(s, o);
    const float pcfLow = edgeWidth(pcf, row(-2.5f), column(-1.2f));
    const float pcfHigh = edgeWidth(pcf, row(2.5f), column(-1.0f));
    EXPECT_LT(pcfHigh, 2.0f * pcfLow + 0.1f) << "pcf " << pcfHigh << " vs " << pcfLow;
    EXPECT_LT(pcfHigh, 0.5f * high);
    std::printf("pcss low %.3f high %.3f (expected ~%.3f), pcf low %.3f high %.3f\n", low, high,
                expectHigh, pcfLow, pcfHigh);
}

// A larger light softens more; light-angle 0 is as hard as the map allows.
TEST(Pcss, LightSizeSetsThePenumbra) {
    float widths[3];
    const float angles[3] = {0.0f, 2.0f, 5.0f};
    for (int i = 0; i < 3; ++i) {
        const Scene s = platesOverFloor(angles[i]);
        RenderOptions o = s.options;
        o.shadow.filter = ShadowFilter::Pcss;
        widths[i] = edgeWidth(sharedRenderer().render(s, o), row(2.5f), column(-1.0f));
    }
    EXPECT_LT(widths[0], 0.15f) << "light-angle 0 should be hard";
    EXPECT_GT(widths[1], 2.0f * widths[0]);
    EXPECT_GT(widths[2], 1.8f * widths[1]);
}

}  // namespace
}  // namespace gnomon::test
