// Scene files with mistakes: each is refused naming the file, the JSON path and what is
// wrong, and unreadable files are input/output errors.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "SceneFileTestUtil.h"

namespace gnomon {
namespace {

using namespace test;

// ---- Mistakes: each names the file, the JSON path and what is wrong

struct Case {
    const char* file;
    std::vector<const char*> says;
};

TEST(SceneFile, BrokenFilesInTheCorpusAreRefusedWithThePath) {
    const std::vector<Case> cases = {
        {"bad_json.json", {"bad_json.json: not valid JSON: parse error at line 1"}},
        {"unknown_key.json",
         {"unknown_key.json: objects[0]: unknown key \"colour\" (known keys: name, mesh, shape, "
          "material, transform, spin, casts-shadows, receives-shadows, centre, size, colours)"}},
        {"wrong_type.json",
         {"wrong_type.json: lights[0].intensity: expected a number, got \"bright\""}},
        {"bad_enum.json",
         {"bad_enum.json: lights[2].type: expected one of directional, spot, point, area, got "
          "\"sun\""}},
        {"index_out_of_range.json",
         {"index_out_of_range.json: objects[0].indices[4]: index 9 is out of range (4 "
          "positions)"}},
        {"cycle_a.json",
         {"cycle_b.json: include[0].scene: include cycle: cycle_a.json -> cycle_b.json -> "
          "cycle_a.json",
          "(included by "}},
        {"self_include.json",
         {"self_include.json: include[0].scene: include cycle: self_include.json -> "
          "self_include.json"}},
        {"missing_include.json",
         {"missing_include.json: include[0].scene: no such file", "nothing-here.gltf"}},
        {"bad_option.json",
         {"bad_option.json: options: map-size must be 0 or in 64..8192, got "
          "10"}},
        {"duplicate_key.json", {"duplicate_key.json: options: duplicate key \"filter\""}},
    };
    for (const Case& c : cases) {
        const std::string path = kCorpus + "/" + c.file;
        const std::string message = errorOf(path);
        ASSERT_FALSE(message.empty()) << c.file << " loaded";
        EXPECT_EQ(message.rfind(path.substr(0, path.size() - std::string(c.file).size()), 0), 0u)
            << "message does not start with the file: " << message;
        for (const char* s : c.says)
            EXPECT_NE(message.find(s), std::string::npos) << c.file << ": " << message;
    }
    // The one valid file of the corpus loads.
    const Scene ok = loadSceneFile(kCorpus + "/include_and_tune.json");
    ASSERT_EQ(ok.lights.size(), 1u);
    EXPECT_EQ(ok.lights[0].type, LightType::Spot);
    EXPECT_EQ(ok.options.shadow.filter, ShadowFilter::Pcss);
}

TEST(SceneFile, MoreMistakesAreRefusedWithThePath) {
    ScopedTempDir dir;
    const std::vector<std::pair<std::string, std::string>> cases = {
        {R"({"objects": []})", "bad.json: missing required key \"gnomon-scene\""},
        {R"({"gnomon-scene": 2})",
         "bad.json: gnomon-scene: this gnomon reads format version 1, got 2"},
        {R"([1, 2])", "bad.json: expected an object {...}, got an array"},
        {R"({"gnomon-scene": 1, "lightz": []})",
         "bad.json: unknown key \"lightz\" (known keys: gnomon-scene, name, description, include, "
         "materials, meshes, objects, lights, camera, ambient, ground, options, textbook-options)"},
        {R"({"gnomon-scene": 1, "lights": [{"position": [0, 1, 0]}]})",
         "bad.json: lights[0]: missing required key \"type\""},
        {R"({"gnomon-scene": 1, "lights": [{"type": "point", "position": [0, 1]}]})",
         "bad.json: lights[0].position: expected [x, y, z] (3 numbers), got an array"},
        {R"({"gnomon-scene": 1, "lights": [{"type": "point", "shadow-map-size": 10}]})",
         "bad.json: lights[0].shadow-map-size: expected an integer in 64..8192, got 10"},
        {R"({"gnomon-scene": 1, "lights": [{"type": "spot", "inner-cone": 50, "outer-cone": 40}]})",
         "bad.json: scene 'bad': lights[0] ('light 0') spot cone needs 0 <= inner <= outer < 90"},
        {R"({"gnomon-scene": 1, "camera": {"eye": [0, 0, 5], "far": 1e300}})",
         "bad.json: camera.far: the number 1e+300 is too large for a 32-bit float"},
        {R"({"gnomon-scene": 1, "camera": {"projection": "fisheye"}})",
         "bad.json: camera.projection: expected one of perspective, orthographic, got \"fisheye\""},
        {R"({"gnomon-scene": 1, "options": {"cascades": "many"}})",
         "bad.json: options.cascades: expected \"auto\" or a number, got \"many\""},
        {R"({"gnomon-scene": 1, "options": {"cascades": 5}})",
         "bad.json: options: cascades must be auto (0) or in 1..4, got 5"},
        {R"({"gnomon-scene": 1, "options": {"fit-to": "sky"}})",
         "bad.json: options.fit-to: expected one of view-depth, boxes, got \"sky\""},
        {R"({"gnomon-scene": 1, "options": {"filter": "blurry"}})",
         "bad.json: options.filter: expected one of none, hw2x2, pcf, poisson, pcss, evsm2, "
         "evsm4, msm, got "
         "\"blurry\""},
        {R"({"gnomon-scene": 1, "options": {"size": "big"}})",
         "bad.json: options.size: expected \"WIDTHxHEIGHT\" such as \"512x512\", got \"big\""},
        {R"({"gnomon-scene": 1, "options": {"shadows": "off"}})",
         "bad.json: options.shadows: expected true or false, got \"off\""},
        {R"({"gnomon-scene": 1, "options": {"pcf-size": 2.5}})",
         "bad.json: options.pcf-size: expected an integer"},
        {R"({"gnomon-scene": 1, "textbook-options": {"shadow-factor": 2}})",
         "bad.json: textbook-options: shadow-factor must be in [0, 1], got 2"},
        {R"({"gnomon-scene": 1, "materials": {"m": {"colour": [1, 0, 0]}}, "objects": [{"shape": "box", "size": 1, "material": "n"}]})",
         "bad.json: objects[0].material: no material \"n\" in materials (known: m)"},
        {R"({"gnomon-scene": 1, "materials": {"vertex colour": {"specular": 2}}})",
         "bad.json: materials[\"vertex colour\"].specular: expected a number in [0, 1], got 2"},
        {R"({"gnomon-scene": 1, "objects": [{"mesh": "cube"}]})",
         "bad.json: objects[0].mesh: no mesh \"cube\" in meshes (there are none)"},
        {R"({"gnomon-scene": 1, "objects": [{"name": "x"}]})",
         "bad.json: objects[0]: needs \"shape\" (box, quad, triangle, mesh) or \"mesh\""},
        {R"({"gnomon-scene": 1, "objects": [{"shape": "sphere"}]})",
         "bad.json: objects[0].shape: expected one of box, quad, triangle, mesh, got \"sphere\""},
        {R"({"gnomon-scene": 1, "objects": [{"shape": "quad", "corners": [[0,0,0],[1,0,0],[2,0,0],[3,0,0]]}]})",
         "bad.json: objects[0].corners: the first three corners lie on a line"},
        {R"({"gnomon-scene": 1, "objects": [{"shape": "box", "size": 1, "transform": {"matrix": [1, 0, 0], "scale": 2}}]})",
         "bad.json: objects[0].transform: \"matrix\" cannot be combined with translate, rotate or "
         "scale"},
        {R"({"gnomon-scene": 1, "objects": [{"shape": "box", "size": 1, "transform": {"rotate": {"axis": [0, 0, 0], "degrees": 5}}}]})",
         "bad.json: objects[0].transform.rotate.axis: the rotation axis is zero"},
        {R"({"gnomon-scene": 1, "objects": [{"shape": "mesh", "positions": [0, 0, 0, 1, 0, 0, 0, 1, 0], "normals": [[0, 0, 1]]}]})",
         "bad.json: objects[0].normals: expected 3 normals (one per position), got 1"},
        {R"({"gnomon-scene": 1, "include": [{"scene": "no-such-scene"}]})",
         "bad.json: include[0].scene: unknown scene 'no-such-scene' (built-in scenes: "
         "book-triangle"},
        {R"({"gnomon-scene": 1, "include": [{"scene": "tutorial-room", "light": false}]})",
         "bad.json: include[0]: unknown key \"light\" (known keys: scene, up, transform, "
         "lights, camera, casts-shadows, receives-shadows)"},
        {"{\"gnomon-scene\": 1, \"objects\": " + std::string(100, '[') + std::string(100, ']') +
             "}",
         "bad.json: objects[0][0][0]"},
    };
    for (const auto& [text, says] : cases) {
        const std::string message = errorOfText(dir, text);
        EXPECT_NE(message.find(says), std::string::npos)
            << text << "\n  gave: " << (message.empty() ? "no error" : message);
        EXPECT_EQ(message.rfind((dir.path() / "bad.json").string() + ": ", 0), 0u) << message;
    }
}

TEST(SceneFile, MissingAndOversizedFilesAreBadInput) {
    ScopedTempDir dir;
    try {
        (void)loadSceneFile((dir.path() / "absent.json").string());
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::InvalidInput);
        EXPECT_NE(std::string(e.what()).find("absent.json': no such file"), std::string::npos);
    }
    // Too large: refused before reading (a sparse file, nothing is written).
    const fs::path big = dir.path() / "big.json";
    writeText(big, "{}");
    fs::resize_file(big, (std::uintmax_t(64) << 20) + 1);
    const std::string message = errorOf(big.string());
    EXPECT_NE(message.find("scene files are limited to 64 MiB"), std::string::npos) << message;
}

}  // namespace
}  // namespace gnomon
