// The scene model (include/gnomon/Scene.h): the built-in scenes carry the textbooks' exact
// numbers (lights, cameras, spin, attenuation, ambient), each validates cleanly, and unknown
// names/paths throw gnomon::Error with a message that helps (known names, the path).
// Scene::validate's catches: test_scene_validate.cpp.
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "UnitTestUtil.h"
#include "gnomon/Error.h"
#include "gnomon/Scene.h"
#include "scene/ModelFinish.h"
#include "scene/SceneUtil.h"

namespace gnomon {
namespace {

const char* const kBuiltinNames[] = {
    "book-triangle", "book-triangle-far",  "course-two-lights",    "course-cubes",
    "tutorial-room", "tutorial-room-thin", "tutorial-directional", "tutorial-spot",
    "tutorial-area", "tutorial-point",     "mixed-lights"};

TEST(Scene, BuiltinListIsStableAndDescribed) {
    const std::vector<SceneInfo> list = builtinScenes();
    ASSERT_EQ(list.size(), std::size(kBuiltinNames));
    for (size_t i = 0; i < list.size(); ++i) {
        EXPECT_EQ(list[i].name, kBuiltinNames[i]);
        EXPECT_FALSE(list[i].description.empty()) << list[i].name;
    }
}

TEST(Scene, EveryBuiltinValidatesAndCarriesItsName) {
    for (const SceneInfo& info : builtinScenes()) {
        SCOPED_TRACE(info.name);
        const Scene s = builtinScene(info.name);
        EXPECT_EQ(s.name, info.name);
        EXPECT_EQ(s.description, info.description);
        EXPECT_TRUE(s.validate().empty()) << s.validate().front();
        EXPECT_TRUE(s.options.validate().empty());
        EXPECT_FALSE(s.objects.empty());
        EXPECT_FALSE(s.lights.empty());
    }
}

TEST(Scene, UnknownNameThrowsListingKnownNames) {
    try {
        builtinScene("no-such-scene");
        FAIL() << "builtinScene did not throw";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::InvalidInput);
        const std::string msg = e.what();
        EXPECT_NE(msg.find("no-such-scene"), std::string::npos) << msg;
        for (const char* name : kBuiltinNames)
            EXPECT_NE(msg.find(name), std::string::npos) << name << " missing from: " << msg;
    }
}

// A slip of the keyboard gets the name meant; a word far from every name gets none.
TEST(Scene, MistypedNameSuggestsTheNearest) {
    try {
        builtinScene("tutorial-rom");
        FAIL() << "builtinScene did not throw";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("unknown scene 'tutorial-rom'; did you mean "
                                             "tutorial-room? (built-in scenes: book-triangle"),
                  std::string::npos)
            << e.what();
    }
    try {
        builtinScene("no-such-scene");
        FAIL() << "builtinScene did not throw";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).find("did you mean"), std::string::npos) << e.what();
    }
}

// --sun's two angles: where the light comes from, and the way it goes (Light::direction).
TEST(Scene, SunDirectionFromAzimuthAndElevation) {
    test::expectVec(sunDirection(0.0f, 90.0f), {0.0f, -1.0f, 0.0f}, 1e-6f);  // overhead
    test::expectVec(sunDirection(0.0f, 0.0f), {0.0f, 0.0f, -1.0f}, 1e-6f);   // from +z
    test::expectVec(sunDirection(90.0f, 0.0f), {-1.0f, 0.0f, 0.0f}, 1e-6f);  // from +x
    test::expectVec(sunDirection(180.0f, 0.0f), {0.0f, 0.0f, 1.0f}, 1e-6f);  // from -z
    test::expectVec(sunDirection(-90.0f, 0.0f), {1.0f, 0.0f, 0.0f}, 1e-6f);  // from -x
    const float h = std::sqrt(0.5f);
    test::expectVec(sunDirection(0.0f, 45.0f), {0.0f, -h, -h}, 1e-6f);  // from +z, halfway up
    // From between +z and +x, 30 degrees up: down by sin 30, across by cos 30 sin 45 each way.
    const glm::vec3 d = sunDirection(45.0f, 30.0f);
    test::expectVec(d, {-0.6123724f, -0.5f, -0.6123724f}, 1e-6f);
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-6f);
}

