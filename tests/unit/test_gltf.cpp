// glTF loading (issue 5): the shared test scenes load into the scene model as their files
// say (triangles, lights, instances, mirrored winding, double-sided materials), and broken
// files are refused with the file, the element and what is wrong. Tests that need
// ../shared/scenes skip with a message where it is absent.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "gnomon/Error.h"
#include "gnomon/Scene.h"
#include "scene/GltfLoader.h"

namespace gnomon {
namespace {

std::string shared(const std::string& file) {
    return std::string(GNOMON_SHARED_SCENES) + "/" + file;
}
std::string corpus(const std::string& file) {
    return std::string(GNOMON_GLTF_CORPUS) + "/" + file;
}

#define NEED_SHARED(file)                                                                   \
    if (!std::filesystem::exists(shared(file))) {                                           \
        GTEST_SKIP() << shared(file) << " is absent (the shared test scenes are not here)"; \
    }

std::size_t triangles(const Scene& s) {
    std::size_t n = 0;
    for (const Object& o : s.objects)
        n += s.meshes[o.mesh].indices.size() / 3;
    return n;
}

TEST(Gltf, BoxLoadsWithADefaultSunAndCamera) {
    NEED_SHARED("Box/Box.glb");
    const Scene s = loadGltf(shared("Box/Box.glb"));
    EXPECT_TRUE(s.validate().empty());
    EXPECT_EQ(triangles(s), 12u);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, LightType::Directional);
    bool warnedSun = false, warnedCamera = false;
    for (const std::string& w : s.warnings) {
        warnedSun |= w.find("default sun") != std::string::npos;
        warnedCamera |= w.find("no camera") != std::string::npos;
    }
    EXPECT_TRUE(warnedSun);
    EXPECT_TRUE(warnedCamera);
    // The camera frames the box: its centre straight ahead.
    EXPECT_GT(glm::length(s.camera.eye - s.camera.centre), 1.0f);
}

TEST(Gltf, LampHasItsFivePointLights) {
    NEED_SHARED("LightsPunctualLamp/LightsPunctualLamp.gltf");
    const Scene s = loadGltf(shared("LightsPunctualLamp/LightsPunctualLamp.gltf"));
    EXPECT_TRUE(s.validate().empty());
    ASSERT_EQ(s.lights.size(), 5u);
    for (const Light& l : s.lights) {
        EXPECT_EQ(l.type, LightType::Point);
        EXPECT_TRUE(l.castsShadows);
        EXPECT_EQ(l.attenuation.quadratic, 1.0f);  // 1/d^2
    }
    // Intensities keep the file's ratios (15, 1.5, 80, 80, 180 candela), scaled for display.
    EXPECT_NEAR(s.lights[4].intensity / s.lights[0].intensity, 12.0f, 1e-3f);
    EXPECT_NEAR(s.lights[1].intensity / s.lights[0].intensity, 0.1f, 1e-4f);
}

TEST(Gltf, InstancingMakesOneObjectPerInstance) {
    NEED_SHARED("SimpleInstancing/SimpleInstancing.glb");
    const Scene s = loadGltf(shared("SimpleInstancing/SimpleInstancing.glb"));
    EXPECT_TRUE(s.validate().empty());
    EXPECT_EQ(s.objects.size(), 125u);
    EXPECT_EQ(triangles(s), 1500u);
}

TEST(Gltf, TwoSidedPlaneIsDoubleSided) {
    NEED_SHARED("TwoSidedPlane/TwoSidedPlane.gltf");
    const Scene s = loadGltf(shared("TwoSidedPlane/TwoSidedPlane.gltf"));
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_TRUE(s.materials[s.objects[0].material].doubleSided);
    EXPECT_EQ(triangles(s), 2u);
}

// Mirrored nodes flip winding: in world space every triangle's winding normal (what GL
// culls by) points the way its vertex normals do, mirrored or not.
TEST(Gltf, MirroredNodesKeepFrontFacesFront) {
    NEED_SHARED("NegativeScaleTest/NegativeScaleTest.glb");
    const Scene s = loadGltf(shared("NegativeScaleTest/NegativeScaleTest.glb"));
    int mirrored = 0;
    std::size_t checked = 0, agree = 0;
    for (const Object& o : s.objects) {
        const glm::mat3 m(o.worldFromModel);
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(m));
        mirrored += glm::determinant(m) < 0.0f;
        const Mesh& mesh = s.meshes[o.mesh];
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const glm::vec3 a = m * mesh.positions[mesh.indices[i]];
            const glm::vec3 b = m * mesh.positions[mesh.indices[i + 1]];
            const glm::vec3 c = m * mesh.positions[mesh.indices[i + 2]];
            const glm::vec3 winding = glm::cross(b - a, c - a);
            const glm::vec3 n =
                normalMatrix * (mesh.normals[mesh.indices[i]] + mesh.normals[mesh.indices[i + 1]] +
                                mesh.normals[mesh.indices[i + 2]]);
            if (glm::length(winding) < 1e-9f || glm::length(n) < 1e-6f) continue;
            ++checked;
            agree += glm::dot(winding, n) > 0.0f;
        }
    }
    EXPECT_GT(mirrored, 0) << "the test scene has mirrored nodes";
    ASSERT_GT(checked, 1000u);
    EXPECT_GT(double(agree) / double(checked), 0.99);
}

