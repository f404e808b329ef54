// Scene description files (docs/scene-file.md): the built-in scenes written in the format load
// to the very same scenes, a saved file reproduces what was tuned, and every kind of mistake
// is refused with the file and the JSON path.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "UnitTestUtil.h"
#include "gnomon/Error.h"
#include "gnomon/Scene.h"
#include "gnomon/SceneFile.h"

namespace gnomon {
namespace {

namespace fs = std::filesystem;
using test::ScopedTempDir;

const std::string kExamples = GNOMON_EXAMPLE_SCENES;
const std::string kCorpus = GNOMON_SCENE_FILE_CORPUS;
const char* const kExampleNames[] = {"book-triangle", "book-triangle-far", "course-two-lights",
                                     "course-cubes",  "tutorial-room",     "tutorial-room-thin"};

// ---- Comparison: `exact` for round trips, else within 1e-6 (relative above 1)

struct Compare {
    bool exact;

    void num(double a, double e, const std::string& what) const {
        if (exact) {
            EXPECT_EQ(a, e) << what;
        } else {
            EXPECT_NEAR(a, e, 1e-6 * std::max(1.0, std::fabs(e))) << what;
        }
    }
    void vec(const glm::vec3& a, const glm::vec3& e, const std::string& what) const {
        for (int i = 0; i < 3; ++i)
            num(a[i], e[i], what + "[" + std::to_string(i) + "]");
    }
    void vecs(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& e,
              const std::string& what) const {
        ASSERT_EQ(a.size(), e.size()) << what;
        for (std::size_t i = 0; i < a.size(); ++i)
            vec(a[i], e[i], what + "[" + std::to_string(i) + "]");
    }
    void mat(const glm::mat4& a, const glm::mat4& e, const std::string& what) const {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                num(a[c][r], e[c][r],
                    what + "[" + std::to_string(c) + "][" + std::to_string(r) + "]");
    }

    void options(const RenderOptions& a, const RenderOptions& e, const std::string& what) const {
        EXPECT_EQ(a.width, e.width) << what << " width";
        EXPECT_EQ(a.height, e.height) << what << " height";
        num(a.time, e.time, what + " time");
        EXPECT_EQ(a.lightOnly, e.lightOnly) << what << " lightOnly";
        EXPECT_EQ(a.debugView, e.debugView) << what << " debugView";
        const ShadowOptions &s = a.shadow, &t = e.shadow;
        EXPECT_EQ(s.enabled, t.enabled) << what << " shadow.enabled";
        EXPECT_EQ(s.outside, t.outside) << what << " shadow.outside";
        num(s.biasConstant, t.biasConstant, what + " biasConstant");
        num(s.biasDepthAware, t.biasDepthAware, what + " biasDepthAware");
        num(s.biasSlope, t.biasSlope, what + " biasSlope");
        num(s.biasUnits, t.biasUnits, what + " biasUnits");
        num(s.normalOffset, t.normalOffset, what + " normalOffset");
        EXPECT_EQ(s.receiverPlane, t.receiverPlane) << what << " receiverPlane";
        EXPECT_EQ(s.cull, t.cull) << what << " cull";
        EXPECT_EQ(s.filter, t.filter) << what << " filter";
        EXPECT_EQ(s.pcfSize, t.pcfSize) << what << " pcfSize";
        num(s.lightRadius, t.lightRadius, what + " lightRadius");
        num(s.lightAngle, t.lightAngle, what + " lightAngle");
        EXPECT_EQ(s.mapSize, t.mapSize) << what << " mapSize";
        EXPECT_EQ(s.cascades, t.cascades) << what << " cascades";
        EXPECT_EQ(s.fitTo, t.fitTo) << what << " fitTo";
        num(s.cascadeLambda, t.cascadeLambda, what + " cascadeLambda");
        num(s.cascadeBlend, t.cascadeBlend, what + " cascadeBlend");
        EXPECT_EQ(s.depthFormat, t.depthFormat) << what << " depthFormat";
        EXPECT_EQ(s.mapFilter, t.mapFilter) << what << " mapFilter";
        EXPECT_EQ(s.blendShadows, t.blendShadows) << what << " blendShadows";
        EXPECT_EQ(a.shading.shadowedRule, e.shading.shadowedRule) << what << " shadowedRule";
        num(a.shading.shadowFactor, e.shading.shadowFactor, what + " shadowFactor");
        EXPECT_EQ(a.shading.output, e.shading.output) << what << " output";
    }

