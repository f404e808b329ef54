// The view's depth buffer spans what is drawn, not the camera's near and far: a plate half a
// unit in front of a wall, seen from 1 600 units through a camera with znear 0.05 and zfar
// 10^6 (as glTF files give them: assimp's 2CylinderEngine), must cover the wall wherever it
// lies over it. With the camera's own planes a depth step there is about 3 units, and the
// two surfaces fought over most of the plate's pixels.
#include <gtest/gtest.h>

#include <utility>

#include "GlTest.h"
#include "scene/MeshBuilder.h"

namespace gnomon::test {
namespace {

Scene plateBeforeWall(float near, float far, bool wallFirst) {
    Scene s;
    s.name = "plate-before-wall";
    Material wall, plate;
    wall.baseColour = {1.0f, 0.0f, 0.0f};
    plate.baseColour = {0.0f, 1.0f, 0.0f};
    wall.specular = plate.specular = 0.0f;
    s.materials = {wall, plate};
    s.meshes.push_back(mesh::box("wall", {0.0f, 0.0f, -0.5f}, {40.0f, 40.0f, 1.0f}));
    s.meshes.push_back(mesh::box("plate", {0.0f, 0.0f, 0.5f}, {10.0f, 10.0f, 0.1f}));
    // Either drawn first: a depth test that cannot tell them apart keeps the first.
    s.objects.push_back({"wall", 0, 0, glm::mat4(1.0f), {}, true, true});
    s.objects.push_back({"plate", 1, 1, glm::mat4(1.0f), {}, true, true});
    if (!wallFirst) std::swap(s.objects[0], s.objects[1]);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.2f, -0.3f, -1.0f));
    s.lights.push_back(sun);
    s.camera.eye = {0.0f, 0.0f, 1600.0f};
    s.camera.centre = {0.0f, 0.0f, 0.0f};
    s.camera.fovyDegrees = 1.0f;  // 28 units across at the wall: the plate fills the middle
    s.camera.near = near;
    s.camera.far = far;
    s.options.width = s.options.height = 64;
    return s;
}

// Pixels of the middle 16 x 16 (all on the plate) that show the wall's red instead.
int wallThroughPlate(const Scene& s) {
    const Image image = sharedRenderer().render(s, s.options);
    int red = 0;
    for (int y = 24; y < 40; ++y)
        for (int x = 24; x < 40; ++x)
            red += image.at(x, y)[0] > image.at(x, y)[1];
    return red;
}

TEST(ViewDepthRange, ExtremeNearAndFarDoNotFight) {
    for (bool wallFirst : {true, false}) {
        EXPECT_EQ(wallThroughPlate(plateBeforeWall(1500.0f, 1700.0f, wallFirst)), 0);
        EXPECT_EQ(wallThroughPlate(plateBeforeWall(0.05f, 1e6f, wallFirst)), 0) << wallFirst;
    }
}

}  // namespace
}  // namespace gnomon::test