// book-triangle: light (0, 7, 2), perspective 70 deg, aspect 1, near 1, far 100, looking at
// the origin with up +y; view eye (0, 7, 9) at the origin, 45 deg, near 1, far 100; 400x400;
// shadowed colour x 0.7.
TEST(Scene, BookTriangleNumbers) {
    const Scene s = builtinScene("book-triangle");
    ASSERT_EQ(s.lights.size(), 1u);
    const Light& l = s.lights[0];
    test::expectVec(l.position, {0.0f, 7.0f, 2.0f}, 0.0f);
    EXPECT_EQ(l.shadowCamera.policy, ShadowCameraPolicy::Manual);
    EXPECT_EQ(l.shadowCamera.projection, Projection::Perspective);
    test::expectVec(l.shadowCamera.target, glm::vec3(0.0f), 0.0f);
    test::expectVec(l.shadowCamera.up, {0.0f, 1.0f, 0.0f}, 0.0f);
    EXPECT_FLOAT_EQ(l.shadowCamera.fovyDegrees, 70.0f);
    EXPECT_FLOAT_EQ(l.shadowCamera.aspect, 1.0f);
    EXPECT_FLOAT_EQ(l.shadowCamera.near, 1.0f);
    EXPECT_FLOAT_EQ(l.shadowCamera.far, 100.0f);
    EXPECT_EQ(l.shadowMapSize, 2048);  // the shipped code's size

    test::expectVec(s.camera.eye, {0.0f, 7.0f, 9.0f}, 0.0f);
    test::expectVec(s.camera.centre, glm::vec3(0.0f), 0.0f);
    test::expectVec(s.camera.up, {0.0f, 1.0f, 0.0f}, 0.0f);
    EXPECT_FLOAT_EQ(s.camera.fovyDegrees, 45.0f);
    EXPECT_FLOAT_EQ(s.camera.near, 1.0f);
    EXPECT_FLOAT_EQ(s.camera.far, 100.0f);
    EXPECT_EQ(s.options.width, 400);
    EXPECT_EQ(s.options.height, 400);
    EXPECT_EQ(s.options.shading.shadowedRule, ShadowedRule::Factor);
    EXPECT_FLOAT_EQ(s.options.shading.shadowFactor, 0.7f);
}

TEST(Scene, BookTriangleFarMovesTheLightAndItsFarPlane) {
    const Scene s = builtinScene("book-triangle-far");
    ASSERT_EQ(s.lights.size(), 1u);
    test::expectVec(s.lights[0].position, {0.0f, 40.0f, 2.0f}, 0.0f);
    EXPECT_FLOAT_EQ(s.lights[0].shadowCamera.far, 200.0f);
    EXPECT_FLOAT_EQ(s.lights[0].shadowCamera.near, 1.0f);
    test::expectVec(s.camera.eye, {0.0f, 7.0f, 9.0f}, 0.0f);
}

const Object& objectNamed(const Scene& s, const std::string& name) {
    for (const Object& o : s.objects)
        if (o.name == name) return o;
    throw std::runtime_error("no object " + name);
}

// the triangle spins 40 deg/s about y through the origin. At 9 s it has turned
// 360 deg (back where it started); at 2.25 s 90 deg, and +90 deg about y maps (x, y, z) to
// (z, y, -x): (0.8, 3.5, 0) -> (0, 3.5, -0.8), (0, 3.5, 1.8) -> (1.8, 3.5, 0).
TEST(Scene, BookTriangleSpinsFortyDegreesPerSecond) {
    const Scene s = builtinScene("book-triangle");
    const Object& tri = objectNamed(s, "triangle");
    EXPECT_FLOAT_EQ(tri.spin.degreesPerSecond, 40.0f);
    const Mesh& mesh = s.meshes.at(tri.mesh);
    ASSERT_EQ(mesh.positions.size(), 3u);
    test::expectVec(mesh.positions[1], {0.8f, 3.5f, 0.0f}, 0.0f);
    test::expectVec(mesh.positions[2], {0.0f, 3.5f, 1.8f}, 0.0f);

    auto at = [&](double t, const glm::vec3& p) {
        return glm::vec3(tri.worldFromModelAt(t) * glm::vec4(p, 1.0f));
    };
    for (const glm::vec3& p : mesh.positions)
        test::expectVec(at(9.0, p), p, 1e-5f);
    test::expectVec(at(2.25, mesh.positions[1]), {0.0f, 3.5f, -0.8f}, 1e-5f);
    test::expectVec(at(2.25, mesh.positions[2]), {1.8f, 3.5f, 0.0f}, 1e-5f);
    // The plane does not spin.
    const Object& plane = objectNamed(s, "plane");
    EXPECT_PRED_FORMAT3(test::matNear, plane.worldFromModelAt(2.25), plane.worldFromModel, 0.0f);
}

