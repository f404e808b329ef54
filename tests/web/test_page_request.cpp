// The web page's address and scene (apps/web/PageRequest.h) and the light its picture shows
// (TruthPicture.h), natively and without a browser: keys and escapes, the CLI's words for
// bad values, models found in the bundle by folder, and views written as addresses that read
// back as the same view.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "PageEdits.h"
#include "PageRequest.h"
#include "TruthPicture.h"
#include "gnomon/Error.h"
#include "gnomon/OptionSchema.h"

namespace gnomon::web {
namespace {

namespace fs = std::filesystem;

std::string errorOf(const std::string& address, const std::string& bundle = "") {
    try {
        loadRequest(parseAddress(address), bundle);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(PageAddress, ReadsSceneKeysAndOptionsWithOrWithoutTheHash) {
    const PageRequest r = parseAddress("#scene=tutorial-spot&map-size=64&&size=96x96");
    EXPECT_EQ(r.scene, "tutorial-spot");
    EXPECT_EQ(r.options.at("map-size"), "64");
    EXPECT_EQ(r.options.at("size"), "96x96");
    EXPECT_EQ(parseAddress("preset=textbook").preset, Preset::Textbook);
    EXPECT_EQ(parseAddress("").scene, "book-triangle");
}

TEST(PageAddress, DecodesEscapesAndPluses) {
    EXPECT_EQ(parseAddress("#scene=Duck%2FDuck.glb").scene, "Duck/Duck.glb");
    EXPECT_EQ(parseAddress("#scene=my+model.glb").scene, "my model.glb");
    EXPECT_EQ(parseAddress("#scene=100%").scene, "100%");  // a stray '%' stays
}

TEST(PageAddress, GroundIsAFlagOrOnOrOff) {
    EXPECT_TRUE(parseAddress("#ground").ground);
    EXPECT_TRUE(parseAddress("#ground=on").ground);
    EXPECT_FALSE(parseAddress("#ground=off").ground);
    EXPECT_THROW(parseAddress("#ground=maybe"), Error);
}

TEST(PageAddress, PictureIsTheRenderUnlessTruthOrScoreIsAsked) {
    using Picture = PageRequest::Picture;
    EXPECT_EQ(parseAddress("#scene=book-triangle").picture, Picture::Render);
    EXPECT_EQ(parseAddress("#picture=render").picture, Picture::Render);
    EXPECT_EQ(parseAddress("#picture=truth").picture, Picture::Truth);
    EXPECT_EQ(parseAddress("#picture=score").picture, Picture::Score);
    EXPECT_THROW(parseAddress("#picture=raytraced"), Error);
}

TEST(PageAddress, RefusesUnknownAndRepeatedKeysAndBadPresets) {
    EXPECT_EQ(errorOf("#map-sise=64"),
              "unknown option in the address: 'map-sise'; did you "
              "mean map-size?");
    EXPECT_EQ(errorOf("#size=64x64&size=32x32"), "the address gives 'size' twice");
    EXPECT_EQ(errorOf("#preset=book"), "--preset: expected one of default, textbook, got 'book'");
}

TEST(PageScene, BadValuesAreRefusedInTheCliWords) {
    EXPECT_EQ(errorOf("#scene=book-triangle&map-size=abc"),
              "--map-size: expected an integer, got 'abc'");
    EXPECT_EQ(errorOf("#scene=book-triangle&map-size=5"),
              "map-size must be 0 or in 64..8192, got 5");
    EXPECT_NE(errorOf("#scene=book-triangl").find("did you mean book-triangle?"),
              std::string::npos);
}

TEST(PageScene, OptionsApplyOverThePresetWithTheCliWarnings) {
    const PageScene s =
        loadRequest(parseAddress("#scene=book-triangle&size=96x64&filter=none&pcf-size=5"), "");
    EXPECT_EQ(s.options.width, 96);
    EXPECT_EQ(s.options.height, 64);
    EXPECT_EQ(s.options.shadow.filter, ShadowFilter::None);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0].rfind("--pcf-size does nothing here", 0), 0u) << s.warnings[0];
}

TEST(PageScene, FindsABundledModelByItsFolderAndRefusesAFolderOfTwo) {
    const fs::path bundle = fs::path(testing::TempDir()) / "gnomon_page_bundle";
    fs::remove_all(bundle);
    fs::create_directories(bundle / "Tri");
    fs::create_directories(bundle / "Two");
    const fs::path triangle = fs::path(GNOMON_GLTF_CORPUS) / "triangle.gltf";
    fs::copy_file(triangle, bundle / "Tri" / "tri.gltf");
    fs::copy_file(triangle, bundle / "Two" / "a.gltf");
    fs::copy_file(triangle, bundle / "Two" / "b.gltf");
    const PageScene s = loadRequest(parseAddress("#scene=Tri"), bundle.string());
    EXPECT_EQ(s.scene.objects.size(), 1u);
    EXPECT_NO_THROW(loadRequest(parseAddress("#scene=Tri/tri.gltf"), bundle.string()));
    EXPECT_NE(errorOf("#scene=Two", bundle.string()).find("the folder holds 2 glTF files"),
              std::string::npos);
    fs::remove_all(bundle);
}

TEST(PagePicture, ShowsLightOnlysLightElseTheFirstShadowedOne) {
    Scene scene = builtinScene("course-two-lights");
    RenderOptions o = scene.options;
    EXPECT_EQ(pictureLight(scene, o), 0);
    scene.lights[0].castsShadows = false;
    EXPECT_EQ(pictureLight(scene, o), 1);
    o.lightOnly = 0;
    EXPECT_EQ(pictureLight(scene, o), 0);
    scene.lights.clear();
    EXPECT_EQ(pictureLight(scene, o), -1);
}

// A view as the page holds it: the request it was loaded from, the scene as loaded, the scene
// and options as the user has changed them.
struct View {
    PageRequest base;
    PageScene loaded;
    Scene edited;
    RenderOptions options;
};

View viewOf(const std::string& address) {
    View v;
    v.base = parseAddress(address);
    v.loaded = loadRequest(v.base, "");
    v.edited = v.loaded.scene;
    v.options = v.loaded.options;
    return v;
}

std::string addressOf(const View& v, bool withSize = true) {
    return writeAddress(v.base, v.loaded.scene, v.edited, v.options, withSize);
}

// The view's address read back as the page reads a link: the same camera, lights, ambient and
// options, every float exactly (the writer prints each float's shortest exact text).
void expectSameView(const View& v, bool withSize = true) {
    const std::string address = addressOf(v, withSize);
    SCOPED_TRACE(address);
    const PageScene r = loadRequest(parseAddress(address), "");
    EXPECT_TRUE(r.scene.camera == v.edited.camera);
    ASSERT_EQ(r.scene.lights.size(), v.edited.lights.size());
    for (std::size_t i = 0; i < r.scene.lights.size(); ++i)
        EXPECT_TRUE(r.scene.lights[i] == v.edited.lights[i]) << "light " << i;
    EXPECT_TRUE(r.scene.ambient == v.edited.ambient);
    for (const OptionSpec& spec : optionSchema())
        EXPECT_EQ(formatOption(spec, r.options), formatOption(spec, v.options)) << spec.name;
    EXPECT_TRUE(r.options == v.options);
}

void setOption(RenderOptions& o, const char* name, const std::string& text) {
    ASSERT_FALSE(parseOption(*findOption(name), text, o).has_value()) << name;
}

TEST(PageAddressWrite, AnUneditedViewIsTheSceneAlone) {
    for (const SceneInfo& info : builtinScenes()) {
        const View v = viewOf("#scene=" + info.name);
        EXPECT_EQ(addressOf(v), "#scene=" + info.name);
    }
}

// Several scenes, each with its camera moved and its planes and field of view changed, a
// light dragged and retuned, another switched off, the ambient and options changed.
TEST(PageAddressWrite, EditedViewsReadBackExactly) {
    for (const char* name : {"book-triangle", "course-two-lights", "tutorial-spot",
                             "tutorial-point", "tutorial-directional", "mixed-lights"}) {
        SCOPED_TRACE(name);
        View v = viewOf(std::string("#scene=") + name);
        Camera& c = v.edited.camera;
        c.eye += glm::vec3(0.1f, -1.0f / 3.0f, 1e-3f);
        c.centre += glm::vec3(0.25f, 0.0f, -0.7f);
        c.fovyDegrees = 33.3f;
        c.near = 0.123f;
        Light& l = v.edited.lights.back();
        l.position += glm::vec3(0.1f, 0.2f, std::sqrt(2.0f));
        l.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
        l.intensity *= 1.7f;
        l.colour = {0.9f, 0.123456f, 1.0f};
        l.shadowMapSize = 512;
        l.innerConeDegrees = 12.5f;
        l.outerConeDegrees = 27.25f;
        l.attenuation = {1.0f, 0.01f, 0.0025f};
        l.range = 35.5f;
        v.edited.lights.front().enabled = v.edited.lights.size() == 1;
        v.edited.ambient = {0.05f, 0.07f, 0.3f};
        setOption(v.options, "map-size", "512");
        setOption(v.options, "filter",
                  v.options.shadow.filter == ShadowFilter::Poisson ? "pcf" : "poisson");
        v.options.shadow.biasSlope = 0.123456789f;
        setOption(v.options, "size", "333x222");
        setOption(v.options, "time", "0.5");
        expectSameView(v);
    }
}

TEST(PageAddressWrite, SizeOnlyWhenAsked) {
    View v = viewOf("#scene=tutorial-room&size=96x96");
    setOption(v.options, "size", "640x480");
    EXPECT_EQ(addressOf(v, false), "#scene=tutorial-room");
    EXPECT_EQ(addressOf(v, true), "#scene=tutorial-room&size=640x480");
    expectSameView(v, true);
}

// Time is a double; the schema writes it to a float's precision.
TEST(PageAddressWrite, TimeReadsBackToAFloatsPrecision) {
    View v = viewOf("#scene=book-triangle");
    v.options.time = 1.0 / 3.0;
    const PageScene r = loadRequest(parseAddress(addressOf(v)), "");
    EXPECT_EQ(float(r.options.time), float(1.0 / 3.0));
}

// Every light field and every camera or ambient key, changed alone, is written and read back:
// a field the writer dropped, or a new one without a change here, fails.
TEST(PageAddressWrite, EachLightFieldAndSceneKeyAlone) {
    const std::map<std::string, std::function<void(Light&)>> lightChanges = {
        {"on", [](Light& l) { l.enabled = false; }},
        {"shadows", [](Light& l) { l.castsShadows = false; }},
        {"type", [](Light& l) { l.type = LightType::Point; }},
        {"pos",
         [](Light& l) {
             l.position = {-2.5f, 7.125f, 0.3f};
         }},
        {"dir",
         [](Light& l) {
             l.direction = {0.1f, -0.9f, 0.2f};
         }},
        {"colour",
         [](Light& l) {
             l.colour = {1.0f, 0.25f, 0.7f};
         }},
        {"int", [](Light& l) { l.intensity = 2.75f; }},
        {"att",
         [](Light& l) {
             l.attenuation = {0.5f, 0.1f, 0.01f};
         }},
        {"range", [](Light& l) { l.range = 12.0f; }},
        {"cone", [](Light& l) { l.innerConeDegrees = 5.5f, l.outerConeDegrees = 44.0f; }},
        {"map", [](Light& l) { l.shadowMapSize = 4096; }},
        {"cam", [](Light& l) { l.shadowCamera.policy = ShadowCameraPolicy::Manual; }},
        {"proj", [](Light& l) { l.shadowCamera.projection = Projection::Orthographic; }},
        {"target",
         [](Light& l) {
             l.shadowCamera.target = {0.5f, 0.0f, -0.5f};
         }},
        {"fov", [](Light& l) { l.shadowCamera.fovyDegrees = 75.5f; }},
        {"box", [](Light& l) { l.shadowCamera.left = -6.0f, l.shadowCamera.top = 4.5f; }},
        {"depth", [](Light& l) { l.shadowCamera.near = 0.75f, l.shadowCamera.far = 40.0f; }},
    };
    for (const LightField& f : lightFields()) {
        SCOPED_TRACE(f.name);
        ASSERT_EQ(lightChanges.count(f.name), 1u) << "no change here for light field " << f.name;
        View v = viewOf("#scene=mixed-lights");
        lightChanges.at(f.name)(v.edited.lights[11]);
        EXPECT_EQ(addressOf(v).rfind("#scene=mixed-lights&light11=" + std::string(f.name) + ":", 0),
                  0u)
            << addressOf(v);
        expectSameView(v);
    }
    const std::map<std::string, std::function<void(Scene&)>> sceneChanges = {
        {"camera-projection", [](Scene& s) { s.camera.projection = Projection::Orthographic; }},
        {"camera-box", [](Scene& s) { s.camera.left = -3.5f, s.camera.top = 2.25f; }},
        {"camera-depth", [](Scene& s) { s.camera.near = 0.25f, s.camera.far = 60.5f; }},
        {"ambient",
         [](Scene& s) {
             s.ambient = {0.2f, 0.1f, 0.0f};
         }},
    };
    for (const SceneKey& k : sceneKeys()) {
        SCOPED_TRACE(k.name);
        ASSERT_EQ(sceneChanges.count(k.name), 1u) << "no change here for key " << k.name;
        View v = viewOf("#scene=tutorial-room");
        sceneChanges.at(k.name)(v.edited);
        EXPECT_EQ(addressOf(v).rfind("#scene=tutorial-room&" + std::string(k.name) + "=", 0), 0u)
            << addressOf(v);
        expectSameView(v);
    }
}

// What the address gave stays in the address when the user has not touched it (the view
// holds it as loaded, so it differs from nothing), and edits over it read back.
TEST(PageAddressWrite, KeepsWhatTheAddressGave) {
    const std::string given =
        "#scene=tutorial-spot&preset=textbook&ground&picture=truth&ui=off&camera-eye=1,2,3&"
        "camera-target=0,0.5,0&camera-fov=50&sun=30,45&camera-depth=0.5,50&ambient=0.2,0.2,0.2&"
        "light0=colour:1,0.5,0.5;int:2&filter=none";
    View v = viewOf(given);
    EXPECT_EQ(addressOf(v), given);
    expectSameView(v);
    v.edited.lights[0].intensity = 3.5f;
    v.edited.camera.eye.x = 1.5f;
    EXPECT_EQ(addressOf(v),
              "#scene=tutorial-spot&preset=textbook&ground&picture=truth&ui=off&"
              "camera-eye=1.5,2,3&camera-target=0,0.5,0&camera-fov=50&sun=30,45&"
              "camera-depth=0.5,50&ambient=0.2,0.2,0.2&light0=colour:1,0.5,0.5;int:3.5&"
              "filter=none");
    expectSameView(v);
}

// A camera moved gets planes fitted to the scene as it loads: the writer says the view's own
// when they are not those.
TEST(PageAddressWrite, AMovedCameraKeepsItsPlanes) {
    View v = viewOf("#scene=tutorial-room");
    v.edited.camera.eye = {-10.0f, 6.0f, 4.0f};
    EXPECT_NE(addressOf(v).find("&camera-depth=0.5,80"), std::string::npos) << addressOf(v);
    expectSameView(v);
    fitCameraDepth(v.edited, v.edited.camera);  // planes the load would give: left out
    EXPECT_EQ(addressOf(v), "#scene=tutorial-room&camera-eye=-10,6,4&camera-target=2,1,3");
    expectSameView(v);
}

TEST(PageAddressWrite, EscapesWhatTheAddressSplitsOn) {
    View v = viewOf("#scene=book-triangle");
    v.base.scene = "/upload/my model #1&2=50%+.glb";
    const std::string address = addressOf(v);
    EXPECT_EQ(address, "#scene=/upload/my%20model%20%231%262%3D50%25%2B.glb");
    EXPECT_EQ(parseAddress(address).scene, v.base.scene);
    EXPECT_EQ(numberText(1e6f), "1e06");
    EXPECT_EQ(numberText(50.0f), "50");
    EXPECT_EQ(numberText(1e20f), "1e20");
    EXPECT_EQ(numberText(1e-5f), "1e-05");
    EXPECT_EQ(numberText(0.1f), "0.1");
    EXPECT_EQ(numberText(-2.5f), "-2.5");
}

TEST(PageAddressWrite, RefusesAViewWithOtherLights) {
    View v = viewOf("#scene=course-two-lights");
    v.edited.lights.pop_back();
    EXPECT_THROW(addressOf(v), Error);
}

TEST(PageAddressRead, CameraAndSunInTheCliWords) {
    const PageScene s = loadRequest(
        parseAddress("#scene=tutorial-room&camera-eye=1,2,3&camera-target=0,1,0&camera-fov=60&"
                     "sun=90,45"),
        "");
    EXPECT_EQ(s.scene.camera.eye, glm::vec3(1, 2, 3));
    EXPECT_EQ(s.scene.camera.centre, glm::vec3(0, 1, 0));
    EXPECT_EQ(s.scene.camera.fovyDegrees, 60.0f);
    ASSERT_EQ(s.scene.lights.size(), 1u);
    EXPECT_EQ(s.scene.lights[0].direction, sunDirection(90, 45));
    EXPECT_TRUE(parseAddress("#ui").ui);
    EXPECT_FALSE(parseAddress("#ui=off").ui);
    EXPECT_EQ(errorOf("#ui=maybe"), "ui: expected on or off, got 'maybe'");
    const std::string t = "#scene=book-triangle&";
    EXPECT_EQ(errorOf(t + "camera-eye=1,2"),
              "--camera-eye: expected X,Y,Z such as 4,3,6, got '1,2'");
    EXPECT_EQ(errorOf(t + "camera-target=a,b,c"),
              "--camera-target: expected X,Y,Z such as 0,1,0, got 'a,b,c'");
    EXPECT_EQ(errorOf(t + "camera-fov=wide"), "--camera-fov: expected a number, got 'wide'");
    EXPECT_EQ(errorOf(t + "camera-fov=200"), "--camera-fov: must be in 1..179 degrees, got 200");
    EXPECT_EQ(errorOf(t + "camera-eye=0,1,0&camera-target=0,1,0"),
              "--camera-eye: the eye and the target are the same point");
    EXPECT_EQ(errorOf(t + "sun=30,0"),
              "--sun: expected AZIMUTH,ELEVATION in degrees, elevation in (0, 90], got '30,0'");
    EXPECT_EQ(errorOf(t + "camera-projection=fisheye"),
              "camera-projection: expected perspective or orthographic, got 'fisheye'");
    EXPECT_EQ(errorOf(t + "camera-box=1,2,3"),
              "camera-box: expected LEFT,RIGHT,BOTTOM,TOP such as -5,5,-5,5, got '1,2,3'");
    EXPECT_EQ(errorOf(t + "camera-depth=5,1"),
              "camera-depth: expected NEAR,FAR with 0 < near < far, such as 0.1,100, got '5,1'");
    EXPECT_EQ(errorOf(t + "ambient=-1,0,0"),
              "ambient: expected R,G,B, each 0 or more, such as 0.1,0.1,0.1, got '-1,0,0'");
}

TEST(PageAddressRead, LightKeysNameTheKeyAndTheField) {
    const std::string t = "#scene=book-triangle&";
    EXPECT_EQ(errorOf(t + "light5=int:2"), "light5: the scene has 1 light (light0)");
    EXPECT_EQ(errorOf("#scene=course-two-lights&light2=int:2"),
              "light2: the scene has 2 lights (light0..light1)");
    EXPECT_EQ(errorOf(t + "light0=posn:1,2,3"), "light0: unknown field 'posn'; did you mean pos?");
    EXPECT_EQ(errorOf(t + "light0=int:1;int:2"), "light0: gives 'int' twice");
    EXPECT_EQ(errorOf(t + "light0=pos"),
              "light0: expected FIELD:VALUE;... such as pos:1,4,2;int:3, got 'pos'");
    EXPECT_EQ(errorOf(t + "light0="), "light0: expected FIELD:VALUE;... such as pos:1,4,2;int:3");
    EXPECT_EQ(errorOf(t + "light02=int:2"),
              "unknown option in the address: 'light02'; did you mean light0?");
    EXPECT_EQ(errorOf(t + "light0=pos:0,5,0;cam:manual;target:0,5,0"),
              "light0: scene 'book-triangle': lights[0] ('light') shadow camera looks at its own "
              "position (target == position)");
    // One bad value for each field, refused in the field's own words.
    const std::map<std::string, std::string> bad = {
        {"on", "yes"},       {"shadows", "1"},     {"type", "laser"}, {"pos", "1,4"},
        {"dir", "0,0,0"},    {"colour", "1,-1,1"}, {"int", "-2"},     {"att", "0,0,0"},
        {"range", "far"},    {"cone", "40,30"},    {"map", "32"},     {"cam", "auto"},
        {"proj", "fisheye"}, {"target", "1,2,x"},  {"fov", "180"},    {"box", "1,2,3"},
        {"depth", "0,10"},
    };
    for (const LightField& f : lightFields()) {
        ASSERT_EQ(bad.count(f.name), 1u) << "no bad value here for light field " << f.name;
        const std::string text = bad.at(f.name);
        EXPECT_EQ(
            errorOf(t + "light0=" + f.name + ":" + text),
            "light0: " + std::string(f.name) + ": expected " + f.expected + ", got '" + text + "'");
    }
}

}  // namespace
}  // namespace gnomon::web