    void light(const Light& a, const Light& e, const std::string& w) const {
        EXPECT_EQ(a.name, e.name) << w;
        EXPECT_EQ(a.type, e.type) << w << " type";
        EXPECT_EQ(a.enabled, e.enabled) << w << " enabled";
        vec(a.position, e.position, w + " position");
        vec(a.direction, e.direction, w + " direction");
        vec(a.colour, e.colour, w + " colour");
        num(a.intensity, e.intensity, w + " intensity");
        num(a.attenuation.constant, e.attenuation.constant, w + " attenuation.constant");
        num(a.attenuation.linear, e.attenuation.linear, w + " attenuation.linear");
        num(a.attenuation.quadratic, e.attenuation.quadratic, w + " attenuation.quadratic");
        num(a.innerConeDegrees, e.innerConeDegrees, w + " innerConeDegrees");
        num(a.outerConeDegrees, e.outerConeDegrees, w + " outerConeDegrees");
        EXPECT_EQ(a.castsShadows, e.castsShadows) << w << " castsShadows";
        EXPECT_EQ(a.shadowMapSize, e.shadowMapSize) << w << " shadowMapSize";
        const ShadowCamera &c = a.shadowCamera, &d = e.shadowCamera;
        EXPECT_EQ(c.policy, d.policy) << w << " shadowCamera.policy";
        EXPECT_EQ(c.projection, d.projection) << w << " shadowCamera.projection";
        vec(c.target, d.target, w + " shadowCamera.target");
        vec(c.up, d.up, w + " shadowCamera.up");
        num(c.fovyDegrees, d.fovyDegrees, w + " shadowCamera.fovyDegrees");
        num(c.aspect, d.aspect, w + " shadowCamera.aspect");
        num(c.near, d.near, w + " shadowCamera.near");
        num(c.far, d.far, w + " shadowCamera.far");
        num(c.left, d.left, w + " shadowCamera.left");
        num(c.right, d.right, w + " shadowCamera.right");
        num(c.bottom, d.bottom, w + " shadowCamera.bottom");
        num(c.top, d.top, w + " shadowCamera.top");
    }

    void camera(const Camera& a, const Camera& e) const {
        vec(a.eye, e.eye, "camera.eye");
        vec(a.centre, e.centre, "camera.centre");
        vec(a.up, e.up, "camera.up");
        EXPECT_EQ(a.projection, e.projection) << "camera.projection";
        num(a.fovyDegrees, e.fovyDegrees, "camera.fovyDegrees");
        num(a.aspect, e.aspect, "camera.aspect");
        num(a.near, e.near, "camera.near");
        num(a.far, e.far, "camera.far");
        num(a.left, e.left, "camera.left");
        num(a.right, e.right, "camera.right");
        num(a.bottom, e.bottom, "camera.bottom");
        num(a.top, e.top, "camera.top");
    }

    // Meshes, materials and objects, including every object's triangles in world space.
    void geometry(const Scene& a, const Scene& e) const {
        ASSERT_EQ(a.meshes.size(), e.meshes.size()) << "mesh count";
        for (std::size_t m = 0; m < a.meshes.size(); ++m) {
            const std::string w = "meshes[" + std::to_string(m) + "]";
            EXPECT_EQ(a.meshes[m].name, e.meshes[m].name) << w;
            vecs(a.meshes[m].positions, e.meshes[m].positions, w + ".positions");
            vecs(a.meshes[m].normals, e.meshes[m].normals, w + ".normals");
            vecs(a.meshes[m].colours, e.meshes[m].colours, w + ".colours");
            EXPECT_EQ(a.meshes[m].uvs.size(), e.meshes[m].uvs.size()) << w;
            EXPECT_EQ(a.meshes[m].indices, e.meshes[m].indices) << w << ".indices";
        }
        ASSERT_EQ(a.materials.size(), e.materials.size()) << "material count";
        for (std::size_t m = 0; m < a.materials.size(); ++m) {
            const Material &x = a.materials[m], &y = e.materials[m];
            const std::string w = "materials[" + std::to_string(m) + "] " + y.name;
            EXPECT_EQ(x.name, y.name) << w;
            vec(x.baseColour, y.baseColour, w + " baseColour");
            num(x.specular, y.specular, w + " specular");
            num(x.shininess, y.shininess, w + " shininess");
            EXPECT_EQ(x.unlit, y.unlit) << w << " unlit";
            EXPECT_EQ(x.doubleSided, y.doubleSided) << w << " doubleSided";
            num(x.alpha, y.alpha, w + " alpha");
            EXPECT_EQ(x.baseColourTexture, y.baseColourTexture) << w;
            EXPECT_EQ(x.alphaMode, y.alphaMode) << w << " alphaMode";
            num(x.alphaCutoff, y.alphaCutoff, w + " alphaCutoff");
        }
        EXPECT_EQ(a.textures.size(), e.textures.size());
        ASSERT_EQ(a.objects.size(), e.objects.size()) << "object count";
        for (std::size_t o = 0; o < a.objects.size(); ++o) {
            const Object &x = a.objects[o], &y = e.objects[o];
            const std::string w = "objects[" + std::to_string(o) + "] " + y.name;
            EXPECT_EQ(x.name, y.name) << w;
            ASSERT_EQ(x.mesh, y.mesh) << w << " mesh";
            EXPECT_EQ(x.material, y.material) << w << " material";
            mat(x.worldFromModel, y.worldFromModel, w + " worldFromModel");
            vec(x.spin.axis, y.spin.axis, w + " spin.axis");
            num(x.spin.degreesPerSecond, y.spin.degreesPerSecond, w + " spin.degreesPerSecond");
            vec(x.spin.pivot, y.spin.pivot, w + " spin.pivot");
            EXPECT_EQ(x.castsShadows, y.castsShadows) << w << " castsShadows";
            EXPECT_EQ(x.receivesShadows, y.receivesShadows) << w << " receivesShadows";
            // The triangles where they are drawn, posed at a time the spin matters.
            const glm::mat4 xa = x.worldFromModelAt(1.5), ya = y.worldFromModelAt(1.5);
            const Mesh &xm = a.meshes[x.mesh], &ym = e.meshes[y.mesh];
            for (std::size_t i = 0; i < std::min(xm.positions.size(), ym.positions.size()); ++i) {
                vec(glm::vec3(xa * glm::vec4(xm.positions[i], 1.0f)),
                    glm::vec3(ya * glm::vec4(ym.positions[i], 1.0f)),
                    w + " world position " + std::to_string(i));
            }
        }
    }