// The plane is rotated -45 deg about (0, 1, 1)/sqrt(2). Rodrigues for v = (1, 0, 0):
// k.v = 0, k x v = (0, 1, -1)/sqrt(2), so v' = v cos + (k x v) sin
// = (0.7071068, 0, 0) + (0, 0.7071068, -0.7071068)(-0.7071068) = (0.7071068, -0.5, 0.5).
TEST(Scene, BookPlaneIsTiltedAboutTheDiagonalAxis) {
    const Scene s = builtinScene("book-triangle");
    const glm::mat4 m = objectNamed(s, "plane").worldFromModel;
    test::expectVec(glm::vec3(m * glm::vec4(1.0f, 0.0f, 0.0f, 0.0f)), {0.7071068f, -0.5f, 0.5f});
    test::expectVec(glm::vec3(m * glm::vec4(0.0f, 1.0f, 1.0f, 0.0f)), {0.0f, 1.0f, 1.0f});  // axis
}

// Course text: lights at (3, 0, 5) and (-3, 0, 5) looking at the view centre, orthographic
// +-2, near 1, far 20, map 512, attenuation 1/(1 + 0.1 d), ambient 0.3; view eye (0, 0, 5).
TEST(Scene, CourseNumbers) {
    for (const char* name : {"course-two-lights", "course-cubes"}) {
        SCOPED_TRACE(name);
        const Scene s = builtinScene(name);
        ASSERT_EQ(s.lights.size(), 2u);
        test::expectVec(s.lights[0].position, {3.0f, 0.0f, 5.0f}, 0.0f);
        test::expectVec(s.lights[1].position, {-3.0f, 0.0f, 5.0f}, 0.0f);
        for (const Light& l : s.lights) {
            EXPECT_TRUE(l.enabled);
            const ShadowCamera& c = l.shadowCamera;
            EXPECT_EQ(c.policy, ShadowCameraPolicy::Course);
            EXPECT_EQ(c.projection, Projection::Orthographic);
            EXPECT_FLOAT_EQ(c.left, -2.0f);
            EXPECT_FLOAT_EQ(c.right, 2.0f);
            EXPECT_FLOAT_EQ(c.bottom, -2.0f);
            EXPECT_FLOAT_EQ(c.top, 2.0f);
            EXPECT_FLOAT_EQ(c.near, 1.0f);
            EXPECT_FLOAT_EQ(c.far, 20.0f);
            EXPECT_FLOAT_EQ(c.fovyDegrees, 45.0f);
            EXPECT_EQ(l.shadowMapSize, 512);
            EXPECT_FLOAT_EQ(l.attenuation.constant, 1.0f);
            EXPECT_FLOAT_EQ(l.attenuation.linear, 0.1f);
            EXPECT_FLOAT_EQ(l.attenuation.quadratic, 0.0f);
        }
        test::expectVec(s.ambient, glm::vec3(0.3f), 0.0f);
        test::expectVec(s.camera.eye, {0.0f, 0.0f, 5.0f}, 0.0f);
        test::expectVec(s.camera.centre, glm::vec3(0.0f), 0.0f);
        EXPECT_FLOAT_EQ(s.camera.fovyDegrees, 45.0f);
        EXPECT_FLOAT_EQ(s.camera.far, 20.0f);
        EXPECT_EQ(s.options.shading.shadowedRule, ShadowedRule::AmbientOnly);
        for (const Material& m : s.materials)
            EXPECT_FLOAT_EQ(m.shininess, 30.0f) << m.name;
        // The model twice: the second copy moved by (-4, 0, -4).
        const size_t half = s.objects.size() / 2;
        ASSERT_EQ(s.objects.size(), 2 * half);
        for (size_t i = 0; i < half; ++i) {
            const glm::mat4 delta =
                s.objects[half + i].worldFromModel * glm::inverse(s.objects[i].worldFromModel);
            test::expectVec(glm::vec3(delta[3]), {-4.0f, 0.0f, -4.0f});
        }
    }
}

