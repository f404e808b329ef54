// Scene description files (docs/scene-file.md): the built-in scenes written in the format load
// to the very same scenes, a saved file reproduces what was tuned, and every kind of mistake
// is refused with the file and the JSON path.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "OptionValues.h"
#include "SceneFileTestUtil.h"

namespace gnomon {
namespace {

using namespace test;

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
              }).find("textbook options bias-constant"),
              std::string::npos);
    changed = builtin;
    changed.options.shadow.cull = CullMode::Front;
    EXPECT_NE(failuresOf([&] { Compare{true}.scene(changed, builtin); }).find("options cull"),
              std::string::npos);
}

// ---- Save and load back

// Every option of the schema set to a value other than its default (OptionValues.h), so the
// round trip below covers each one, a new option included.
RenderOptions everyOptionChanged() {
    const RenderOptions defaults;
    RenderOptions o;
    for (const OptionSpec& spec : optionSchema()) {
        const std::string value = otherValue(spec, defaults);
        EXPECT_EQ(parseOption(spec, value, o), std::nullopt) << spec.name << " " << value;
    }
    EXPECT_TRUE(o.validate().empty());
    for (const OptionSpec& spec : optionSchema())
        EXPECT_FALSE(sameOption(spec, o, defaults)) << spec.name << " kept its default";
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
    // Floats as their shortest text.
    EXPECT_NE(text.find("\"light-bleed\": 0.495"), std::string::npos) << text;

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

// A light without a map size is saved without one, so it keeps its default when read.
TEST(SceneFile, ALightWithoutAMapSizeIsSavedWithoutOne) {
    ScopedTempDir dir;
    Scene s = builtinScene("tutorial-room");
    s.lights[0].shadowMapSize = 0;
    const fs::path saved = dir.path() / "sun.json";
    saveSceneFile(saved.string(), "tutorial-room", s, s.options);
    EXPECT_EQ(readText(saved).find("shadow-map-size"), std::string::npos);
    const Scene back = loadSceneFile(saved.string());
    ASSERT_EQ(back.lights.size(), 1u);
    EXPECT_EQ(back.lights[0].shadowMapSize, 0);
    EXPECT_EQ(shadowMapSizeOf(back.lights[0]), 2048);
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

TEST(SceneFile, LightTilesReadAsTheSwitchTheyWere) {
    // Files written when --light-tiles was on|off keep their meaning: true is auto.
    ScopedTempDir dir;
    const std::pair<const char*, LightTiles> cases[] = {{"true", LightTiles::Auto},
                                                        {"false", LightTiles::Off},
                                                        {"\"lists\"", LightTiles::Lists},
                                                        {"\"draws\"", LightTiles::Draws}};
    for (const auto& [value, mode] : cases) {
        const fs::path p = dir.path() / "tiles.json";
        writeText(p, std::string(R"({"gnomon-scene": 1, "include": [{"scene": "tutorial-room"}],
                                    "options": {"light-tiles": )") +
                         value + "}}");
        EXPECT_EQ(loadSceneFile(p.string()).options.shading.lightTiles, mode) << value;
    }
}

}  // namespace
}  // namespace gnomon