    void scene(const Scene& a, const Scene& e) const {
        EXPECT_EQ(a.name, e.name);
        EXPECT_EQ(a.description, e.description);
        geometry(a, e);
        ASSERT_EQ(a.lights.size(), e.lights.size()) << "light count";
        for (std::size_t l = 0; l < a.lights.size(); ++l)
            light(a.lights[l], e.lights[l], "lights[" + std::to_string(l) + "]");
        camera(a.camera, e.camera);
        vec(a.ambient, e.ambient, "ambient");
        options(a.options, e.options, "options");
        ASSERT_EQ(a.textbookOptions.has_value(), e.textbookOptions.has_value());
        if (e.textbookOptions) options(*a.textbookOptions, *e.textbookOptions, "textbook options");
    }
};

std::string readText(const fs::path& p) {
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void writeText(const fs::path& p, const std::string& text) {
    std::ofstream(p) << text;
}

// The message loading `path` fails with ("" when it loads).
std::string errorOf(const std::string& path) {
    try {
        (void)loadSceneFile(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

// The message a file with `text` fails with.
std::string errorOfText(const ScopedTempDir& dir, const std::string& text) {
    const fs::path p = dir.path() / "bad.json";
    writeText(p, text);
    return errorOf(p.string());
}

// ---- The built-in scenes are expressible

TEST(SceneFile, ExamplesLoadToTheBuiltinScenes) {
    for (const char* name : kExampleNames) {
        SCOPED_TRACE(name);
        const std::string path = kExamples + "/" + name + ".json";
        const Scene fromFile = loadSceneFile(path);
        const Scene builtin = builtinScene(name);
        Compare{false}.scene(fromFile, builtin);
        EXPECT_TRUE(fromFile.warnings.empty()) << fromFile.warnings.front();
        // The CLI's way in: loadScene dispatches .json here.
        EXPECT_EQ(loadScene(path).objects.size(), builtin.objects.size());
    }
}

TEST(SceneFile, EveryExampleIsABuiltinScene) {
    int files = 0;
    for (const auto& entry : fs::directory_iterator(kExamples)) {
        if (entry.path().extension() != ".json") continue;
        ++files;
        EXPECT_NO_THROW((void)builtinScene(entry.path().stem().string())) << entry.path();
    }
    EXPECT_EQ(files, 6);
}

// The failures `compare` reports, joined (the reporter keeps them from failing this test).
template <typename F>
std::string failuresOf(F compare) {
    ::testing::TestPartResultArray results;
    {
        ::testing::ScopedFakeTestPartResultReporter reporter(
            ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &results);
        compare();
    }
    std::string all;
    for (int i = 0; i < results.size(); ++i)
        all += std::string(results.GetTestPartResult(i).message()) + "\n";
    return all;
}

// The comparison above can fail: a changed number anywhere is caught.
TEST(SceneFile, ComparisonNoticesDifferences) {
    const Scene builtin = builtinScene("course-cubes");
    EXPECT_EQ(failuresOf([&] { Compare{false}.scene(builtin, builtin); }), "");
    Scene changed = builtin;
    changed.lights[1].shadowCamera.far = 21.0f;
    EXPECT_NE(failuresOf([&] {
                  Compare{false}.scene(changed, builtin);
              }).find("lights[1] shadowCamera.far"),
              std::string::npos);
    changed = builtin;
    changed.meshes[0].positions[5].y += 1e-4f;
    const std::string moved = failuresOf([&] { Compare{false}.scene(changed, builtin); });
    EXPECT_NE(moved.find("meshes[0].positions[5][1]"), std::string::npos) << moved;
    EXPECT_NE(moved.find("objects[7] z cube world position 5[1]"), std::string::npos) << moved;
    changed = builtin;
    changed.objects[6].worldFromModel[3][0] += 1e-5f;
    EXPECT_NE(failuresOf([&] {
                  Compare{false}.scene(changed, builtin);
              }).find("objects[6] y cube worldFromModel[3][0]"),
              std::string::npos);
    changed = builtin;
    changed.textbookOptions->shadow.biasConstant = 0.001f;
    EXPECT_NE(failuresOf([&] {
                  Compare{false}.scene(changed, builtin);
              }).find("textbook options biasConstant"),
              std::string::npos);
    changed = builtin;
    changed.options.shadow.cull = CullMode::Front;
    EXPECT_NE(failuresOf([&] { Compare{true}.scene(changed, builtin); }).find("options cull"),
              std::string::npos);
}

// ---- Save and load back

RenderOptions everyOptionChanged() {
    RenderOptions o;
    o.width = 320;
    o.height = 200;
    o.time = 2.25;
    o.lightOnly = 1;
    o.debugView = DebugView::LightFrusta;
    ShadowOptions& s = o.shadow;
    s.enabled = false;
    s.outside = OutsidePolicy::Clamp;
    s.biasConstant = 0.0013f;
    s.biasDepthAware = 2.5f;
    s.biasSlope = 0.7f;
    s.biasUnits = 3.1f;
    s.normalOffset = 0.35f;
    s.receiverPlane = false;
    s.cull = CullMode::Front;
    s.filter = ShadowFilter::Poisson;
    s.pcfSize = 7;
    s.lightRadius = 0.123f;
    s.lightAngle = 2.5f;
    s.mapSize = 768;
    s.cascades = 3;
    s.fitTo = FitTo::Boxes;
    s.cascadeLambda = 0.3f;
    s.cascadeBlend = 0.2f;
    s.depthFormat = DepthFormat::Rgba8Packed256;
    s.mapFilter = MapFilter::Linear;
    s.blendShadows = BlendShadows::None;
    o.shading.shadowedRule = ShadowedRule::Factor;
    o.shading.shadowFactor = 0.45f;
    o.shading.output = OutputEncoding::Srgb;
    EXPECT_TRUE(o.validate().empty());
    return o;
}

TEST(SceneFile, SavedFileReproducesWhatWasTuned) {
    ScopedTempDir dir;
    const Scene builtin = builtinScene("tutorial-room");
    Scene tuned = builtin;
    tuned.lights[0].direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    tuned.lights[0].intensity = 0.6f;
    tuned.lights[0].shadowCamera.policy = ShadowCameraPolicy::Manual;
    tuned.lights[0].position = {-9.0f, 27.0f, -18.0f};
    Light spot;
    spot.name = "desk \"lamp\"";
    spot.type = LightType::Spot;
    spot.enabled = false;
    spot.position = {1.5f, 7.25f, -0.1f};
    spot.direction = glm::normalize(glm::vec3(-0.1f, -1.0f, 0.05f));
    spot.colour = {0.9f, 0.8f, 0.1f / 3.0f};
    spot.intensity = 123.456f;
    spot.attenuation = {0.5f, 0.25f, 0.0625f};
    spot.innerConeDegrees = 12.5f;
    spot.outerConeDegrees = 33.3f;
    spot.castsShadows = false;
    spot.shadowMapSize = 333;
    spot.shadowCamera = {ShadowCameraPolicy::Course,
                         Projection::Orthographic,
                         {1, 2, 3},
                         {0, 0, 1},
                         61.0f,
                         1.5f,
                         0.3f,
                         70.0f,
                         -3.0f,
                         4.0f,
                         -5.0f,
                         6.0f};
    tuned.lights.push_back(spot);
    tuned.camera = Camera{{-12.5f, 8.1f, -2.9f},
                          {2.0f, 1.1f, 3.3f},
                          {0.0f, 1.0f, 0.1f},
                          Projection::Orthographic,
                          47.5f,
                          1.25f,
                          0.7f,
                          91.0f,
                          -11.0f,
                          12.0f,
                          -13.0f,
                          14.0f};
    tuned.ambient = {0.15f, 0.1f, 0.05f};
    const RenderOptions options = everyOptionChanged();

    const fs::path saved = dir.path() / "tuned.json";
    saveSceneFile(saved.string(), "tutorial-room", tuned, options);
    // Written by rename: nothing else is left in the folder.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);
    const std::string text = readText(saved);
    EXPECT_NE(text.find("\"scene\": \"tutorial-room\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"bias-constant\": 0.0013,"), std::string::npos) << "shortest floats";

    const Scene back = loadSceneFile(saved.string());
    const Compare exact{true};
    ASSERT_EQ(back.lights.size(), 2u);
    for (std::size_t l = 0; l < 2; ++l)
        exact.light(back.lights[l], tuned.lights[l], "lights[" + std::to_string(l) + "]");
    exact.camera(back.camera, tuned.camera);
    exact.vec(back.ambient, tuned.ambient, "ambient");
    exact.options(back.options, options, "options");
    // The geometry and the textbook's options come from the included built-in.
    exact.geometry(back, builtin);
    ASSERT_TRUE(back.textbookOptions.has_value());
    exact.options(*back.textbookOptions, *builtin.textbookOptions, "textbook options");
    EXPECT_TRUE(back.warnings.empty());
}

TEST(SceneFile, SavedFileIncludesAModelRelativeToItsFolder) {
    ScopedTempDir dir;
    fs::create_directories(dir.path() / "models" / "book");
    fs::create_directories(dir.path() / "saves");
    const fs::path model = dir.path() / "models" / "book" / "triangle.json";
    fs::copy_file(kExamples + "/book-triangle.json", model);
    const Scene source = loadSceneFile(model.string());
    const fs::path saved = dir.path() / "saves" / "mine.json";
    saveSceneFile(saved.string(), model.string(), source, source.options);
    EXPECT_NE(readText(saved).find("\"scene\": \"../models/book/triangle.json\""),
              std::string::npos)
        << readText(saved);
    const Scene back = loadSceneFile(saved.string());
    Compare{false}.scene(back, builtinScene("book-triangle"));
}

TEST(SceneFile, SaveRefusesNumbersJsonCannotHold) {
    ScopedTempDir dir;
    Scene s = builtinScene("tutorial-room");
    s.lights[0].position.y = std::numeric_limits<float>::quiet_NaN();
    const fs::path p = dir.path() / "nan.json";
    try {
        saveSceneFile(p.string(), "tutorial-room", s, s.options);
        FAIL() << "saved a NaN";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("lights[0].position[1] is not a finite number"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(fs::exists(p));
}

// ---- Includes

TEST(SceneFile, IncludedSceneIsPlacedAndItsOptionsTuned) {
    ScopedTempDir dir;
    const fs::path p = dir.path() / "moved.json";
    writeText(p, R"({
        "gnomon-scene": 1,
        "include": [{"scene": "tutorial-room",
                     "transform": [{"translate": [0, 0, 5]}, {"rotate": {"axis": [0, 1, 0], "degrees": 90}}]}],
        "options": {"map-size": 512, "filter": "pcss"}
    })");
    const Scene s = loadSceneFile(p.string());
    const Scene room = builtinScene("tutorial-room");
    EXPECT_EQ(s.name, "moved");
    ASSERT_EQ(s.objects.size(), room.objects.size());
    const glm::mat4 t = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 5)),
                                    glm::radians(90.0f), glm::vec3(0, 1, 0));
    for (std::size_t o = 0; o < s.objects.size(); ++o)
        Compare{false}.mat(s.objects[o].worldFromModel, t * room.objects[o].worldFromModel,
                           "objects[" + std::to_string(o) + "]");
    // The room's sun and camera move with it.
    ASSERT_EQ(s.lights.size(), 1u);
    Compare{false}.vec(s.lights[0].direction, glm::mat3(t) * room.lights[0].direction, "sun");
    Compare{false}.vec(s.camera.eye, glm::vec3(t * glm::vec4(room.camera.eye, 1.0f)), "eye");
    // Options: the room's, with the file's keys over them; its textbook options kept.
    RenderOptions expected = room.options;
    expected.shadow.mapSize = 512;
    expected.shadow.filter = ShadowFilter::Pcss;
    Compare{true}.options(s.options, expected, "options");
    Compare{true}.options(*s.textbookOptions, *room.textbookOptions, "textbook");
}

TEST(SceneFile, FilesIncludeFilesRelativeToTheirFolder) {
    ScopedTempDir dir;
    fs::create_directories(dir.path() / "parts");
    writeText(dir.path() / "parts" / "crate.json", R"({
        "gnomon-scene": 1,
        "materials": {"wood": {"colour": [0.6, 0.4, 0.2]}},
        "objects": [{"name": "crate", "shape": "box", "size": 1, "material": "wood"}],
        "lights": [{"type": "directional", "direction": [0, -2, 0]}]
    })");
    writeText(dir.path() / "yard.json", R"({
        "gnomon-scene": 1,
        "include": [{"scene": "parts/crate.json"},
                    {"scene": "parts/crate.json", "transform": {"translate": [3, 0, 0], "scale": 2}}],
        "objects": [{"name": "ground", "shape": "quad",
                     "corners": [[-5, -0.5, 5], [5, -0.5, 5], [5, -0.5, -5], [-5, -0.5, -5]]}],
        "camera": {"eye": [0, 5, 10]}
    })");
    const Scene s = loadSceneFile((dir.path() / "yard.json").string());
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_EQ(s.meshes.size(), 3u);
    EXPECT_EQ(s.materials.size(), 3u);  // wood twice, and the default for the ground
    EXPECT_EQ(s.materials[s.objects[2].material].name, "default");
    Compare{false}.vec(glm::vec3(s.objects[1].worldFromModelAt(0) * glm::vec4(0.5f, 0.5f, 0.5f, 1)),
                       {4.0f, 1.0f, 1.0f}, "scaled crate corner");
    // Lights of both includes (the directions normalized), the file's camera.
    ASSERT_EQ(s.lights.size(), 2u);
    Compare{false}.vec(s.lights[1].direction, {0, -1, 0}, "direction");
    Compare{false}.vec(s.camera.eye, {0, 5, 10}, "eye");
}

TEST(SceneFile, WithoutLightsOrCameraASunAndAFramingCameraAreAdded) {
    ScopedTempDir dir;
    const fs::path p = dir.path() / "bare.json";
    writeText(p, R"({"gnomon-scene": 1, "objects": [{"shape": "box", "size": [2, 1, 2]}]})");
    const Scene s = loadSceneFile(p.string());
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, LightType::Directional);
    ASSERT_EQ(s.warnings.size(), 2u);
    EXPECT_GT(glm::length(s.camera.eye - s.camera.centre), 1.0f);
    // An explicit empty list means no lights, and nothing is said.
    writeText(p, R"({"gnomon-scene": 1, "objects": [{"shape": "box", "size": 1}], "lights": [],
                     "camera": {"eye": [0, 0, 4]}})");
    const Scene dark = loadSceneFile(p.string());
    EXPECT_TRUE(dark.lights.empty());
    EXPECT_TRUE(dark.warnings.empty());
}

