// The viewer without a window: its state becomes the render options `gnomon render` would
// use, presets and scripted commands edit that state as the controls do, and the camera and
// light drags move what they should.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <cmath>

#include "RenderOptionsCli.h"
#include "ViewerState.h"
#include "gnomon/Error.h"

namespace gnomon::view {
namespace {

State loaded(const std::string& scene) {
    State s;
    load(s, scene, false);
    return s;
}

// What `gnomon render --scene X FLAGS` resolves to.
RenderOptions renderCliOptions(const std::vector<std::string>& args, Scene& scene) {
    CLI::App app{"render"};
    cli::RenderFlags flags;
    std::string sceneName;
    app.add_option("--scene", sceneName);
    flags.add(app);
    std::vector<std::string> reversed(args.rbegin(), args.rend());
    app.parse(reversed);
    scene = loadScene(sceneName);
    flags.editScene(scene);
    return flags.resolve(scene);
}

TEST(ViewerState, LoadStartsFromTheScenesAuthoredOptions) {
    const State s = loaded("tutorial-room");
    EXPECT_EQ(s.source, "tutorial-room");
    EXPECT_TRUE(s.options == s.scene.options);
    EXPECT_EQ(s.selectedLight, 0);
    EXPECT_TRUE(s.fitView);
}

TEST(ViewerState, SelectsTheFirstShadowedLight) {
    const State s = loaded("course-two-lights");
    ASSERT_GE(s.scene.lights.size(), 2u);
    EXPECT_TRUE(s.scene.lights[std::size_t(s.selectedLight)].castsShadows);
}

TEST(ViewerState, MainViewFollowsTheWindowUnlessASizeWasSet) {
    State s = loaded("tutorial-room");
    RenderOptions o = mainViewOptions(s, 640, 360);
    EXPECT_EQ(o.width, 640);
    EXPECT_EQ(o.height, 360);
    applyFlags(s, {"--size", "256x128"});
    EXPECT_FALSE(s.fitView);
    o = mainViewOptions(s, 640, 360);
    EXPECT_EQ(o.width, 256);
    EXPECT_EQ(o.height, 128);
}

TEST(ViewerState, FrustaToggleIsTheLightFrustaDebugView) {
    State s = loaded("tutorial-spot");
    applyFlags(s, {"--debug-view", "cascades"});
    EXPECT_EQ(mainViewOptions(s, 64, 64).debugView, DebugView::Cascades);
    s.frusta = true;
    EXPECT_EQ(mainViewOptions(s, 64, 64).debugView, DebugView::LightFrusta);
    s.frusta = false;
    EXPECT_EQ(mainViewOptions(s, 64, 64).debugView, DebugView::Cascades);
}

TEST(ViewerState, FlagsSetTheOptionsTheyName) {
    State s = loaded("tutorial-room");
    const std::uint64_t before = s.revision;
    applyFlags(s, {"--map-size", "64", "--filter", "none", "--bias-constant", "0.01", "--cull",
                   "front", "--depth-format", "depth16", "--cascades", "3"});
    EXPECT_EQ(s.options.shadow.mapSize, 64);
    EXPECT_EQ(s.options.shadow.filter, ShadowFilter::None);
    EXPECT_FLOAT_EQ(s.options.shadow.biasConstant, 0.01f);
    EXPECT_EQ(s.options.shadow.cull, CullMode::Front);
    EXPECT_EQ(s.options.shadow.depthFormat, DepthFormat::Depth16);
    EXPECT_EQ(s.options.shadow.cascades, 3);
    EXPECT_GT(s.revision, before);
    // Untouched options keep their values.
    EXPECT_FLOAT_EQ(s.options.shadow.biasSlope, s.scene.options.shadow.biasSlope);
}

// A camera placed by flags sees the whole scene from wherever it stands: its depth range is
// refitted (the scene's own, sized for its authored eye, would cut a distant view away).
TEST(ViewerState, CameraFlagsRefitTheDepthRange) {
    State s = loaded("tutorial-room");
    applyFlags(s, {"--camera-eye", "300,200,300", "--camera-target", "0,0,0"});
    const Camera& c = s.scene.camera;
    glm::vec3 lo, hi;
    sceneBounds(s.scene, lo, hi);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p(corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y,
                          corner & 4 ? hi.z : lo.z);
        EXPECT_LT(glm::length(p - c.eye), c.far) << "corner " << corner;
        EXPECT_GT(glm::length(p - c.eye), c.near) << "corner " << corner;
    }
}

TEST(ViewerState, BadFlagsNameTheFlagAndChangeNothing) {
    State s = loaded("tutorial-room");
    const RenderOptions before = s.options;
    try {
        applyFlags(s, {"--map-size", "20"});
        FAIL() << "map size 20 accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("map"), std::string::npos) << e.what();
    }
    EXPECT_THROW(applyFlags(s, {"--filter", "blurry"}), Error);
    EXPECT_THROW(applyFlags(s, {"--no-such-flag", "1"}), Error);
    EXPECT_TRUE(s.options == before);
}

TEST(ViewerState, TextbookPresetIsTheScenesTextbookOptions) {
    State s = loaded("tutorial-room");
    applyFlags(s, {"--map-size", "64"});
    const PresetEntry* textbook = findPreset("textbook");
    ASSERT_NE(textbook, nullptr);
    applyPreset(s, *textbook);
    RenderOptions expected = presetOptions(s.scene, Preset::Textbook);
    expected.width = s.options.width;
    expected.height = s.options.height;
    EXPECT_TRUE(s.options == expected);
    applyPreset(s, *findPreset("default"));
    expected = s.scene.options;
    expected.width = s.options.width;
    expected.height = s.options.height;
    EXPECT_TRUE(s.options == expected);
}

// Every example preset gives exactly what `gnomon render` gives for the same flags, so a
// picture in docs/techniques.md can be reproduced and then tuned in the viewer.
TEST(ViewerState, ExamplePresetsMatchTheRenderCommand) {
    int examples = 0;
    for (const PresetEntry& p : presets()) {
        if (p.name == "default" || p.name == "textbook") continue;
        ++examples;
        State s;
        s.fitView = false;
        applyPreset(s, p);
        Scene scene;
        RenderOptions expected = renderCliOptions(p.args, scene);
        expected.width = s.options.width;
        expected.height = s.options.height;
        EXPECT_TRUE(s.options == expected) << p.name;
        EXPECT_EQ(s.scene.name, scene.name) << p.name;
        EXPECT_FALSE(p.group.empty()) << p.name;
    }
    EXPECT_GE(examples, 20);  // examples/presets.txt holds the techniques doc's pictures
}

TEST(ViewerCamera, OrbitKeepsTheDistanceAndStopsShortOfThePoles) {
    Camera c;
    c.eye = {0, 2, 5};
    c.centre = {0, 0, 0};
    const float distance = glm::length(c.eye - c.centre);
    orbit(c, 90.0f, 0.0f);
    EXPECT_NEAR(glm::length(c.eye - c.centre), distance, 1e-4f);
    EXPECT_NEAR(c.eye.y, 2.0f, 1e-4f);  // yaw about up keeps the height
    EXPECT_GT(std::abs(c.eye.x), 4.0f);
    orbit(c, 0.0f, 500.0f);  // far past the pole
    EXPECT_NEAR(glm::length(c.eye - c.centre), distance, 1e-4f);
    const float angle = glm::degrees(std::acos(glm::dot(glm::normalize(c.eye - c.centre), c.up)));
    EXPECT_GE(angle, 1.9f);
    EXPECT_LE(angle, 178.1f);
}

TEST(ViewerCamera, PanMovesEyeAndCentreTogether) {
    Camera c;
    c.eye = {0, 0, 10};
    const glm::vec3 offset = c.eye - c.centre;
    pan(c, 0.5f, 0.0f);
    EXPECT_NEAR(glm::length((c.eye - c.centre) - offset), 0.0f, 1e-4f);
    EXPECT_LT(c.centre.x, 0.0f);  // dragging right moves the scene right: the camera left
    EXPECT_NEAR(c.centre.y, 0.0f, 1e-5f);
}

TEST(ViewerCamera, ZoomScalesTheDistanceButNotThroughTheNearPlane) {
    Camera c;
    c.eye = {0, 0, 10};
    c.near = 1.0f;
    zoom(c, 0.5f);
    EXPECT_NEAR(glm::length(c.eye), 5.0f, 1e-4f);
    zoom(c, 1e-6f);
    EXPECT_GE(glm::length(c.eye), c.near);
    Camera ortho;
    ortho.projection = Projection::Orthographic;
    zoom(ortho, 2.0f);
    EXPECT_FLOAT_EQ(ortho.right - ortho.left, 4.0f);
}

TEST(ViewerLights, DraggingTurnsDirectionsAndOrbitsPositions) {
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0, -1, 0.5f};
    const float length = glm::length(sun.direction);
    orbitLight(sun, {0, 0, 0}, {1, 0, 0}, 90.0f, 0.0f);
    EXPECT_NEAR(glm::length(sun.direction), length, 1e-4f);
    EXPECT_NEAR(sun.direction.y, -1.0f, 1e-4f);  // yaw keeps the elevation
    EXPECT_GT(std::abs(sun.direction.x), 0.4f);

    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0, 5, 0};
    spot.direction = {0, -1, 0};
    orbitLight(spot, {0, 0, 0}, {1, 0, 0}, 0.0f, 30.0f);
    EXPECT_NEAR(glm::length(spot.position), 5.0f, 1e-4f);
    // It keeps pointing at the pivot.
    EXPECT_NEAR(glm::dot(glm::normalize(spot.direction), glm::normalize(-spot.position)), 1.0f,
                1e-4f);
}

