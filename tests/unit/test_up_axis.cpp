// Models that are not Y-up (--up, a scene file's include "up"): a Z-up post exported as STL
// (tests/data/models/post_z_up.stl) stands on its foot along +y, its slanted top up, with the
// camera and sun placed for it standing; other axes and the refusals.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "SceneFileTestUtil.h"
#include "gnomon/Error.h"
#include "gnomon/SceneFile.h"
#include "scene/ModelFinish.h"

namespace gnomon {
namespace {

using namespace test;

std::string post() {
    return std::string(GNOMON_MODELS) + "/post_z_up.stl";
}

struct Box {
    glm::vec3 lo, hi;
};
Box boundsOf(const Scene& s) {
    Box b;
    sceneBounds(s, b.lo, b.hi);
    return b;
}

std::string loadError(const std::string& name, UpAxis up) {
    try {
        (void)loadScene(name, up);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(UpAxis, ZUpModelLiesOnItsBackUnlessTurned) {
    const Box lying = boundsOf(loadScene(post()));
    EXPECT_NEAR(lying.hi.z - lying.lo.z, 1.0f, 1e-5f);  // its height along z, as in the file
    EXPECT_NEAR(lying.hi.y - lying.lo.y, 0.3f, 1e-5f);
}

TEST(UpAxis, ZUpModelStandsOnItsFoot) {
    const Scene s = loadScene(post(), UpAxis::Z);
    const Box b = boundsOf(s);
    EXPECT_NEAR(b.lo.y, 0.0f, 1e-5f);  // the foot (z = 0) on the ground plane y = 0
    EXPECT_NEAR(b.hi.y, 1.0f, 1e-5f);  // the top (z = 1) up
    EXPECT_NEAR(b.hi.x - b.lo.x, 0.2f, 1e-5f);
    EXPECT_NEAR(b.hi.z - b.lo.z, 0.3f, 1e-5f);  // +y of the file turns to -z
    EXPECT_NEAR(b.lo.z, -0.3f, 1e-5f);
    // The slanted top: the file's corner (0.2, 0.3, 0.9) is now at (0.2, 0.9, -0.3).
    const Mesh& m = s.meshes[s.objects[0].mesh];
    bool found = false;
    for (const glm::vec3& p : m.positions) {
        const glm::vec3 w = glm::vec3(s.objects[0].worldFromModel * glm::vec4(p, 1.0f));
        found = found || glm::length(w - glm::vec3(0.2f, 0.9f, -0.3f)) < 1e-5f;
    }
    EXPECT_TRUE(found);
    // Framed and lit standing: the camera looks down on it, the sun shines down.
    EXPECT_GT(s.camera.eye.y, s.camera.centre.y);
    EXPECT_NEAR(s.camera.centre.y, 0.5f, 1e-4f);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_LT(s.lights[0].direction.y, 0.0f);
}

TEST(UpAxis, XUpTurnsXToY) {
    const glm::mat4 t = worldFromUp(UpAxis::X);
    const glm::vec3 up = glm::vec3(t * glm::vec4(1, 0, 0, 0));
    EXPECT_NEAR(glm::length(up - glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::determinant(glm::mat3(t)), 1.0f, 1e-6f);  // a turn, not a mirror
    EXPECT_NEAR(glm::determinant(glm::mat3(worldFromUp(UpAxis::Z))), 1.0f, 1e-6f);
}

TEST(UpAxis, ParsedByName) {
    EXPECT_EQ(parseUpAxis("z"), UpAxis::Z);
    EXPECT_EQ(parseUpAxis("X"), UpAxis::X);
    EXPECT_EQ(parseUpAxis("y"), UpAxis::Y);
    EXPECT_FALSE(parseUpAxis("-z").has_value());
    EXPECT_STREQ(toString(UpAxis::Z), "z");
}

TEST(UpAxis, RefusedForWhatIsAlreadyUpright) {
    EXPECT_NE(loadError("tutorial-room", UpAxis::Z).find("--up applies to model files"),
              std::string::npos);
    ScopedTempDir dir;
    const fs::path p = dir.path() / "room.json";
    writeText(p, R"({"gnomon-scene": 1, "include": [{"scene": "tutorial-room"}]})");
    EXPECT_NE(loadError(p.string(), UpAxis::Z).find("give \"up\" on its include"),
              std::string::npos);
}

TEST(UpAxis, SceneFileIncludeTakesUp) {
    ScopedTempDir dir;
    const fs::path p = dir.path() / "yard.json";
    writeText(p, R"({"gnomon-scene": 1,
        "include": [{"scene": ")" +
                     post() + R"(", "up": "z"}]})");
    const Box b = boundsOf(loadSceneFile(p.string()));
    EXPECT_NEAR(b.lo.y, 0.0f, 1e-5f);
    EXPECT_NEAR(b.hi.y, 1.0f, 1e-5f);
    const std::string bad = errorOfText(dir, R"({"gnomon-scene": 1,
        "include": [{"scene": ")" + post() + R"(", "up": "w"}]})");
    EXPECT_NE(bad.find("include[0].up: expected one of x, y, z, got \"w\""), std::string::npos)
        << bad;
    const std::string builtin = errorOfText(dir, R"({"gnomon-scene": 1,
        "include": [{"scene": "tutorial-room", "up": "z"}]})");
    EXPECT_NE(builtin.find("\"up\" applies to model files"), std::string::npos) << builtin;
}

TEST(UpAxis, SavedSceneFileKeepsTheAxis) {
    ScopedTempDir dir;
    const Scene s = loadScene(post(), UpAxis::Z);
    const fs::path p = dir.path() / "saved.json";
    saveSceneFile(p.string(), post(), s, s.options, false, UpAxis::Z);
    EXPECT_NE(readText(p).find("\"up\": \"z\""), std::string::npos) << readText(p);
    const Box b = boundsOf(loadSceneFile(p.string()));
    EXPECT_NEAR(b.hi.y, 1.0f, 1e-5f);
}

}  // namespace
}  // namespace gnomon
