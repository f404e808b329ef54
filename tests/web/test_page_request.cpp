// The web page's address and scene (apps/web/PageRequest.h) and the light its picture shows
// (TruthPicture.h), natively and without a browser: keys and escapes, the CLI's words for
// bad values, models found in the bundle by folder.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "PageRequest.h"
#include "TruthPicture.h"
#include "gnomon/Error.h"

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

}  // namespace
}  // namespace gnomon::web
