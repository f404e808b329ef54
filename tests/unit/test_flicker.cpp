// The temporal-stability pieces without GL: the flicker count between two renders of one
// view, and the camera and light paths (built-in and from a file).
#include <fstream>

#include <gtest/gtest.h>

#include "UnitTestUtil.h"
#include "gnomon/Error.h"
#include "gnomon/ScenePath.h"
#include "truth/Flicker.h"

namespace gnomon::test {
namespace {

// A 4x1 view with one light whose shadow shows on every pixel; lit everywhere.
truth::Reference litReference() {
    truth::Reference r;
    r.width = 4;
    r.height = 1;
    r.lights = 1;
    r.object.assign(4, 0);
    r.pixelWorld.assign(4, 0.01f);
    r.applies.assign(4, 1);
    r.hard.assign(4, 1.0f);
    r.lightCosine.assign(4, 1.0f);
    return r;
}

TEST(Flicker, NothingChangedIsZero) {
    const truth::Reference r = litReference();
    const std::vector<float> v = {1.0f, 0.0f, 0.7f, 0.2f};
    const truth::FlickerCount c = truth::countFlicker(r, v, r, v, false);
    EXPECT_EQ(c.compared, 4);
    EXPECT_EQ(c.flickered, 0);
    EXPECT_EQ(c.fraction(), 0.0);
}

// A rendered shadow that crosses 0.5 while the reference holds is flicker; one that moves
// with the reference is not; a change that stays on one side of 0.5 is not.
TEST(Flicker, CountsRenderedChangesTheReferenceDoesNotMake) {
    const truth::Reference before = litReference();
    truth::Reference after = litReference();
    after.hard[1] = 0.0f;  // the true shadow moved onto pixel 1
    const std::vector<float> v0 = {1.0f, 1.0f, 0.9f, 1.0f};
    const std::vector<float> v1 = {0.0f, 0.0f, 0.6f, 1.0f};
    const truth::FlickerCount c = truth::countFlicker(before, v0, after, v1, false);
    EXPECT_EQ(c.compared, 4);
    EXPECT_EQ(c.flickered, 1);  // pixel 0 only
    EXPECT_EQ(c.truthChanged, 1);
    EXPECT_DOUBLE_EQ(c.fraction(), 0.25);
    EXPECT_EQ(c.map, (std::vector<std::uint8_t>{1, 0, 0, 0}));
}

TEST(Flicker, PixelsWithoutTheLightsShadowAreNotCompared) {
    truth::Reference before = litReference();
    const truth::Reference after = litReference();
    before.applies[0] = 0;
    const truth::FlickerCount c =
        truth::countFlicker(before, {1, 1, 1, 1}, after, {0, 1, 1, 1}, false);
    EXPECT_EQ(c.compared, 3);
    EXPECT_EQ(c.flickered, 0);
}

TEST(Flicker, SizesMustAgree) {
    const truth::Reference a = litReference();
    truth::Reference b = litReference();
    b.width = 2;
    EXPECT_THROW(truth::countFlicker(a, {1, 1, 1, 1}, b, {1, 1, 1, 1}, false), Error);
}

Scene sceneWithSun() {
    Scene s;
    s.camera.eye = {0, 2, 10};
    s.camera.centre = {0, 0, 0};
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {1, -1, 0};
    Light lamp;
    lamp.type = LightType::Point;
    lamp.direction = {0, -1, 0};
    s.lights = {sun, lamp};
    return s;
}

TEST(ScenePath, OrbitKeepsItsDistanceAndDollyCloses) {
    const Scene s = sceneWithSun();
    const float d = glm::length(s.camera.eye - s.camera.centre);
    const ScenePath orbit = makeScenePath("orbit", s, 5);
    ASSERT_EQ(orbit.frames(), 5);
    EXPECT_TRUE(orbit.lightDirections.empty());
    for (const Camera& c : orbit.cameras)
        EXPECT_NEAR(glm::length(c.eye - c.centre), d, 1e-4f);
    EXPECT_GT(glm::length(orbit.cameras[4].eye - orbit.cameras[0].eye), 0.01f);
    const ScenePath dolly = makeScenePath("dolly", s, 3);
    EXPECT_NEAR(glm::length(dolly.cameras[2].eye - dolly.cameras[2].centre), 0.99f * d, 1e-4f);
    const ScenePath still = makeScenePath("still", s, 3);
    expectVec(still.cameras[2].eye, s.camera.eye);
}

TEST(ScenePath, SunTurnsParallelLightsOnly) {
    Scene s = sceneWithSun();
    const ScenePath sun = makeScenePath("sun", s, 3);
    ASSERT_EQ(sun.lightDirections.size(), 3u);
    applyPathFrame(sun, 2, s);
    expectVec(s.camera.eye, {0, 2, 10});
    const glm::vec3 d = glm::normalize(s.lights[0].direction);
    EXPECT_NEAR(std::fabs(glm::degrees(std::atan2(d.z, d.x))), 0.5f, 1e-3f);  // azimuth turned
    EXPECT_NEAR(d.y, -std::sqrt(0.5f), 1e-5f);  // about the vertical: elevation kept
    expectVec(s.lights[1].direction, {0, -1, 0});
}

TEST(ScenePath, BadNamesAndCountsAreRefused) {
    const Scene s = sceneWithSun();
    EXPECT_THROW(makeScenePath("orbit", s, 1), Error);
    EXPECT_THROW(makeScenePath("orbit", s, 100000), Error);
    try {
        makeScenePath("no-such-path.json", s, 0);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no-such-path.json"), std::string::npos) << e.what();
    }
}

TEST(ScenePath, FileGivesOneFramePerCamera) {
    const ScopedTempDir dir;
    const std::string file = (dir.path() / "path.json").string();
    std::ofstream(file) << R"({"gnomon-path": 1, "cameras": [
        {"eye": [0, 1, 5], "centre": [0, 0, 0]},
        {"eye": [0, 1, 4]},
        {"eye": [0, 1, 3], "fovy": 30}]})";
    const Scene s = sceneWithSun();
    const ScenePath p = makeScenePath(file, s, 0);
    ASSERT_EQ(p.frames(), 3);
    expectVec(p.cameras[1].eye, {0, 1, 4});
    expectVec(p.cameras[1].centre, {0, 0, 0});  // the scene's, where the file gives none
    EXPECT_FLOAT_EQ(p.cameras[2].fovyDegrees, 30.0f);
    EXPECT_EQ(makeScenePath(file, s, 2).frames(), 2);
    EXPECT_THROW(makeScenePath(file, s, 4), Error);  // more frames than cameras

    std::ofstream(file) << R"({"gnomon-path": 1, "cameras": [{"eye": [0, 1, 5]}, {"eye": "x"}]})";
    try {
        makeScenePath(file, s, 0);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("cameras[1].eye"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace gnomon::test
