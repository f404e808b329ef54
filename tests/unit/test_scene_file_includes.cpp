// Scene files that build on others (docs/scene-file.md): includes placed and tuned, paths
// relative to each file, what gnomon adds when a file leaves it out (sun, camera, ground),
// and meshes given inline.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "SceneFileTestUtil.h"

namespace gnomon {
namespace {

using namespace test;

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

// A model included at another scale (a glTF in centimetres placed in a scene in metres) keeps
// what it looked like: the camera's near and far scale with it, and its lights' range and
// falloff are the same at the same place on the model.
TEST(SceneFile, ScaledIncludeKeepsItsFramingAndFalloff) {
    ScopedTempDir dir;
    const fs::path p = dir.path() / "big.json";
    writeText(p, R"({"gnomon-scene": 1,
        "include": [{"scene": "tutorial-spot", "transform": {"scale": 1000}}]})");
    const Scene s = loadSceneFile(p.string());
    const Scene spot = builtinScene("tutorial-spot");
    EXPECT_FLOAT_EQ(s.camera.near, 1000.0f * spot.camera.near);
    EXPECT_FLOAT_EQ(s.camera.far, 1000.0f * spot.camera.far);
    ASSERT_EQ(s.lights.size(), spot.lights.size());
    const Light &a = spot.lights[0], &b = s.lights[0];
    Compare{false}.vec(b.position, 1000.0f * a.position, "spot position");
    EXPECT_FLOAT_EQ(b.range, 1000.0f * a.range);
    auto falloff = [](const Attenuation& c, float d) {
        return 1.0f / (c.constant + c.linear * d + c.quadratic * d * d);
    };
    const float d = glm::length(a.position - spot.camera.centre);
    EXPECT_NEAR(falloff(b.attenuation, 1000.0f * d), falloff(a.attenuation, d),
                1e-5f * falloff(a.attenuation, d));
    // A light's own shadow camera (the course text's orthographic one) scales too.
    writeText(p, R"({"gnomon-scene": 1,
        "include": [{"scene": "course-two-lights", "transform": {"scale": 0.01}}]})");
    const Scene small = loadSceneFile(p.string());
    const Scene course = builtinScene("course-two-lights");
    const ShadowCamera& c = course.lights[0].shadowCamera;
    const ShadowCamera& scaled = small.lights[0].shadowCamera;
    EXPECT_FLOAT_EQ(scaled.near, 0.01f * c.near);
    EXPECT_FLOAT_EQ(scaled.far, 0.01f * c.far);
    EXPECT_FLOAT_EQ(scaled.right - scaled.left, 0.01f * (c.right - c.left));
    EXPECT_FLOAT_EQ(scaled.top - scaled.bottom, 0.01f * (c.top - c.bottom));
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

// An include's shadow flags, when given, set every object it brings; not given, each keeps
// its own (the room's objects all cast and receive).
TEST(SceneFile, IncludeSetsItsObjectsShadowFlags) {
    ScopedTempDir dir;
    const fs::path p = dir.path() / "flags.json";
    writeText(p, R"({"gnomon-scene": 1, "include": [
        {"scene": "tutorial-room", "receives-shadows": false},
        {"scene": "tutorial-room", "casts-shadows": false},
        {"scene": "tutorial-room"}]})");
    const Scene s = loadSceneFile(p.string());
    const std::size_t n = builtinScene("tutorial-room").objects.size();
    ASSERT_EQ(s.objects.size(), 3 * n);
    for (std::size_t o = 0; o < 3 * n; ++o) {
        EXPECT_EQ(s.objects[o].castsShadows, o < n || o >= 2 * n) << o;
        EXPECT_EQ(s.objects[o].receivesShadows, o >= n) << o;
    }
    writeText(
        p, R"({"gnomon-scene": 1, "include": [{"scene": "tutorial-room", "casts-shadows": 1}]})");
    EXPECT_THROW(loadSceneFile(p.string()), Error);
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

// A camera without near and far takes them from the scene's extent, so a model in millimetres
// is not cut away whole by the defaults (1, 100) and one in kilometres is not clipped; given
// planes are kept as written. The same for manual and course shadow cameras.
TEST(SceneFile, CameraWithoutPlanesFitsThemToTheScene) {
    ScopedTempDir dir;
    const fs::path p = dir.path() / "tiny.json";
    for (const float scale : {0.001f, 1000.0f}) {
        // A box of the scale's size, the camera 3 sizes ahead of it and a spot 3 sizes above
        // it with a manual shadow camera: neither gives planes.
        const std::string s = std::to_string(scale), three = std::to_string(3 * scale);
        writeText(p, R"({"gnomon-scene": 1, "objects": [{"shape": "box", "size": )" + s +
                         R"(}], "lights": [{"type": "spot", "position": [0, )" + three +
                         R"(, 0], "direction": [0, -1, 0], "shadow-camera": {"policy": "manual",
                         "target": [0, 0, 0], "fovy": 60}}], "camera": {"eye": [0, )" +
                         s + ", " + three + "]}}");
        const Scene loaded = loadSceneFile(p.string());
        const Camera& c = loaded.camera;
        const float farthestCorner = glm::length(glm::vec3(0.5f, 1.5f, 3.5f)) * scale;
        EXPECT_GT(c.far, farthestCorner) << scale;
        EXPECT_LT(c.far, 1.1f * farthestCorner) << scale;
        EXPECT_LT(c.near, 2.5f * scale) << scale;  // in front of the box's face
        EXPECT_GT(c.near, 0.0f) << scale;
        // Manual and course shadow cameras sit at their light: their planes come from the
        // scene's extent seen from there (the defaults 1 and 100 would hold nothing of the
        // millimetre box), far beyond its farthest corner, near short of its top face.
        const ShadowCamera& sc = loaded.lights.at(0).shadowCamera;
        const float farthestFromLight = glm::length(glm::vec3(0.5f, 3.5f, 0.5f)) * scale;
        EXPECT_GT(sc.far, farthestFromLight) << scale;
        EXPECT_LT(sc.far, 1.1f * farthestFromLight) << scale;
        EXPECT_LT(sc.near, 2.5f * scale) << scale;
        EXPECT_GT(sc.near, 2.0f * scale) << scale;  // and not far short of it
    }
    writeText(p, R"({"gnomon-scene": 1, "objects": [{"shape": "box", "size": 0.001}],
                     "lights": [], "camera": {"eye": [0, 0, 0.003], "near": 0.5, "far": 7}})");
    const Camera kept = loadSceneFile(p.string()).camera;
    EXPECT_EQ(kept.near, 0.5f);
    EXPECT_EQ(kept.far, 7.0f);
    // One plane given: the other is fitted. A fitted shadow camera keeps its defaults.
    writeText(p, R"({"gnomon-scene": 1, "objects": [{"shape": "box", "size": 0.001}],
                     "lights": [{"type": "point", "position": [0, 0.003, 0],
                                 "shadow-camera": {"policy": "course", "far": 7}},
                                {"type": "point", "position": [0, 0.003, 0]}],
                     "camera": {"eye": [0, 0, 0.003], "far": 7}})");
    const Scene farOnly = loadSceneFile(p.string());
    EXPECT_EQ(farOnly.camera.far, 7.0f);
    EXPECT_LT(farOnly.camera.near, 0.0025f);
    EXPECT_EQ(farOnly.lights[0].shadowCamera.far, 7.0f);
    EXPECT_LT(farOnly.lights[0].shadowCamera.near, 0.0025f);
    EXPECT_EQ(farOnly.lights[1].shadowCamera, ShadowCamera{});
}

}  // namespace
}  // namespace gnomon
