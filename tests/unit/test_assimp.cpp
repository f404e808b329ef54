// Other formats through assimp: the small models in tests/data/models (make_models.py writes
// them) load into the scene model as their files say (positions, normals, indices,
// materials, textures and their coordinates, hierarchy transforms, mirrored winding, lights,
// camera), and broken or unusable files are refused naming the file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "UnitTestUtil.h"
#include "core/Aabb.h"
#include "gnomon/Error.h"
#include "scene/AssimpLoader.h"

namespace gnomon {
namespace {

using test::expectVec;

std::string model(const std::string& file) {
    return std::string(GNOMON_MODELS) + "/" + file;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string s;
    for (const std::string& l : lines)
        s += "\n  " + l;
    return s;
}

bool warns(const Scene& s, const std::string& part) {
    for (const std::string& w : s.warnings)
        if (w.find(part) != std::string::npos) return true;
    return false;
}

std::size_t triangles(const Scene& s) {
    std::size_t n = 0;
    for (const Object& o : s.objects)
        n += s.meshes[o.mesh].indices.size() / 3;
    return n;
}

const Object& objectNamed(const Scene& s, const std::string& name) {
    for (const Object& o : s.objects)
        if (o.name == name) return o;
    throw std::runtime_error("no object '" + name + "'");
}

// The message of the gnomon::Error `load` throws, checking its kind; "" if it loaded.
template <typename F>
std::string errorOf(F load, ErrorKind kind = ErrorKind::InvalidInput) {
    try {
        load();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), kind) << e.what();
        return e.what();
    }
    ADD_FAILURE() << "loaded";
    return {};
}

TEST(Assimp, ObjKeepsPositionsNormalsIndicesAndMaterials) {
    const Scene s = loadWithAssimp(model("two_parts.obj"));
    ASSERT_TRUE(s.validate().empty()) << joined(s.validate());
    ASSERT_EQ(s.objects.size(), 2u) << joined(s.warnings);
    EXPECT_EQ(triangles(s), 3u);

    const Object& quad = objectNamed(s, "quad");
    const Mesh& q = s.meshes[quad.mesh];
    ASSERT_EQ(q.positions.size(), 4u);  // the quad's corners, shared by its two triangles
    expectVec(q.positions[0], {0, 0, 0}, 0.0f);
    expectVec(q.positions[1], {1, 0, 0}, 0.0f);
    expectVec(q.positions[2], {1, 1, 0}, 0.0f);
    expectVec(q.positions[3], {0, 1, 0}, 0.0f);
    EXPECT_EQ(q.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
    for (const glm::vec3& n : q.normals)
        expectVec(n, {0, 0, 1}, 0.0f);
    EXPECT_TRUE(q.uvs.empty());  // untextured: no coordinates kept
    EXPECT_EQ(quad.worldFromModel, glm::mat4(1.0f));

    const Material& blue = s.materials[quad.material];
    EXPECT_EQ(blue.name, "blue");
    expectVec(blue.baseColour, {0.1f, 0.2f, 0.8f}, 1e-6f);  // Kd as written (taken as linear)
    EXPECT_EQ(blue.alphaMode, AlphaMode::Opaque);
    EXPECT_FLOAT_EQ(blue.shininess, 96.0f);
    EXPECT_FLOAT_EQ(blue.specular, 0.5f);
    EXPECT_EQ(blue.baseColourTexture, -1);

    const Object& tri = objectNamed(s, "tri");
    const Mesh& t = s.meshes[tri.mesh];
    ASSERT_EQ(t.indices.size(), 3u);
    expectVec(t.positions[t.indices[1]], {2, 0, -1}, 0.0f);
    expectVec(t.normals[t.indices[1]], {1, 0, 0}, 0.0f);
    const Material& half = s.materials[tri.material];
    EXPECT_EQ(half.name, "half");
    expectVec(half.baseColour, {0.25f, 0.5f, 0.75f}, 1e-6f);
    EXPECT_EQ(half.alphaMode, AlphaMode::Blend);  // d 0.4
    EXPECT_FLOAT_EQ(half.alpha, 0.4f);
    EXPECT_FLOAT_EQ(half.shininess, 2048.0f);  // Ns 5000, clamped

    // No lights or camera in an OBJ: the glTF loader's defaults, said in the warnings.
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, LightType::Directional);
    EXPECT_TRUE(warns(s, "default sun")) << joined(s.warnings);
    EXPECT_TRUE(warns(s, "no camera")) << joined(s.warnings);
    EXPECT_FALSE(warns(s, "normals")) << "the file has normals: " << joined(s.warnings);
    // The framing camera looks at the middle of the bounds (0..2, 0..1, -1..0).
    expectVec(s.camera.centre, {1.0f, 0.5f, -0.5f}, 1e-6f);
}

