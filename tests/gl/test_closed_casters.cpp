// Face culling in the shadow pass keeps a closed caster's shadow only when the faces left
// still stand between the light and everything behind. Two cases where they did not:
// - A box around a point or spot light shows it only back faces, so culling them dropped the
//   whole box, and the floor around it was lit where the trace finds every ray to the light
//   blocked (assimp-testmodels' spider.fbx, its point light inside the abdomen: 34 % of the
//   view leaked).
// - A box wound inwards (as some FBX exports are) had its light-facing side culled, and the
//   side left in the map was the one the camera sees, lit everywhere (the skinned mesh of
//   assimp-testmodels' animation_with_skeleton.fbx: 100 %).
#include <gtest/gtest.h>

#include <utility>

#include "GlTest.h"
#include "GridSolid.h"
#include "scene/MeshBuilder.h"
#include "scene/MeshTopology.h"

namespace gnomon::test {
namespace {

Scene lightInABox(LightType type) {
    Scene s;
    s.name = "light-in-a-box";
    s.materials.push_back(Material{});
    s.meshes.push_back(mesh::quad("floor", {-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}));
    s.meshes.push_back(mesh::box("box", {0.0f, 2.0f, 0.0f}, {2.0f, 2.0f, 2.0f}));
    s.objects.push_back({"floor", 0, 0, glm::mat4(1.0f), {}, true, true});
    s.objects.push_back({"box", 1, 0, glm::mat4(1.0f), {}, true, true});
    Light l;
    l.type = type;
    l.position = {0.2f, 2.1f, 0.3f};  // inside the box (y 1 to 3)
    l.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    l.outerConeDegrees = 60.0f;
    l.innerConeDegrees = 50.0f;
    s.lights.push_back(l);
    s.camera.eye = {0.0f, 14.0f, 9.0f};
    s.camera.centre = {0.0f, 0.0f, 0.0f};
    s.options.width = s.options.height = 96;
    return s;
}

TEST(ClosedCasters, ABoxAroundTheLightShadowsEverythingOutside) {
    for (LightType type : {LightType::Point, LightType::Spot}) {
        const Scene s = lightInABox(type);
        ASSERT_EQ(s.options.shadow.cull, CullMode::Back);  // the default, which culls solids
        const ScoreResult r = score(sharedRenderer(), s, s.options);
        EXPECT_GT(r.overall.pixels, 1000) << int(type);
        EXPECT_LT(r.overall.misclassified, 0.001) << int(type);
    }
}

TEST(ClosedCasters, ABoxWoundInwardsKeepsItsShadow) {
    Scene s = lightInABox(LightType::Directional);
    s.lights[0].direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    Mesh& box = s.meshes[1];
    for (std::size_t t = 0; t < box.indices.size(); t += 3)
        std::swap(box.indices[t + 1], box.indices[t + 2]);
    for (glm::vec3& n : box.normals)
        n = -n;
    const ScoreResult r = score(sharedRenderer(), s, s.options);
    EXPECT_GT(r.overall.pixels, 1000);
    EXPECT_LT(r.overall.misclassified, 0.005);
}

// A solid with a few faces wound the wrong way (glmark2's 3DS horse has 48 of 7 172): those
// faces and the ones beside them are drawn from both sides, the rest culled. Culled with the
// rest, the turned faces on the light's side would be back faces, and light would pass
// through them and out of the culled far side: here a patch of the floor beside the floating
// box, a few hundred pixels, would be lit inside its shadow.
TEST(ClosedCasters, ASolidWithAFewFacesTurnedKeepsItsShadow) {
    Scene s = lightInABox(LightType::Point);
    Mesh solid = gridSolid(16, 0.25f, {-2.0f, 3.0f, -2.0f});  // 4 units wide, y 3 to 7
    // The +x side (the second), its middle 2 x 2 squares (x = 2, y 4.75 to 5.25, z -0.25 to
    // 0.25), both triangles of each.
    const std::size_t perSide = 16 * 16 * 2;
    for (int i : {7, 8}) {
        for (int j : {7, 8}) {
            const std::size_t square = std::size_t(16 * i + j);
            turnTriangle(solid, perSide + 2 * square);
            turnTriangle(solid, perSide + 2 * square + 1);
        }
    }
    const CullingSplit split = splitForCulling(solid);
    ASSERT_GT(split.closedIndices, 0u);
    ASSERT_LT(split.closedIndices, solid.indices.size());
    s.meshes[1] = solid;
    s.lights[0].position = {8.0f, 9.0f, 0.0f};
    s.options.width = s.options.height = 160;
    const ScoreResult r = score(sharedRenderer(), s, s.options);
    EXPECT_GT(r.overall.pixels, 10000);
    EXPECT_LT(r.overall.misclassified, 0.002);
}

// Gives `box` a masked material (added to `s`, its index returned) whose texture is clear on
// the side facing `clearSide` and opaque on every other: a solid cut by its texture.
std::uint32_t addMaskCuttingSide(Scene& s, Mesh& box, glm::vec3 clearSide, bool doubleSided) {
    s.textures.push_back({"clear | opaque",
                          2,
                          1,
                          {255, 255, 255, 0, 255, 255, 255, 255},
                          TextureWrap::Repeat,
                          TextureWrap::Repeat,
                          /*nearest=*/true});
    Material cut;
    cut.alphaMode = AlphaMode::Mask;
    cut.alphaCutoff = 0.5f;
    cut.baseColourTexture = int(s.textures.size() - 1);
    cut.doubleSided = doubleSided;
    s.materials.push_back(cut);
    box.uvs.clear();
    for (const glm::vec3& n : box.normals)
        box.uvs.push_back(glm::dot(n, clearSide) > 0.5f ? glm::vec2(0.25f, 0.5f)
                                                        : glm::vec2(0.75f, 0.5f));
    return std::uint32_t(s.materials.size() - 1);
}

// A solid whose texture cuts its faces is no solid for light: light let in through a clear
// texel of a face towards the light meets the opaque texels of the faces behind. Here the
// box's top is clear and every other face opaque, so it shadows the floor under it; with its
// back faces culled, nothing of it was left in the map (the slab of assimp's ClearCoatTest
// with a partly clear coating let light onto the dome behind it the same way).
TEST(ClosedCasters, ASolidCutByItsTextureIsNotCulled) {
    Scene s = lightInABox(LightType::Directional);
    s.lights[0].direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
    Mesh& box = s.meshes[1];
    ASSERT_EQ(box.indices.size(), splitForCulling(box).closedIndices);  // a solid
    s.objects[1].material = addMaskCuttingSide(s, box, {0, 1, 0}, false);
    const ScoreResult r = score(sharedRenderer(), s, s.options);
    EXPECT_GT(r.overall.pixels, 1000);
    EXPECT_LT(r.overall.misclassified, 0.005);
}

// The view skips a double-sided solid's back faces where it starts outside the solid, but not
// a masked one's: through the clear texels of its near side the far side's inside shows.
TEST(ClosedCasters, AMaskedSolidShowsItsInsideThroughItsClearTexels) {
    Scene s;
    s.name = "masked-box";
    Mesh box = mesh::box("box", glm::vec3(0.0f), glm::vec3(2.0f));
    addMaskCuttingSide(s, box, {0, 0, 1}, true);  // the side facing the camera clear
    ASSERT_EQ(box.indices.size(), splitForCulling(box).closedIndices);
    s.meshes.push_back(box);
    s.objects.push_back({"box", 0, 0, glm::mat4(1.0f), {}, true, true});
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.0f, 0.0f, -1.0f));  // onto the far side's inside
    s.lights.push_back(sun);
    s.ambient = glm::vec3(0.3f);
    s.camera.eye = {0.0f, 0.0f, 6.0f};
    s.camera.centre = {0.0f, 0.0f, 0.0f};
    s.options.width = s.options.height = 64;
    const Image image = sharedRenderer().render(s, s.options);
    EXPECT_GT(luminance(image.at(32, 32)), 60);  // the far side's inside, not the background
}

}  // namespace
}  // namespace gnomon::test