TEST(ViewerScript, ParsesCommandsAndSkipsComments) {
    const std::vector<Command> c = parseScript(
        "# a comment\n\nwait 3\nset --map-size 64   # trailing\nscreenshot out.png\nquit\n",
        "s.txt");
    ASSERT_EQ(c.size(), 4u);
    EXPECT_EQ(c[0].verb, "wait");
    EXPECT_EQ(c[0].line, 3);
    EXPECT_EQ(c[1].args, (std::vector<std::string>{"--map-size", "64"}));
    EXPECT_EQ(c[3].verb, "quit");
}

TEST(ViewerScript, ErrorsNameTheFileAndLine) {
    try {
        parseScript("wait 1\nexplode now\n", "bad.txt");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bad.txt:2"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("explode"), std::string::npos) << e.what();
    }
    EXPECT_THROW(parseScript("wait\n", "s"), Error);
    EXPECT_THROW(parseScript("quit now\n", "s"), Error);
}

TEST(ViewerScript, CommandsEditTheStateAsTheControlsDo) {
    State s = loaded("course-two-lights");
    auto run = [&](const std::string& line) {
        return applyCommand(s, parseScript(line, "t").at(0));
    };
    EXPECT_TRUE(run("light 1 on off"));
    EXPECT_FALSE(s.scene.lights[1].enabled);
    EXPECT_TRUE(run("light 0 position 1 2 3"));
    EXPECT_EQ(s.scene.lights[0].position, glm::vec3(1, 2, 3));
    EXPECT_TRUE(run("light 0 map-size 64"));
    EXPECT_EQ(s.scene.lights[0].shadowMapSize, 64);
    EXPECT_TRUE(run("select-light 1"));
    EXPECT_EQ(s.selectedLight, 1);
    // A view toggle redraws (viewRevision) but leaves a score of the frame current (revision).
    const std::uint64_t revision = s.revision, viewRevision = s.viewRevision;
    EXPECT_TRUE(run("frusta on"));
    EXPECT_EQ(mainViewOptions(s, 8, 8).debugView, DebugView::LightFrusta);
    EXPECT_EQ(s.revision, revision);
    EXPECT_GT(s.viewRevision, viewRevision);
    EXPECT_TRUE(run("camera eye 0 1 9"));
    EXPECT_EQ(s.scene.camera.eye, glm::vec3(0, 1, 9));
    EXPECT_TRUE(run("preset map-64"));  // an example: loads its scene
    EXPECT_EQ(s.source, "tutorial-room");
    EXPECT_EQ(s.options.shadow.mapSize, 64);
    EXPECT_THROW(run("light 7 on off"), Error);
    EXPECT_THROW(run("light 0 colour red"), Error);
    EXPECT_THROW(run("preset nonsense"), Error);
    // The viewer's own verbs are not state edits.
    EXPECT_FALSE(run("screenshot x.png"));
    EXPECT_FALSE(run("wait 2"));
}

}  // namespace
}  // namespace gnomon::view