TEST(Gltf, OurTriangleLoads) {
    const Scene s = loadGltf(corpus("triangle.gltf"));
    EXPECT_TRUE(s.validate().empty());
    EXPECT_EQ(triangles(s), 1u);
    bool flat = false;
    for (const std::string& w : s.warnings)
        flat |= w.find("flat ones generated") != std::string::npos;
    EXPECT_TRUE(flat);
    EXPECT_EQ(s.meshes[0].normals[0], glm::vec3(0, 0, 1));  // CCW in the xy plane
}

// MSFT_lod: the node's mesh keeps the coarser versions its node names, finest first, in
// the mesh's model space; the extension is read, not ignored.
TEST(Gltf, MsftLodVersionsGoWithTheirMesh) {
    const Scene s = loadGltf(corpus("lod_spheres.gltf"));
    ASSERT_EQ(s.objects.size(), 1u);  // the versions' nodes are not placed themselves
    const Mesh& m = s.meshes[s.objects[0].mesh];
    EXPECT_EQ(m.indices.size() / 3, 48u * 46u);
    ASSERT_EQ(m.lods.size(), 2u);
    EXPECT_EQ(m.lods[0].indices.size() / 3, 16u * 14u);
    EXPECT_EQ(m.lods[1].indices.size() / 3, 8u * 6u);
    for (const MeshLod& lod : m.lods) {
        for (const glm::vec3& p : lod.positions)
            EXPECT_NEAR(glm::length(p - glm::vec3(0.0f, 1.0f, 0.0f)), 0.5f, 1e-5f);
        for (std::uint32_t i : lod.indices)
            ASSERT_LT(i, lod.positions.size());
    }
    for (const std::string& w : s.warnings)
        EXPECT_EQ(w.find("MSFT_lod"), std::string::npos) << w;
}