TEST(Scene, TutorialSunNumbers) {
    for (const char* name : {"tutorial-room", "tutorial-room-thin"}) {
        SCOPED_TRACE(name);
        const Scene s = builtinScene(name);
        ASSERT_EQ(s.lights.size(), 1u);
        const Light& sun = s.lights[0];
        EXPECT_EQ(sun.type, LightType::Directional);
        // (0.267, -0.802, 0.535) has length 1.000359: normalised (0.2669042, -0.8017122,
        // 0.5348080).
        test::expectVec(sun.direction, {0.2669042f, -0.8017122f, 0.5348080f}, 1e-6f);
        EXPECT_FLOAT_EQ(sun.intensity, 0.75f);
        EXPECT_EQ(sun.shadowCamera.policy, ShadowCameraPolicy::Fit);
        test::expectVec(s.ambient, glm::vec3(0.1f), 0.0f);
    }
    // The thin variant's floor is one double-sided quad; the thick one a closed box.
    const Scene thick = builtinScene("tutorial-room"), thin = builtinScene("tutorial-room-thin");
    EXPECT_EQ(thin.meshes.at(objectNamed(thin, "floor").mesh).positions.size(), 4u);
    EXPECT_EQ(thick.meshes.at(objectNamed(thick, "floor").mesh).positions.size(), 24u);
    EXPECT_TRUE(thin.materials.at(objectNamed(thin, "floor").material).doubleSided);
    EXPECT_FALSE(thick.materials.at(objectNamed(thick, "floor").material).doubleSided);
}

TEST(Scene, LoadSceneByNameGivesTheBuiltin) {
    const Scene s = loadScene("course-cubes");
    EXPECT_EQ(s.name, "course-cubes");
    EXPECT_EQ(s.objects.size(), builtinScene("course-cubes").objects.size());
}

TEST(Scene, LoadSceneMissingFileIsBadInput) {
    try {
        loadScene("no/such/file.gltf");
        FAIL() << "loadScene did not throw";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::InvalidInput);
        EXPECT_NE(std::string(e.what()).find("no/such/file.gltf"), std::string::npos) << e.what();
    }
}

TEST(Scene, LoadSceneUnknownNameThrowsInvalidInput) {
    try {
        loadScene("nosuchscene");
        FAIL() << "loadScene did not throw";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::InvalidInput);
        EXPECT_NE(std::string(e.what()).find("book-triangle"), std::string::npos) << e.what();
    }
}

