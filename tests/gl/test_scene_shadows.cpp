// Shadows where the geometry says, and nowhere else: for each built-in scene, pixels that the
// scene's own triangles put in shadow (tests/support/GeometryShadows, CPU ray casting) must
// be darker than in the shadows-off render, and pixels in no shadow must be unchanged.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "GlTest.h"
#include "ShadowCheck.h"
#include "scene/MeshBuilder.h"

namespace gnomon::test {
namespace {

struct Case {
    std::string name;
    Scene scene;
    RenderOptions options;
};

void PrintTo(const Case& c, std::ostream* os) {
    *os << c.name;
}

// Checks one scene and options; returns a description of the first failures.
class BuiltinShadows : public testing::TestWithParam<Case> {};

TEST_P(BuiltinShadows, DarkerWhereGeometryShadowsUnchangedElsewhere) {
    expectShadowsMatchGeometry(GetParam().scene, GetParam().options);
}

Case builtin(const std::string& name, double time = 0.0) {
    Case c{
        name + (time != 0.0 ? "_t" + std::to_string(int(time * 10)) : ""), builtinScene(name), {}};
    c.options = c.scene.options;
    c.options.time = time;
    for (char& ch : c.name)
        ch = ch == '-' ? '_' : ch;
    return c;
}

std::vector<Case> builtinCases() {
    std::vector<Case> cases;
    for (const SceneInfo& info : builtinScenes())
        cases.push_back(builtin(info.name));
    cases.push_back(builtin("book-triangle", 1.5));  // rotated 60 degrees (the book's spin)
    return cases;
}

INSTANTIATE_TEST_SUITE_P(Scenes, BuiltinShadows, testing::ValuesIn(builtinCases()),
                         [](const auto& info) { return info.param.name; });

// Every filter and the course light cameras switched to perspective keep the property.
TEST(Shadows, EachFilterKeepsShadowsWhereGeometrySays) {
    for (ShadowFilter f : {ShadowFilter::None, ShadowFilter::Hw2x2, ShadowFilter::Pcf,
                           ShadowFilter::Poisson, ShadowFilter::Pcss}) {
        Scene scene = builtinScene("tutorial-room");
        RenderOptions o = scene.options;
        o.shadow.filter = f;
        SCOPED_TRACE(toString(f));
        expectShadowsMatchGeometry(scene, o);
    }
}

// PCSS through each light type's map (perspective, cube, orthographic from a plane): soft
// edges, but shadowed where the geometry says and no acne or leaks elsewhere.
TEST(Shadows, PcssOnEveryLightType) {
    for (const char* name : {"tutorial-spot", "tutorial-point", "tutorial-area"}) {
        Scene scene = builtinScene(name);
        RenderOptions o = scene.options;
        o.shadow.filter = ShadowFilter::Pcss;
        o.shadow.lightRadius = 0.1f;
        SCOPED_TRACE(name);
        expectShadowsMatchGeometry(scene, o);
    }
}

TEST(Shadows, PerspectiveCourseCameras) {
    Scene scene = builtinScene("course-cubes");
    for (Light& l : scene.lights)
        l.shadowCamera.projection = Projection::Perspective;
    expectShadowsMatchGeometry(scene, scene.options);
}

// A scene file in millimetres with a manual shadow camera that gives no planes: they are
// fitted to the scene seen from the light, so the box's shadow falls where the geometry
// says (with the defaults near 1 and far 100, the whole scene lay before the near plane and
// nothing was shadowed).
TEST(Shadows, ManualShadowCameraWithoutPlanesInMillimetres) {
    const Scene scene = parseSceneFile(R"({"gnomon-scene": 1, "ground": true,
        "objects": [{"shape": "box", "size": 0.001, "centre": [0, 0.0005, 0]}],
        "lights": [{"type": "spot", "position": [-0.0015, 0.003, -0.001], "direction": [0.5, -1, 0.35],
                    "outer-cone": 50, "inner-cone": 40,
                    "shadow-camera": {"policy": "manual", "target": [0, 0, 0], "fovy": 100}}],
        "camera": {"eye": [0.003, 0.003, 0.004], "centre": [0, 0, 0]}})",
                                       "millimetres.json");
    expectShadowsMatchGeometry(scene, scene.options);
}

// at least 16 shadowed lights in one main pass, each with its own map.
TEST(Shadows, SixteenSpotLightsEachCastTheirShadow) {
    GNOMON_NEEDS_DEPTH_READBACK();
    Scene scene;
    scene.name = "sixteen spots";
    Material grey;
    grey.baseColour = glm::vec3(0.8f);
    scene.materials.push_back(grey);
    Mesh floor;
    floor.positions = {{-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}};
    floor.normals.assign(4, glm::vec3(0, 1, 0));
    floor.indices = {0, 1, 2, 0, 2, 3};
    scene.meshes.push_back(floor);
    scene.objects.push_back({"floor", 0, 0, glm::mat4(1.0f), {}, true, true});
    // A pillar in the middle: 16 shadows fanning out.
    scene.meshes.push_back(mesh::box("pillar", {0.0f, 1.25f, 0.0f}, {0.8f, 2.5f, 0.8f}));
    scene.objects.push_back({"pillar", 1, 0, glm::mat4(1.0f), {}, true, true});
    for (int i = 0; i < 16; ++i) {
        Light l;
        l.name = "spot " + std::to_string(i);
        l.type = LightType::Spot;
        const float a = glm::radians(22.5f * float(i));
        l.position = {2.5f * std::cos(a), 6.0f, 2.5f * std::sin(a)};
        l.direction = glm::normalize(glm::vec3(0.0f) - l.position);
        l.intensity = 0.06f;  // 16 x 0.06: the picture does not saturate
        l.innerConeDegrees = 60.0f;
        l.outerConeDegrees = 70.0f;
        // Fine enough that PCF's penumbra (a few texels) stays inside the oracle's margin.
        l.shadowMapSize = 1024;
        scene.lights.push_back(l);
    }
    scene.camera.eye = {0.0f, 11.0f, 5.0f};
    scene.camera.centre = {0.0f, 0.0f, 0.0f};
    scene.camera.near = 1.0f;
    scene.camera.far = 40.0f;
    scene.ambient = glm::vec3(0.1f);
    RenderOptions o;
    sharedRenderer().render(scene, o);
    EXPECT_EQ(sharedRenderer().lastFrameStats().shadowPasses, 16);
    EXPECT_EQ(sharedRenderer().shadowMaps().size(), 16u);
    expectShadowsMatchGeometry(scene, o);
}

}  // namespace
}  // namespace gnomon::test
