// Light range (glTF KHR_lights_punctual): point and spot lights end at their range with the
// spec's smooth window (1 - (d/range)^4)^2 on top of their attenuation.
#include <gtest/gtest.h>

#include <cmath>

#include "GlTest.h"
#include "scene/MeshBuilder.h"

namespace gnomon::test {
namespace {

constexpr int kSize = 128;
constexpr float kHalfView = 4.0f;  // the orthographic camera sees x, z in [-4, 4]

// A floor lit by an unattenuated point light 1 above its centre, seen from straight above.
Scene floorUnderALamp(float range) {
    Scene s;
    s.name = "lamp over a floor";
    Material grey;
    grey.baseColour = glm::vec3(0.8f);
    grey.specular = 0.0f;
    s.materials.push_back(grey);
    s.meshes.push_back(mesh::box("floor", {0.0f, -0.05f, 0.0f}, {10.0f, 0.1f, 10.0f}));
    s.objects.push_back({"floor", 0, 0, glm::mat4(1.0f), {}, true, true});
    Light lamp;
    lamp.type = LightType::Point;
    lamp.position = {0.0f, 1.0f, 0.0f};
    lamp.range = range;
    s.lights.push_back(lamp);
    s.camera = lookingStraightDown(kHalfView);
    s.ambient = glm::vec3(0.0f);
    s.options.width = s.options.height = kSize;
    return s;
}

// Red channel on the middle row at floor x (pixel centres: x = -4 + (i + 0.5) / 16).
float redAt(const Image& image, float x) {
    const int i = int((x + kHalfView) / (2.0f * kHalfView) * kSize);
    return float(image.at(i, kSize / 2)[0]);
}

TEST(LightRange, PointLightFadesOutAtItsRange) {
    const Scene unlimited = floorUnderALamp(0.0f);
    const Scene ranged = floorUnderALamp(3.0f);
    const Image a = sharedRenderer().render(unlimited, unlimited.options);
    const Image b = sharedRenderer().render(ranged, ranged.options);
    // Straight below (d = 1): window (1 - 1/81)^2 = 0.975.
    EXPECT_NEAR(redAt(b, 0.03f) / redAt(a, 0.03f), 0.975f, 0.03f);
    // At x = 2 (d = sqrt(5), r = 0.745): window 0.479.
    const float x = 2.0f - 0.03f;
    const float d = std::sqrt(x * x + 1.0f), r = d / 3.0f;
    const float window = std::pow(1.0f - r * r * r * r, 2.0f);
    EXPECT_NEAR(redAt(b, x) / redAt(a, x), window, 0.04f);
    // Beyond the range (d > 3 from x = 2.83): no light at all, where the unlimited light
    // still lights the floor.
    EXPECT_EQ(redAt(b, 3.5f), 0.0f);
    EXPECT_GT(redAt(a, 3.5f), 10.0f);
}

}  // namespace
}  // namespace gnomon::test