TEST(SceneFile, GroundAddsAReceiverThatDoesNotMoveTheCamera) {
    ScopedTempDir dir;
    const fs::path p = dir.path() / "ground.json";
    writeText(p, R"({"gnomon-scene": 1, "objects": [{"shape": "box", "size": [2, 1, 2]}]})");
    const Scene bare = loadSceneFile(p.string());
    writeText(p, R"({"gnomon-scene": 1, "objects": [{"shape": "box", "size": [2, 1, 2]}],
                     "ground": true})");
    const Scene grounded = loadSceneFile(p.string());
    ASSERT_EQ(grounded.objects.size(), bare.objects.size() + 1);
    EXPECT_FALSE(grounded.objects.back().castsShadows);
    EXPECT_EQ(grounded.camera.eye, bare.camera.eye);
    EXPECT_LT(grounded.meshes[grounded.objects.back().mesh].positions[0].y, -0.5f);
}

TEST(SceneFile, MeshShapeWithFlatListsAndGeneratedNormals) {
    ScopedTempDir dir;
    const fs::path p = dir.path() / "mesh.json";
    writeText(p, R"({
        "gnomon-scene": 1,
        /* a square from two triangles, counter-clockwise seen from +z */
        "objects": [{"name": "square", "shape": "mesh",
                     "positions": [0, 0, 0,  1, 0, 0,  1, 1, 0,  0, 1, 0],
                     "indices": [0, 1, 2, 0, 2, 3], "colours": [0.5, 0.25, 1],
                     "casts-shadows": false, "receives-shadows": false}],
        "lights": [], "camera": {"eye": [0, 0, 3]}
    })");
    const Scene s = loadSceneFile(p.string());
    ASSERT_EQ(s.meshes.size(), 1u);
    const Mesh& m = s.meshes[0];
    EXPECT_EQ(m.positions.size(), 4u);
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
    for (const glm::vec3& n : m.normals)
        Compare{false}.vec(n, {0, 0, 1}, "normal");
    Compare{false}.vecs(m.colours, std::vector<glm::vec3>(4, {0.5f, 0.25f, 1.0f}), "colours");
    EXPECT_FALSE(s.objects[0].castsShadows);
    EXPECT_FALSE(s.objects[0].receivesShadows);
}