TEST(Assimp, TexturedObjGetsItsImageAndGltfOrientedCoordinates) {
    const Scene s = loadWithAssimp(model("textured.obj"));
    ASSERT_TRUE(s.validate().empty()) << joined(s.validate());
    ASSERT_EQ(s.objects.size(), 1u);
    const Material& m = s.materials[s.objects[0].material];
    ASSERT_GE(m.baseColourTexture, 0) << joined(s.warnings);
    const Texture& tex = s.textures[std::size_t(m.baseColourTexture)];
    EXPECT_EQ(tex.width, 4);
    EXPECT_EQ(tex.height, 2);
    ASSERT_EQ(tex.rgba.size(), 4u * 2u * 4u);
    // Rows top-down: the first texel is the image's top-left one (red), the last blue.
    EXPECT_EQ(tex.rgba[0], 255);
    EXPECT_EQ(tex.rgba[2], 0);
    EXPECT_EQ(tex.rgba[4 * 7 + 2], 255);
    EXPECT_EQ(tex.wrapS, TextureWrap::Repeat);

    const Mesh& mesh = s.meshes[s.objects[0].mesh];
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    ASSERT_EQ(mesh.positions.size(), 4u);
    // OBJ's vt (0, 0) (the image's bottom-left, v up) becomes glTF's (0, 1): v down.
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3 p = mesh.positions[i];
        const glm::vec2 expected(p.x / 2.0f, 1.0f - p.y);
        EXPECT_NEAR(mesh.uvs[i].x, expected.x, 1e-6f) << "vertex " << i;
        EXPECT_NEAR(mesh.uvs[i].y, expected.y, 1e-6f) << "vertex " << i;
    }
}

TEST(Assimp, TextureOutsideTheFolderIsRefusedWithAWarning) {
    const Scene s = loadWithAssimp(model("escape.obj"));
    EXPECT_TRUE(s.validate().empty()) << joined(s.validate());
    EXPECT_TRUE(s.textures.empty());
    EXPECT_EQ(s.materials[s.objects[0].material].baseColourTexture, -1);
    EXPECT_TRUE(warns(s, "outside the model's folder")) << joined(s.warnings);
}

TEST(Assimp, HierarchyTransformsAndMirroredWinding) {
    const Scene s = loadWithAssimp(model("hierarchy.dae"));
    ASSERT_TRUE(s.validate().empty()) << joined(s.validate());
    const Object& scaled = objectNamed(s, "scaled");
    const Object& mirrored = objectNamed(s, "mirrored");
    // parent: translate (10, 0, 0); child: scale 2.
    const glm::vec4 far = scaled.worldFromModel * glm::vec4(1, 0, 0, 1);
    expectVec(glm::vec3(far), {12, 0, 0});
    const glm::vec4 mirroredFar = mirrored.worldFromModel * glm::vec4(1, 0, 0, 1);
    expectVec(glm::vec3(mirroredFar), {9, 0, 0});
    EXPECT_LT(glm::determinant(glm::mat3(mirrored.worldFromModel)), 0.0f);
    EXPECT_NE(scaled.mesh, mirrored.mesh);  // the mirrored one has its winding flipped
    const Material& red = s.materials[scaled.material];
    expectVec(red.baseColour, {0.8f, 0.1f, 0.1f}, 1e-6f);
    EXPECT_FLOAT_EQ(red.shininess, 64.0f);
    // In world space each triangle's winding agrees with its normal, mirrored or not.
    for (const Object* o : {&scaled, &mirrored}) {
        const Mesh& m = s.meshes[o->mesh];
        const glm::mat3 w(o->worldFromModel);
        ASSERT_EQ(m.indices.size(), 3u);
        const glm::vec3 a = w * m.positions[m.indices[0]], b = w * m.positions[m.indices[1]],
                        c = w * m.positions[m.indices[2]];
        const glm::vec3 n = glm::transpose(glm::inverse(w)) * m.normals[m.indices[0]];
        EXPECT_GT(glm::dot(glm::cross(b - a, c - a), n), 0.0f) << o->name;
    }
}

