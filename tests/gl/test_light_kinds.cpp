// When every single-map light of a frame has one kind (all spots, say), the main pass is a
// program with that kind compiled in (FramePlan::singleMapKind); with kinds mixed, the
// program reads each record's kind. Both must light the same: adding a light of another
// kind that adds nothing (intensity 0, with its own map) turns the specialised program into
// the mixed one and must leave every byte of the image as it was. Likewise a frame whose
// lights have no distance falloff (FramePlan::constantFalloff), or whose lit objects have no
// specular highlight (DrawItem::specular, per draw), against the general program.
#include <gtest/gtest.h>

#include "GlTest.h"

namespace gnomon::test {
namespace {

Image renderAt(const Scene& s, int size) {
    RenderOptions o = s.options;
    o.width = o.height = size;
    o.shadow.cascades = 1;  // the sun added below keeps a single map, beside the others
    return sharedRenderer().render(s, o);
}

void expectSameWithADarkSun(const Scene& s, int size) {
    Scene mixed = s;
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0.3f, -1.0f, 0.2f};
    sun.intensity = 0.0f;
    sun.castsShadows = true;
    mixed.lights.push_back(sun);
    const Image one = renderAt(s, size);
    const Image both = renderAt(mixed, size);
    ASSERT_EQ(one.pixels.size(), both.pixels.size());
    long differing = 0;
    for (std::size_t i = 0; i < one.pixels.size(); ++i)
        differing += one.pixels[i] != both.pixels[i];
    EXPECT_EQ(differing, 0) << s.name << ": the mixed-kind program changed " << differing
                            << " bytes";
}

TEST(LightKinds, SpotsLightTheSameAloneAsBesideAnotherKind) {
    Scene s = builtinScene("tutorial-spot");
    ASSERT_FALSE(s.lights.empty());
    ASSERT_EQ(s.lights.front().type, LightType::Spot);
    expectSameWithADarkSun(s, 128);
}

TEST(LightKinds, FramedPointLightsLightTheSameAloneAsBesideAnotherKind) {
    // A point light with a manual frustum has one map, not a cube.
    Scene s = builtinScene("tutorial-spot");
    ASSERT_FALSE(s.lights.empty());
    Light& l = s.lights.front();
    l.type = LightType::Point;
    l.shadowCamera.policy = ShadowCameraPolicy::Manual;
    l.shadowCamera.target = l.position + l.direction;
    l.shadowCamera.fovyDegrees = 90.0f;
    expectSameWithADarkSun(s, 128);
}

// A dark unshadowed point light whose falloff grows with distance and ends at a range turns
// the frame's constant-falloff program into the general one.
TEST(LightKinds, LightsWithoutFalloffLightTheSameAsBesideOneWithIt) {
    for (const char* name : {"tutorial-spot", "mixed-lights"}) {
        Scene s = builtinScene(name);
        for (Light& l : s.lights) {  // halved everywhere: falloff 1 / c0, no distance terms
            l.range = 0.0f;
            l.attenuation = {2.0f, 0.0f, 0.0f};
        }
        Scene general = s;
        Light dark;
        dark.type = LightType::Point;
        dark.position = {0.0f, 2.0f, 0.0f};
        dark.intensity = 0.0f;
        dark.attenuation = {1.0f, 0.5f, 0.25f};
        dark.range = 10.0f;
        dark.castsShadows = false;
        general.lights.push_back(dark);
        const Image constant = renderAt(s, 128);
        const Image falling = renderAt(general, 128);
        ASSERT_EQ(constant.pixels.size(), falling.pixels.size());
        long differing = 0;
        for (std::size_t i = 0; i < constant.pixels.size(); ++i)
            differing += constant.pixels[i] != falling.pixels[i];
        EXPECT_EQ(differing, 0) << name << ": the constant-falloff program changed " << differing
                                << " bytes";
    }
}

long differingBytes(const Image& a, const Image& b) {
    EXPECT_EQ(a.pixels.size(), b.pixels.size());
    long differing = 0;
    for (std::size_t i = 0; i < std::min(a.pixels.size(), b.pixels.size()); ++i)
        differing += a.pixels[i] != b.pixels[i];
    return differing;
}

// A highlight a thousand times too faint to change a byte turns the frame's program without
// specular terms into the general one.
TEST(LightKinds, ObjectsWithoutHighlightsLightTheSameInEitherProgram) {
    for (const char* name : {"tutorial-room", "mixed-lights"}) {
        Scene s = builtinScene(name);
        ASSERT_FALSE(s.materials.empty());
        for (Material& m : s.materials)
            m.specular = 0.0f;
        Scene general = s;
        general.materials.front().specular = 1e-30f;
        EXPECT_EQ(differingBytes(renderAt(s, 128), renderAt(general, 128)), 0) << name;
    }
}

// Per draw: objects without a highlight take the program without specular terms even where
// another object has one (glmark2's ground beside its horse), and light as the general
// program lights them; the object with the highlight keeps it.
TEST(LightKinds, ObjectsWithoutHighlightsBesideOneWithLightTheSame) {
    for (const char* name : {"tutorial-room", "mixed-lights"}) {
        Scene mixed = builtinScene(name);
        ASSERT_GE(mixed.materials.size(), 2u);
        for (Material& m : mixed.materials)
            m.specular = 0.0f;
        mixed.revision.bump();  // materials edited in place (Scene::revision)
        const Image dull = renderAt(mixed, 128);
        mixed.materials.front().specular = 1.0f;
        mixed.revision.bump();
        Scene general = mixed;  // every object in the general program
        for (std::size_t i = 1; i < general.materials.size(); ++i)
            general.materials[i].specular = 1e-30f;
        general.revision.bump();
        const Image shiny = renderAt(mixed, 128);
        EXPECT_GT(differingBytes(shiny, dull), 0) << name << ": no highlight in view";
        EXPECT_EQ(differingBytes(shiny, renderAt(general, 128)), 0) << name;
    }
}

}  // namespace
}  // namespace gnomon::test