// ---- Mistakes: each names the file, the JSON path and what is wrong

struct Case {
    const char* file;
    std::vector<const char*> says;
};

TEST(SceneFile, BrokenFilesInTheCorpusAreRefusedWithThePath) {
    const std::vector<Case> cases = {
        {"bad_json.json", {"bad_json.json: not valid JSON: parse error at line 1"}},
        {"unknown_key.json",
         {"unknown_key.json: objects[0]: unknown key \"colour\" (known keys: name, mesh, shape, "
          "material, transform, spin, casts-shadows, receives-shadows, centre, size, colours)"}},
        {"wrong_type.json",
         {"wrong_type.json: lights[0].intensity: expected a number, got \"bright\""}},
        {"bad_enum.json",
         {"bad_enum.json: lights[2].type: expected one of directional, spot, point, area, got "
          "\"sun\""}},
        {"index_out_of_range.json",
         {"index_out_of_range.json: objects[0].indices[4]: index 9 is out of range (4 "
          "positions)"}},
        {"cycle_a.json",
         {"cycle_b.json: include[0].scene: include cycle: cycle_a.json -> cycle_b.json -> "
          "cycle_a.json",
          "(included by "}},
        {"self_include.json",
         {"self_include.json: include[0].scene: include cycle: self_include.json -> "
          "self_include.json"}},
        {"missing_include.json",
         {"missing_include.json: include[0].scene: no such file", "nothing-here.gltf"}},
        {"bad_option.json",
         {"bad_option.json: options: map-size must be 0 (each light's own) or in 64..8192, got "
          "10"}},
        {"duplicate_key.json", {"duplicate_key.json: options: duplicate key \"filter\""}},
    };
    for (const Case& c : cases) {
        const std::string path = kCorpus + "/" + c.file;
        const std::string message = errorOf(path);
        ASSERT_FALSE(message.empty()) << c.file << " loaded";
        EXPECT_EQ(message.rfind(path.substr(0, path.size() - std::string(c.file).size()), 0), 0u)
            << "message does not start with the file: " << message;
        for (const char* s : c.says)
            EXPECT_NE(message.find(s), std::string::npos) << c.file << ": " << message;
    }
    // The one valid file of the corpus loads.
    const Scene ok = loadSceneFile(kCorpus + "/include_and_tune.json");
    ASSERT_EQ(ok.lights.size(), 1u);
    EXPECT_EQ(ok.lights[0].type, LightType::Spot);
    EXPECT_EQ(ok.options.shadow.filter, ShadowFilter::Pcss);
}