TEST(Assimp, LightsAndCameraFromTheFile) {
    const Scene s = loadWithAssimp(model("hierarchy.dae"));
    ASSERT_EQ(s.lights.size(), 2u) << joined(s.warnings);
    EXPECT_FALSE(warns(s, "default sun"));
    const Light& lamp = s.lights[0].type == LightType::Point ? s.lights[0] : s.lights[1];
    const Light& spot = s.lights[0].type == LightType::Point ? s.lights[1] : s.lights[0];
    ASSERT_EQ(lamp.type, LightType::Point);
    ASSERT_EQ(spot.type, LightType::Spot);
    expectVec(lamp.position, {0, 5, 0});
    EXPECT_FLOAT_EQ(lamp.intensity, 2.0f);  // colour (2, 1, 0.5): brightest channel
    expectVec(lamp.colour, {1.0f, 0.5f, 0.25f});
    EXPECT_FLOAT_EQ(lamp.attenuation.constant, 1.0f);
    EXPECT_FLOAT_EQ(lamp.attenuation.linear, 0.5f);
    EXPECT_FLOAT_EQ(lamp.attenuation.quadratic, 0.25f);
    expectVec(spot.position, {0, 5, 5});
    expectVec(spot.direction, {0, 0, -1});
    // Cones are full angles in assimp: falloff_angle 60 is the inner cone; assimp's Collada
    // importer widens the outer one by acos(0.1^(1/falloff_exponent)) (exponent 0 read as 1).
    EXPECT_NEAR(spot.innerConeDegrees, 30.0f, 1e-3f);
    EXPECT_NEAR(spot.outerConeDegrees, 0.5f * (60.0f + glm::degrees(std::acos(0.1f))), 1e-3f);

    // Camera: at (0, 0, 10) looking down -z; xfov 90 at aspect 2 is a 53.13 degree fovy.
    EXPECT_FALSE(warns(s, "no camera"));
    expectVec(s.camera.eye, {0, 0, 10});
    const glm::vec3 look = glm::normalize(s.camera.centre - s.camera.eye);
    expectVec(look, {0, 0, -1});
    EXPECT_NEAR(s.camera.aspect, 2.0f, 1e-6f);
    EXPECT_NEAR(s.camera.fovyDegrees, glm::degrees(2.0f * std::atan(0.5f)), 1e-3f);
    EXPECT_FLOAT_EQ(s.camera.near, 0.5f);
    EXPECT_FLOAT_EQ(s.camera.far, 50.0f);
}

TEST(Assimp, PlyWithColoursAndGeneratedNormals) {
    const Scene s = loadWithAssimp(model("quad.ply"));
    ASSERT_TRUE(s.validate().empty()) << joined(s.validate());
    EXPECT_EQ(triangles(s), 2u);
    EXPECT_TRUE(warns(s, "smooth ones generated")) << joined(s.warnings);
    const Mesh& m = s.meshes[s.objects[0].mesh];
    ASSERT_EQ(m.colours.size(), m.positions.size());
    bool sawRed = false;
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        // The square lies in y = 0 wound towards +y: every generated normal is +y.
        expectVec(m.normals[i], {0, 1, 0});
        if (m.positions[i] == glm::vec3(0, 0, 0)) {
            expectVec(m.colours[i], {1, 0, 0});
            sawRed = true;
        }
    }
    EXPECT_TRUE(sawRed);
}