TEST(Gltf, TexturedMaskedQuadKeepsItsTextureAlphaAndTransform) {
    const Scene s = loadGltf(corpus("textured_quad.gltf"));
    EXPECT_TRUE(s.validate().empty());
    ASSERT_EQ(s.textures.size(), 1u);
    const Texture& t = s.textures[0];
    EXPECT_EQ(t.width, 2);
    EXPECT_EQ(t.height, 1);
    EXPECT_EQ(t.rgba, (std::vector<std::uint8_t>{255, 0, 0, 255, 0, 255, 0, 0}));
    EXPECT_EQ(t.wrapS, TextureWrap::ClampToEdge);
    EXPECT_TRUE(t.nearest);
    ASSERT_EQ(s.objects.size(), 1u);
    const Material& m = s.materials[s.objects[0].material];
    EXPECT_EQ(m.baseColourTexture, 0);
    EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(m.alphaCutoff, 0.4f);
    EXPECT_FLOAT_EQ(m.alpha, 0.9f);
    EXPECT_TRUE(m.doubleSided);
    // KHR_texture_transform offset (0.25, 0): uv (0.5, 0.5) is read at (0.75, 0.5).
    const glm::vec3 moved = m.uvTransform * glm::vec3(0.5f, 0.5f, 1.0f);
    EXPECT_FLOAT_EQ(moved.x, 0.75f);
    EXPECT_FLOAT_EQ(moved.y, 0.5f);
    const Mesh& mesh = s.meshes[s.objects[0].mesh];
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        // The file's uv: u = x, v = 1 - y.
        EXPECT_FLOAT_EQ(mesh.uvs[i].x, mesh.positions[i].x);
        EXPECT_FLOAT_EQ(mesh.uvs[i].y, 1.0f - mesh.positions[i].y);
    }
}

TEST(Gltf, KhrTextureTransformRotatesAsItsSpecExampleSays) {
    // The extension's example: offset (0, 1), rotation pi/2, scale 0.5 shows the lower-left
    // quadrant of the image turned: uv (0, 0) reads (0, 1), uv (1, 0) reads (0, 0.5).
    // Checked through the loader on a copy of the textured quad.
    std::ifstream in(corpus("textured_quad.gltf"));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto at = text.find("\"KHR_texture_transform\": {");
    ASSERT_NE(at, std::string::npos);
    const auto open = text.find('{', at), close = text.find('}', at);
    text.replace(open, close - open + 1,
                 "{\"offset\": [0, 1], \"rotation\": 1.5707963268, \"scale\": [0.5, 0.5]}");
    const Scene s = loadGltf(std::vector<unsigned char>(text.begin(), text.end()), "rotated.gltf",
                             GNOMON_GLTF_CORPUS);
    const glm::mat3& m = s.materials[s.objects[0].material].uvTransform;
    const glm::vec3 a = m * glm::vec3(0, 0, 1), b = m * glm::vec3(1, 0, 1);
    EXPECT_NEAR(a.x, 0.0f, 1e-6f);
    EXPECT_NEAR(a.y, 1.0f, 1e-6f);
    EXPECT_NEAR(b.x, 0.0f, 1e-6f);
    EXPECT_NEAR(b.y, 0.5f, 1e-6f);
}

TEST(Gltf, AlphaBlendModeTestHasMaskedAndBlendedTexturedMaterials) {
    NEED_SHARED("AlphaBlendModeTest/AlphaBlendModeTest.glb");
    const Scene s = loadGltf(shared("AlphaBlendModeTest/AlphaBlendModeTest.glb"));
    EXPECT_TRUE(s.validate().empty());
    int mask = 0, blend = 0, textured = 0;
    for (const Object& o : s.objects) {
        const Material& m = s.materials[o.material];
        mask += m.alphaMode == AlphaMode::Mask;
        blend += m.alphaMode == AlphaMode::Blend;
        textured += m.baseColourTexture >= 0;
    }
    EXPECT_GE(mask, 3);
    EXPECT_GE(blend, 1);
    EXPECT_EQ(textured, int(s.objects.size()));
    for (const Texture& t : s.textures)
        EXPECT_EQ(t.rgba.size(), std::size_t(t.width) * std::size_t(t.height) * 4);
}

struct Broken {
    const char* file;
    const char* says;  // a part of the message
    ErrorKind kind;
};
void PrintTo(const Broken& b, std::ostream* os) {
    *os << b.file;
}
class BrokenFiles : public testing::TestWithParam<Broken> {};

TEST_P(BrokenFiles, AreRefusedWithWhereAndWhat) {
    try {
        loadGltf(corpus(GetParam().file));
        FAIL() << "loaded";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_EQ(e.kind(), GetParam().kind) << m;
        EXPECT_NE(m.find(GetParam().file), std::string::npos) << "no file name: " << m;
        EXPECT_NE(m.find(GetParam().says), std::string::npos) << m;
    }
}