TEST(SceneFile, MoreMistakesAreRefusedWithThePath) {
    ScopedTempDir dir;
    const std::vector<std::pair<std::string, std::string>> cases = {
        {R"({"objects": []})", "bad.json: missing required key \"gnomon-scene\""},
        {R"({"gnomon-scene": 2})",
         "bad.json: gnomon-scene: this gnomon reads format version 1, got 2"},
        {R"([1, 2])", "bad.json: expected an object {...}, got an array"},
        {R"({"gnomon-scene": 1, "lightz": []})",
         "bad.json: unknown key \"lightz\" (known keys: gnomon-scene, name, description, include, "
         "materials, meshes, objects, lights, camera, ambient, ground, options, textbook-options)"},
        {R"({"gnomon-scene": 1, "lights": [{"position": [0, 1, 0]}]})",
         "bad.json: lights[0]: missing required key \"type\""},
        {R"({"gnomon-scene": 1, "lights": [{"type": "point", "position": [0, 1]}]})",
         "bad.json: lights[0].position: expected [x, y, z] (3 numbers), got an array"},
        {R"({"gnomon-scene": 1, "lights": [{"type": "point", "shadow-map-size": 10}]})",
         "bad.json: lights[0].shadow-map-size: expected an integer in 64..8192, got 10"},
        {R"({"gnomon-scene": 1, "lights": [{"type": "spot", "inner-cone": 50, "outer-cone": 40}]})",
         "bad.json: scene 'bad': lights[0] ('light 0') spot cone needs 0 <= inner <= outer < 90"},
        {R"({"gnomon-scene": 1, "camera": {"eye": [0, 0, 5], "far": 1e300}})",
         "bad.json: camera.far: the number 1e+300 is too large for a 32-bit float"},
        {R"({"gnomon-scene": 1, "camera": {"projection": "fisheye"}})",
         "bad.json: camera.projection: expected one of perspective, orthographic, got \"fisheye\""},
        {R"({"gnomon-scene": 1, "options": {"cascades": "many"}})",
         "bad.json: options.cascades: expected \"auto\" or a count 1..4, got \"many\""},
        {R"({"gnomon-scene": 1, "options": {"cascades": 5}})",
         "bad.json: options: cascades must be auto (0) or in 1..4, got 5"},
        {R"({"gnomon-scene": 1, "options": {"fit-to": "sky"}})",
         "bad.json: options.fit-to: expected one of view-depth, boxes, got \"sky\""},
        {R"({"gnomon-scene": 1, "options": {"filter": "blurry"}})",
         "bad.json: options.filter: expected one of none, hw2x2, pcf, poisson, pcss, got "
         "\"blurry\""},
        {R"({"gnomon-scene": 1, "options": {"size": "big"}})",
         "bad.json: options.size: expected \"WIDTHxHEIGHT\" such as \"512x512\", got \"big\""},
        {R"({"gnomon-scene": 1, "options": {"shadows": "off"}})",
         "bad.json: options.shadows: expected true or false, got \"off\""},
        {R"({"gnomon-scene": 1, "options": {"pcf-size": 2.5}})",
         "bad.json: options.pcf-size: expected an integer"},
        {R"({"gnomon-scene": 1, "textbook-options": {"shadow-factor": 2}})",
         "bad.json: textbook-options: shadow-factor must be in [0, 1], got 2"},
        {R"({"gnomon-scene": 1, "materials": {"m": {"colour": [1, 0, 0]}}, "objects": [{"shape": "box", "size": 1, "material": "n"}]})",
         "bad.json: objects[0].material: no material \"n\" in materials (known: m)"},
        {R"({"gnomon-scene": 1, "materials": {"vertex colour": {"specular": 2}}})",
         "bad.json: materials[\"vertex colour\"].specular: expected a number in [0, 1], got 2"},
        {R"({"gnomon-scene": 1, "objects": [{"mesh": "cube"}]})",
         "bad.json: objects[0].mesh: no mesh \"cube\" in meshes (there are none)"},
        {R"({"gnomon-scene": 1, "objects": [{"name": "x"}]})",
         "bad.json: objects[0]: needs \"shape\" (box, quad, triangle, mesh) or \"mesh\""},
        {R"({"gnomon-scene": 1, "objects": [{"shape": "sphere"}]})",
         "bad.json: objects[0].shape: expected one of box, quad, triangle, mesh, got \"sphere\""},
        {R"({"gnomon-scene": 1, "objects": [{"shape": "quad", "corners": [[0,0,0],[1,0,0],[2,0,0],[3,0,0]]}]})",
         "bad.json: objects[0].corners: the first three corners lie on a line"},
        {R"({"gnomon-scene": 1, "objects": [{"shape": "box", "size": 1, "transform": {"matrix": [1, 0, 0], "scale": 2}}]})",
         "bad.json: objects[0].transform: \"matrix\" cannot be combined with translate, rotate or "
         "scale"},
        {R"({"gnomon-scene": 1, "objects": [{"shape": "box", "size": 1, "transform": {"rotate": {"axis": [0, 0, 0], "degrees": 5}}}]})",
         "bad.json: objects[0].transform.rotate.axis: the rotation axis is zero"},
        {R"({"gnomon-scene": 1, "objects": [{"shape": "mesh", "positions": [0, 0, 0, 1, 0, 0, 0, 1, 0], "normals": [[0, 0, 1]]}]})",
         "bad.json: objects[0].normals: expected 3 normals (one per position), got 1"},
        {R"({"gnomon-scene": 1, "include": [{"scene": "no-such-scene"}]})",
         "bad.json: include[0].scene: unknown scene 'no-such-scene' (built-in scenes: "
         "book-triangle"},
        {R"({"gnomon-scene": 1, "include": [{"scene": "tutorial-room", "light": false}]})",
         "bad.json: include[0]: unknown key \"light\" (known keys: scene, transform, lights, "
         "camera)"},
        {"{\"gnomon-scene\": 1, \"objects\": " + std::string(100, '[') + std::string(100, ']') +
             "}",
         "bad.json: objects[0][0][0]"},
    };
    for (const auto& [text, says] : cases) {
        const std::string message = errorOfText(dir, text);
        EXPECT_NE(message.find(says), std::string::npos)
            << text << "\n  gave: " << (message.empty() ? "no error" : message);
        EXPECT_EQ(message.rfind((dir.path() / "bad.json").string() + ": ", 0), 0u) << message;
    }
}

TEST(SceneFile, UnreadableFilesAreIoErrors) {
    ScopedTempDir dir;
    try {
        (void)loadSceneFile((dir.path() / "absent.json").string());
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Io);
        EXPECT_NE(std::string(e.what()).find("absent.json': no such file"), std::string::npos);
    }
    // Too large: refused before reading (a sparse file, nothing is written).
    const fs::path big = dir.path() / "big.json";
    writeText(big, "{}");
    fs::resize_file(big, (std::uintmax_t(64) << 20) + 1);
    const std::string message = errorOf(big.string());
    EXPECT_NE(message.find("scene files are limited to 64 MiB"), std::string::npos) << message;
}

}  // namespace
}  // namespace gnomon