// The world box of the scene's first object.
void expectFirstObjectSpans(const Scene& s, const glm::vec3& lo, const glm::vec3& hi) {
    Aabb box;
    for (const glm::vec3& p : s.meshes[s.objects[0].mesh].positions)
        box.extend(glm::vec3(s.objects[0].worldFromModel * glm::vec4(p, 1.0f)));
    expectVec(box.min, lo);
    expectVec(box.max, hi);
}

TEST(Assimp, StlLoads) {
    const Scene s = loadWithAssimp(model("wedge.stl"));
    ASSERT_TRUE(s.validate().empty()) << joined(s.validate());
    EXPECT_EQ(triangles(s), 8u);
    expectFirstObjectSpans(s, {0, 0, 0}, {1, 1, 1});
}

TEST(Assimp, PointsAndLinesAreSkippedWithAWarning) {
    const Scene s = loadWithAssimp(model("with_lines.obj"));
    ASSERT_TRUE(s.validate().empty()) << joined(s.validate());
    EXPECT_EQ(triangles(s), 1u);
    EXPECT_TRUE(warns(s, "points or lines only: skipped")) << joined(s.warnings);
}

// assimp itself refuses a mesh without faces (a point cloud): its reason is passed on.
TEST(Assimp, PointCloudHasNothingToDraw) {
    const std::string m = errorOf([] { loadWithAssimp(model("points.ply")); });
    EXPECT_NE(m.find("points.ply: assimp cannot read it"), std::string::npos) << m;
    EXPECT_NE(m.find("contains no faces"), std::string::npos) << m;
}

TEST(Assimp, BrokenFilesAreRefusedNamingThemWithAssimpsReason) {
    const std::string xml = errorOf([] { loadWithAssimp(model("broken.dae")); });
    EXPECT_NE(xml.find("broken.dae: assimp cannot read it"), std::string::npos) << xml;
    EXPECT_NE(xml.find("malformed XML"), std::string::npos) << xml;
    const std::string index = errorOf([] { loadWithAssimp(model("bad_index.ply")); });
    EXPECT_NE(index.find("bad_index.ply: assimp cannot read it"), std::string::npos) << index;
    EXPECT_NE(index.find("mIndices[2] is out of range"), std::string::npos) << index;
}