// A binary glTF whose header length is right but whose chunk overruns the file: the message
// names the chunk, its offset and the bytes it claims.
TEST(Gltf, GlbChunkOverrunNamesTheChunkAndItsOffset) {
    const std::string json = R"({"asset":{"version":"2.0"}})";
    std::string glb = "glTF";
    const auto u32 = [&](std::uint32_t v) {
        for (int i = 0; i < 4; ++i)
            glb.push_back(static_cast<char>(v >> (8 * i)));
    };
    u32(2);
    u32(std::uint32_t(12 + 8 + json.size()));
    u32(std::uint32_t(json.size() + 100));  // claims 100 bytes more than there are
    glb += "JSON" + json;
    const std::vector<unsigned char> bytes(glb.begin(), glb.end());
    try {
        loadGltf(bytes, "overrun.glb", ".");
        FAIL() << "loaded a GLB whose chunk overruns the file";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::InvalidInput);
        EXPECT_NE(std::string(e.what()).find("overrun.glb: broken binary glTF: chunk 0 at offset "
                                             "12 claims 127 bytes of data, only 27 remain"),
                  std::string::npos)
            << e.what();
    }
}

// A file tinygltf refuses names the extensions it requires, which are often why (a Draco-
// compressed mesh fails tinygltf's parse before gnomon's own check of extensions).
TEST(GltfErrors, ARefusalNamesTheRequiredExtensions) {
    try {
        loadScene(corpus("draco_unparsed.gltf"));
        FAIL() << "loaded";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("nothere.bin"), std::string::npos) << m;
        EXPECT_NE(m.find("(the file requires KHR_draco_mesh_compression)"), std::string::npos) << m;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Corpus, BrokenFiles,
    testing::Values(
        Broken{"bad_json.gltf", "parse error", ErrorKind::InvalidInput},
        Broken{"missing_buffer.gltf", "nothere.bin", ErrorKind::InvalidInput},
        Broken{"escape_uri.gltf", "inside the scene's folder only", ErrorKind::InvalidInput},
        Broken{"absolute_uri.gltf", "inside the scene's folder only", ErrorKind::InvalidInput},
        Broken{"index_out_of_range.gltf", "accessors[1] holds index 7", ErrorKind::InvalidInput},
        Broken{"accessor_overrun.gltf", "accessors[0] (40 elements from byte 0) overruns",
               ErrorKind::InvalidInput},
        Broken{"nan_position.gltf", "accessors[0] (POSITION) holds NaN", ErrorKind::InvalidInput},
        Broken{"required_extension.gltf", "requires extension KHR_draco_mesh_compression",
               ErrorKind::InvalidInput},
        Broken{"cycle.gltf", "nodes[0] is its own ancestor", ErrorKind::InvalidInput},
        Broken{"lod_missing_node.gltf",
               "nodes[0] MSFT_lod names nodes[7], which does not exist or has no mesh",
               ErrorKind::InvalidInput},
        Broken{"empty_scene.gltf", "no triangles", ErrorKind::InvalidInput},
        Broken{"zero_area.gltf", "no triangles", ErrorKind::InvalidInput},
        Broken{"lines_only.gltf", "no triangles", ErrorKind::InvalidInput},
        Broken{"truncated.glb",
               "broken binary glTF: the header at offset 8 gives a length of 1000 bytes, the "
               "file has 21 (truncated?)",
               ErrorKind::InvalidInput},
        Broken{"bad_image.gltf", "images[0]: the image cannot be decoded", ErrorKind::InvalidInput},
        Broken{"no_such_file.gltf", "no such file", ErrorKind::InvalidInput}),
    [](const auto& info) {
        std::string n = info.param.file;
        for (char& c : n)
            c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
        return n;
    });

}  // namespace
}  // namespace gnomon