// Files go to their loader by extension: glTF is read (an empty JSON object is no glTF),
// other formats are refused by name.
TEST(Scene, LoadSceneDispatchesByExtension) {
    const test::ScopedTempDir dir;
    const std::string gltf = (dir.path() / "model.gltf").string();
    std::ofstream(gltf) << "{}";
    const std::string obj = (dir.path() / "model.obj").string();
    std::ofstream(obj) << "v 0 0 0\n";
    for (const std::string& path : {gltf, obj}) {
        try {
            loadScene(path);
            FAIL() << "loadScene did not throw for " << path;
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::InvalidInput);
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        }
    }
    try {
        loadScene(obj);
    } catch (const Error& e) {
        // .obj goes to assimp (test_assimp.cpp), which finds this one unreadable.
        EXPECT_NE(std::string(e.what()).find("assimp cannot read it"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace gnomon

namespace gnomon {
namespace {
// The tutorial's numbers.
TEST(Scene, TutorialLightsCarryTheTutorialsNumbers) {
    const Light spot = builtinScene("tutorial-spot").lights.at(0);
    EXPECT_EQ(spot.type, LightType::Spot);
    EXPECT_EQ(spot.position, glm::vec3(-3.0f, 10.0f, -6.0f));
    EXPECT_EQ(spot.colour, glm::vec3(0.3f));
    EXPECT_EQ(spot.intensity, 300.0f);
    EXPECT_EQ(spot.attenuation.quadratic, 1.0f);
    const Light area = builtinScene("tutorial-area").lights.at(0);
    EXPECT_EQ(area.type, LightType::Area);
    EXPECT_EQ(area.colour, glm::vec3(0.5f));
    EXPECT_EQ(area.intensity, 1000.0f);
    const Light point = builtinScene("tutorial-point").lights.at(0);
    EXPECT_EQ(point.type, LightType::Point);
    EXPECT_EQ(point.position, glm::vec3(0.0f, 3.0f, -1.5f));
    EXPECT_EQ(point.colour, glm::vec3(0.3f));
    EXPECT_EQ(point.intensity, 20.0f);
    const Light sun = builtinScene("tutorial-directional").lights.at(0);
    EXPECT_EQ(sun.shadowCamera.policy, ShadowCameraPolicy::Manual);
    EXPECT_EQ(sun.shadowCamera.near, 25.0f);
    EXPECT_EQ(sun.shadowCamera.far, 40.0f);
    EXPECT_NEAR(glm::length(sun.position), 33.67f, 0.01f);
}

TEST(Scene, MixedLightsHasEveryTypeAndSixteenShadowedLights) {
    const Scene s = builtinScene("mixed-lights");
    int shadowed = 0, types[4] = {};
    for (const Light& l : s.lights) {
        shadowed += l.castsShadows;
        ++types[int(l.type)];
    }
    EXPECT_GE(shadowed, 16);
    for (int t = 0; t < 4; ++t)
        EXPECT_GT(types[t], 0) << "light type " << t;
}
}  // namespace
}  // namespace gnomon

namespace gnomon {
namespace {
TEST(Presets, DefaultIsTheScenesOwnOptions) {
    const Scene s = builtinScene("tutorial-room");
    const RenderOptions o = presetOptions(s, Preset::Default);
    EXPECT_EQ(o.shadow.biasConstant, s.options.shadow.biasConstant);
    EXPECT_EQ(o.shadow.depthFormat, DepthFormat::Depth32F);
    EXPECT_EQ(o.shadow.shadowRays, ShadowRayMode::Off);  // the maps alone
}

TEST(Presets, TextbookCarriesEachTextbooksNumbers) {
    const RenderOptions book = presetOptions(builtinScene("book-triangle"), Preset::Textbook);
    EXPECT_EQ(book.shadow.depthFormat, DepthFormat::R8);
    EXPECT_EQ(book.shadow.mapFilter, MapFilter::Linear);
    EXPECT_EQ(book.shadow.biasConstant, 0.005f);
    EXPECT_EQ(book.shading.shadowFactor, 0.7f);
    const RenderOptions far = presetOptions(builtinScene("book-triangle-far"), Preset::Textbook);
    EXPECT_EQ(far.shadow.depthFormat, DepthFormat::Rgba8Packed256);
    EXPECT_EQ(far.shadow.mapFilter, MapFilter::Nearest);
    EXPECT_EQ(far.shadow.biasConstant, 0.0015f);
    const RenderOptions course = presetOptions(builtinScene("course-cubes"), Preset::Textbook);
    EXPECT_EQ(course.shadow.biasConstant, 0.00001f);
    EXPECT_EQ(course.shadow.mapFilter, MapFilter::Linear);
    const RenderOptions spot = presetOptions(builtinScene("tutorial-spot"), Preset::Textbook);
    EXPECT_EQ(spot.shadow.biasConstant, 0.025f);
    EXPECT_EQ(spot.shadow.pcfSize, 5);
    EXPECT_EQ(presetOptions(builtinScene("tutorial-room"), Preset::Textbook).shadow.biasConstant,
              0.00575f);
    for (const SceneInfo& info : builtinScenes()) {
        const RenderOptions t = presetOptions(builtinScene(info.name), Preset::Textbook);
        SCOPED_TRACE(info.name);
        EXPECT_TRUE(t.validate().empty());
        // Only the constant tolerance: every other remedy is off.
        EXPECT_EQ(t.shadow.biasSlope, 0.0f);
        EXPECT_EQ(t.shadow.normalOffset, 0.0f);
        EXPECT_FALSE(t.shadow.receiverPlane);
        EXPECT_EQ(t.shadow.biasDepthAware, 0.0f);
        EXPECT_EQ(t.shadow.shadowRays, ShadowRayMode::Off);  // the maps alone decide
    }
}

TEST(Presets, SceneWithoutTextbookGetsTheConstantToleranceMethod) {
    Scene s = builtinScene("tutorial-room");
    s.textbookOptions.reset();
    const RenderOptions t = presetOptions(s, Preset::Textbook);
    EXPECT_EQ(t.shadow.biasConstant, 0.005f);
    EXPECT_EQ(t.shadow.filter, ShadowFilter::None);
    EXPECT_EQ(t.shadow.cull, CullMode::None);
    EXPECT_EQ(t.shadow.shadowRays, ShadowRayMode::Off);
    EXPECT_EQ(parsePreset("textbook"), Preset::Textbook);
    EXPECT_FALSE(parsePreset("fancy").has_value());
}
}  // namespace
}  // namespace gnomon

namespace gnomon {
namespace {

TEST(Scene, ObjectsWithoutUvsGetOneUntexturedCopyOfTheirMaterial) {
    Scene s = builtinScene("course-cubes");
    Texture t;
    t.width = t.height = 1;
    t.rgba = {1, 2, 3, 4};
    s.textures.push_back(t);
    s.materials[s.objects[0].material].baseColourTexture = 0;
    const std::uint32_t textured = s.objects[0].material;
    const std::size_t materials = s.materials.size();
    EXPECT_FALSE(s.validate().empty()) << "textured material on a mesh without uvs";
    untextureObjectsWithoutUvs(s);
    EXPECT_TRUE(s.validate().empty());
    ASSERT_EQ(s.materials.size(), materials + 1) << "one copy, shared by every such object";
    for (const Object& o : s.objects) {
        EXPECT_NE(o.material, textured);
        EXPECT_EQ(s.materials[o.material].baseColourTexture, -1);
    }
}

TEST(Scene, AddGroundPutsAReceiverUnderTheScene) {
    Scene s = builtinScene("course-cubes");
    const Aabb before = worldBounds(s, meshBounds(s), 0.0, false);
    const std::size_t objects = s.objects.size();
    addGround(s);
    ASSERT_EQ(s.objects.size(), objects + 1);
    EXPECT_TRUE(s.validate().empty());
    const Object& g = s.objects.back();
    EXPECT_FALSE(g.castsShadows);
    EXPECT_TRUE(g.receivesShadows);
    const Mesh& m = s.meshes[g.mesh];
    for (const glm::vec3& p : m.positions) {
        EXPECT_LT(p.y, before.min.y);
        EXPECT_GT(p.y, before.min.y - 1e-3f * before.radius());
    }
    for (const glm::vec3& n : m.normals)
        EXPECT_EQ(n, glm::vec3(0, 1, 0));
    // Wider than the scene on every side, and its first triangle faces up (CCW from +y).
    const Aabb ground = meshBounds(s).back();
    EXPECT_LT(ground.min.x, before.min.x);
    EXPECT_GT(ground.max.z, before.max.z);
    const glm::vec3 up =
        glm::cross(m.positions[1] - m.positions[0], m.positions[2] - m.positions[0]);
    EXPECT_GT(up.y, 0.0f);
    Scene empty;
    addGround(empty);
    EXPECT_TRUE(empty.objects.empty());
}

}  // namespace
}  // namespace gnomon

namespace gnomon {
namespace {

// The default sun stands over the camera's right shoulder: its light travels away from the
// camera (shadows fall beyond their casters, not towards the viewer), from the camera's right
// (they fall to the left, beside the casters), 50 degrees down.
TEST(DefaultSun, ComesOverTheCamerasRightShoulder) {
    Camera cam;
    cam.eye = {0.0f, 2.0f, 10.0f};
    cam.centre = {0.0f, 0.0f, 0.0f};
    const glm::vec3 d = defaultSunDirection(cam);
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
    EXPECT_NEAR(-d.y, std::sin(glm::radians(50.0f)), 1e-4f);
    EXPECT_LT(d.z, 0.0f) << "travels towards the camera";
    EXPECT_LT(d.x, 0.0f) << "comes from the camera's left";
    // Looking straight down there is no shoulder: a fixed high sun.
    cam.eye = {0.0f, 10.0f, 0.0f};
    const glm::vec3 down = defaultSunDirection(cam);
    EXPECT_LT(down.y, -0.8f);
}

}  // namespace
}  // namespace gnomon