// A parser's reason quotes the text it stopped at: a short excerpt, on one line. A zipped
// AMF (the standard's compressed form, which assimp does not unpack) says what to do.
TEST(Assimp, ReasonsAreOneShortLine) {
    test::ScopedTempDir dir;
    std::string facet = "solid bad\n  facet normal 0 0 1\n    outer loop\n      vertex x 0 0\n";
    for (int i = 0; i < 20; ++i)
        facet += "      vertex 0 0 10\n    endloop\n  endfacet\n";
    const std::string stl = (dir.path() / "unparseable.stl").string();
    std::ofstream(stl) << facet << "endsolid bad\n";
    const std::string m = errorOf([&] { loadWithAssimp(stl); });
    EXPECT_NE(m.find("unparseable.stl: assimp cannot read it: "), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_EQ(m.find("  "), std::string::npos) << m;
    EXPECT_LT(m.size(), 300u) << m;
    const std::string amf = (dir.path() / "zipped.amf").string();
    std::ofstream(amf, std::ios::binary)
        << std::string("PK\x03\x04\x14\0\0\0\x08\0", 10) << std::string(64, 'z');
    const std::string z = errorOf([&] { loadWithAssimp(amf); });
    EXPECT_NE(z.find("zipped.amf: a zip-compressed AMF file"), std::string::npos) << z;
    EXPECT_NE(z.find("unzip it"), std::string::npos) << z;
}

// OBJ says nothing of sides: a closed cube wound outwards keeps single-sided faces (culling
// them is safe), the same cube wound inwards and an open quad are drawn double-sided, or the
// camera would see their insides.
TEST(Assimp, SidesTheFileDoesNotGiveFollowTheTopology) {
    test::ScopedTempDir dir;
    const std::string corners =
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
    // Each face counter-clockwise seen from outside the unit cube.
    const char* outwards =
        "f 1 4 3\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n"
        "f 4 8 7\nf 4 7 3\nf 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n";
    std::string inwards;
    for (std::string line; const char c : std::string(outwards)) {
        if (c != '\n') {
            line += c;
            continue;
        }
        int a, b, d;
        std::sscanf(line.c_str(), "f %d %d %d", &a, &b, &d);
        inwards +=
            "f " + std::to_string(a) + " " + std::to_string(d) + " " + std::to_string(b) + "\n";
        line.clear();
    }
    auto sides = [&](const std::string& name, const std::string& text) {
        const std::string path = (dir.path() / name).string();
        std::ofstream(path) << text;
        const Scene s = loadWithAssimp(path);
        EXPECT_EQ(s.objects.size(), 1u) << name;
        return s.materials.at(s.objects.at(0).material).doubleSided;
    };
    EXPECT_FALSE(sides("out.obj", corners + outwards));
    EXPECT_TRUE(sides("in.obj", corners + inwards));
    EXPECT_TRUE(sides("quad.obj", corners + "f 1 2 3\nf 1 3 4\n"));
}

TEST(Assimp, MissingFileIsAnIoError) {
    const std::string m =
        errorOf([] { loadWithAssimp(model("no_such_model.obj")); }, ErrorKind::InvalidInput);
    EXPECT_NE(m.find("no_such_model.obj': no such file"), std::string::npos) << m;
}

// Files written at run time: faults assimp itself lets through.
TEST(Assimp, NanPositionAndBadIndexAndZeroArea) {
    test::ScopedTempDir dir;
    auto write = [&](const std::string& name, const std::string& text) {
        const std::string path = (dir.path() / name).string();
        std::ofstream(path) << text;
        return path;
    };
    const std::string nan = write("nan.obj", "o bad\nv 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string m = errorOf([&] { loadWithAssimp(nan); });
    EXPECT_NE(m.find("nan.obj"), std::string::npos) << m;
    EXPECT_NE(m.find("NaN or infinite"), std::string::npos) << m;

    const std::string zero =
        write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\n");
    const Scene s = loadWithAssimp(zero);
    EXPECT_EQ(triangles(s), 1u);
    EXPECT_TRUE(warns(s, "1 zero-area triangles skipped")) << joined(s.warnings);

    // A PLY face with no vertices (assimp 5.2 lets it through, then aborts triangulating).
    const std::string empty = write("empty_face.ply",
                                    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                    "property float y\nproperty float z\nelement face 1\n"
                                    "property list uchar int vertex_indices\nend_header\n"
                                    "0 0 0\n1 0 0\n0 1 0\n0\n");
    const std::string e = errorOf([&] { loadWithAssimp(empty); });
    EXPECT_NE(e.find("empty_face.ply: meshes[0] face 0 has no vertices"), std::string::npos) << e;

    // A material library outside the model's folder is not read, with a warning.
    std::filesystem::create_directories(dir.path() / "sub");
    write("outside.mtl", "newmtl m\nKd 1 0 0\n");
    const std::string inner = write("sub/inner.obj",
                                    "mtllib ../outside.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                    "usemtl m\nf 1 2 3\n");
    const Scene in = loadWithAssimp(inner);
    EXPECT_TRUE(warns(in, "outside.mtl' lies outside the model's folder")) << joined(in.warnings);
    EXPECT_NE(in.materials[in.objects[0].material].baseColour, glm::vec3(1, 0, 0));

    const std::string flat = write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    const std::string f = errorOf([&] { loadWithAssimp(flat); });
    EXPECT_NE(f.find("no triangles"), std::string::npos) << f;
}

TEST(Assimp, ExtensionsAreAssimps) {
    EXPECT_TRUE(assimpReads(".obj"));
    EXPECT_TRUE(assimpReads(".PLY"));
    EXPECT_TRUE(assimpReads(".stl"));
    EXPECT_TRUE(assimpReads(".dae"));
    EXPECT_FALSE(assimpReads(".png"));
    EXPECT_FALSE(assimpReads(""));
    const std::string list = assimpExtensions();
    EXPECT_NE(list.find(".obj"), std::string::npos) << list;
    EXPECT_NE(list.find(".fbx"), std::string::npos) << list;
}

TEST(Assimp, LoadSceneDispatchesByExtension) {
    const Scene s = loadScene(model("two_parts.obj"));
    EXPECT_EQ(s.objects.size(), 2u);
    test::ScopedTempDir dir;
    const std::string odd = (dir.path() / "model.xyzzy").string();
    std::ofstream(odd) << "not a model\n";
    const std::string m = errorOf([&] { loadScene(odd); });
    EXPECT_NE(m.find("'.xyzzy' files are not supported"), std::string::npos) << m;
    EXPECT_NE(m.find(".gltf"), std::string::npos) << m;  // the message lists what is
    EXPECT_NE(m.find(".obj"), std::string::npos) << m;
}

// An animation assimp's validation would refuse (a key past its clip's end) is dropped
// with a warning, and the model drawn as its nodes pose it.
TEST(Assimp, AnimationsAreDroppedBeforeValidation) {
    const Scene s = loadWithAssimp(model("anim_past_end.b3d"));
    ASSERT_TRUE(s.validate().empty()) << joined(s.validate());
    EXPECT_EQ(triangles(s), 1u);
    EXPECT_NE(joined(s.warnings).find("animations are not played"), std::string::npos)
        << joined(s.warnings);
}

// So is a light no node places; the model loads, lit by the default sun.
TEST(Assimp, UnplacedLightsAreDroppedBeforeValidation) {
    const Scene s = loadWithAssimp(model("orphan_light.ogex"));
    ASSERT_TRUE(s.validate().empty()) << joined(s.validate());
    EXPECT_EQ(triangles(s), 1u);
    EXPECT_NE(joined(s.warnings).find("1 light(s) or camera(s) that no node places"),
              std::string::npos)
        << joined(s.warnings);
}

// glTF 1.0, which tinygltf refuses, is read through assimp; a broken 2.0 file keeps
// tinygltf's own reason.
TEST(Assimp, Gltf1GoesToAssimp) {
    const Scene s = loadScene(model("quad_gltf1.gltf"));
    ASSERT_TRUE(s.validate().empty()) << joined(s.validate());
    EXPECT_EQ(triangles(s), 2u);
    expectFirstObjectSpans(s, {0, 0, 0}, {1, 1, 0});
    test::ScopedTempDir dir;
    const std::string broken = (dir.path() / "broken.gltf").string();
    std::ofstream(broken) << R"({"asset": {"version": "2.0"}, "meshes": [{"primitives": 3}]})";
    const std::string m = errorOf([&] { loadScene(broken); });
    EXPECT_EQ(m.find("assimp"), std::string::npos) << m;
    EXPECT_NE(m.find("broken.gltf"), std::string::npos) << m;
    // Binary 1.0, which assimp 5.2 does not read either, is refused saying so.
    const std::string b = errorOf([&] { loadScene(model("binary_gltf1.glb")); });
    EXPECT_NE(b.find("binary_gltf1.glb: binary glTF 1.0"), std::string::npos) << b;
}

// A bigger real model, where the shared scenes are: the course's cubes along axes.
TEST(Assimp, SharedSeedModelLoads) {
    const std::string path = std::string(GNOMON_SHARED_SCENES) + "/../seeds/models/xyz_blocks.obj";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent";
    const Scene s = loadWithAssimp(path);
    EXPECT_TRUE(s.validate().empty()) << joined(s.validate());
    EXPECT_GT(triangles(s), 100u);
}

}  // namespace
}  // namespace gnomon
