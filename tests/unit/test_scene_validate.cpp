// Scene::validate: each spoiled scene yields exactly one problem that names what is wrong and
// the scene; a light without a map size is valid and takes its default; the
// spoilings that would turn a matrix into NaN (a light camera at its own target, a spin
// about nothing) are flagged before they render.
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gnomon/Scene.h"

namespace gnomon {
namespace {

// Scene::validate: each spoiled scene yields exactly one problem mentioning what is wrong.
void expectOneProblem(const Scene& s, const std::string& mention) {
    const std::vector<std::string> problems = s.validate();
    ASSERT_EQ(problems.size(), 1u) << (problems.empty() ? "no problem" : problems[0]);
    EXPECT_NE(problems[0].find(mention), std::string::npos) << problems[0];
    EXPECT_NE(problems[0].find("scene '" + s.name + "'"), std::string::npos) << problems[0];
}

TEST(Scene, ValidateCatchesIndexOutOfRange) {
    Scene s = builtinScene("book-triangle");
    s.meshes[0].indices[1] = 3;  // the triangle has 3 vertices
    expectOneProblem(s, "index 1 = 3 is out of range");
}

TEST(Scene, ValidateCatchesNonFinitePosition) {
    Scene s = builtinScene("course-cubes");
    s.meshes[0].positions[5].y = std::numeric_limits<float>::quiet_NaN();
    expectOneProblem(s, "position 5 is not finite");
}

TEST(Scene, ValidateCatchesNormalCountMismatch) {
    Scene s = builtinScene("tutorial-room");
    s.meshes[1].normals.pop_back();
    expectOneProblem(s, "normals for");
}

TEST(Scene, ValidateCatchesMissingMaterialAndMesh) {
    Scene s = builtinScene("course-two-lights");
    s.objects[2].material = std::uint32_t(s.materials.size());
    expectOneProblem(s, "missing material");
    s = builtinScene("course-two-lights");
    s.objects[0].mesh = 99;
    expectOneProblem(s, "missing mesh");
}

TEST(Scene, ValidateCatchesLightAndCameraProblems) {
    Scene s = builtinScene("tutorial-room");
    s.lights[0].direction = glm::vec3(0.0f);
    expectOneProblem(s, "zero direction");
    s = builtinScene("book-triangle");
    s.lights[0].shadowMapSize = 8;
    expectOneProblem(s, "shadow map size 8");
    s = builtinScene("book-triangle");
    s.lights[0].shadowCamera.near = 0.0f;
    expectOneProblem(s, "near < far");
    s = builtinScene("book-triangle");
    s.camera.centre = s.camera.eye;
    expectOneProblem(s, "eye equals its centre");
}

// A light that names no map size takes the default, 2048 (a point light's cube faces, when it
// is drawn as one, take 1024: cli.map_sizes); one it names is kept, --map-size
// overrides both, and 0 is valid where other sizes below 64 are not.
TEST(Scene, LightsWithoutAMapSizeTakeTheDefault) {
    Light l;
    EXPECT_EQ(l.shadowMapSize, 0);
    for (LightType t :
         {LightType::Directional, LightType::Area, LightType::Spot, LightType::Point}) {
        l.type = t;
        EXPECT_EQ(shadowMapSizeOf(l), 2048);
    }
    l.shadowMapSize = 333;
    EXPECT_EQ(shadowMapSizeOf(l), 333);
    ShadowOptions every;
    every.mapSize = 256;
    EXPECT_EQ(shadowMapSizeOf(l, every), 256);
    Scene s = builtinScene("book-triangle");
    s.lights[0].shadowMapSize = 0;
    EXPECT_TRUE(s.validate().empty());
}

// Scenes that pass validate() must render: each of these turns a matrix into NaN (a light
// camera looking at its own eye, a spin about a zero axis), so validate() should flag them.
TEST(Scene, ValidateCatchesDegenerateLightCamerasAndSpins) {
    std::string unflagged;
    Scene s = builtinScene("book-triangle");
    s.lights[0].shadowCamera.target = s.lights[0].position;  // Manual: eye == target
    if (s.validate().empty()) unflagged += " [Manual light at its own target]";
    s = builtinScene("course-two-lights");
    s.camera.centre = s.lights[0].position;  // Course: light camera looks at the view centre
    if (s.validate().empty()) unflagged += " [Course light at the view camera's centre]";
    s = builtinScene("book-triangle");
    s.objects[0].spin.axis = glm::vec3(0.0f);  // spinning at 40 deg/s about nothing
    if (s.validate().empty()) unflagged += " [spin with a zero axis]";
    EXPECT_TRUE(unflagged.empty()) << "validate() accepted:" << unflagged;
}

}  // namespace
}  // namespace gnomon
