// Shared by the scene-file tests: comparing scenes (exactly for round trips, else within
// 1e-6), reading and writing text files, and the message a file fails to load with.
#pragma once

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "UnitTestUtil.h"
#include "gnomon/Error.h"
#include "gnomon/OptionSchema.h"
#include "gnomon/Scene.h"
#include "gnomon/SceneFile.h"

namespace gnomon::test {

namespace fs = std::filesystem;

const std::string kExamples = GNOMON_EXAMPLE_SCENES;
const std::string kCorpus = GNOMON_SCENE_FILE_CORPUS;
const char* const kExampleNames[] = {"book-triangle", "book-triangle-far", "course-two-lights",
                                     "course-cubes",  "tutorial-room",     "tutorial-room-thin"};

// ---- Comparison: `exact` for round trips, else within 1e-6 (relative above 1)

struct Compare {
    bool exact;

    void num(double a, double e, const std::string& what) const {
        if (exact) {
            EXPECT_EQ(a, e) << what;
        } else {
            EXPECT_NEAR(a, e, 1e-6 * std::max(1.0, std::fabs(e))) << what;
        }
    }
    void vec(const glm::vec3& a, const glm::vec3& e, const std::string& what) const {
        for (int i = 0; i < 3; ++i)
            num(a[i], e[i], what + "[" + std::to_string(i) + "]");
    }
    void vecs(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& e,
              const std::string& what) const {
        ASSERT_EQ(a.size(), e.size()) << what;
        for (std::size_t i = 0; i < a.size(); ++i)
            vec(a[i], e[i], what + "[" + std::to_string(i) + "]");
    }
    void mat(const glm::mat4& a, const glm::mat4& e, const std::string& what) const {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                num(a[c][r], e[c][r],
                    what + "[" + std::to_string(c) + "][" + std::to_string(r) + "]");
    }

    // Every option through the schema's accessors, named as the CLI names it.
    void options(const RenderOptions& a, const RenderOptions& e, const std::string& what) const {
        for (const OptionSpec& spec : optionSchema()) {
            if (spec.kind == OptionKind::Size) {
                EXPECT_EQ(a.width, e.width) << what << " size (width)";
                EXPECT_EQ(a.height, e.height) << what << " size (height)";
            } else {
                num(spec.get(a), spec.get(e), what + " " + spec.name);
            }
        }
        // A member of RenderOptions that no option holds would differ unseen above.
        if (exact) {
            EXPECT_TRUE(a == e) << what << ": a member that is no option differs";
        }
    }

    void light(const Light& a, const Light& e, const std::string& w) const {
        EXPECT_EQ(a.name, e.name) << w;
        EXPECT_EQ(a.type, e.type) << w << " type";
        EXPECT_EQ(a.enabled, e.enabled) << w << " enabled";
        vec(a.position, e.position, w + " position");
        vec(a.direction, e.direction, w + " direction");
        vec(a.colour, e.colour, w + " colour");
        num(a.intensity, e.intensity, w + " intensity");
        num(a.attenuation.constant, e.attenuation.constant, w + " attenuation.constant");
        num(a.attenuation.linear, e.attenuation.linear, w + " attenuation.linear");
        num(a.attenuation.quadratic, e.attenuation.quadratic, w + " attenuation.quadratic");
        num(a.innerConeDegrees, e.innerConeDegrees, w + " innerConeDegrees");
        num(a.outerConeDegrees, e.outerConeDegrees, w + " outerConeDegrees");
        EXPECT_EQ(a.castsShadows, e.castsShadows) << w << " castsShadows";
        EXPECT_EQ(a.shadowMapSize, e.shadowMapSize) << w << " shadowMapSize";
        const ShadowCamera &c = a.shadowCamera, &d = e.shadowCamera;
        EXPECT_EQ(c.policy, d.policy) << w << " shadowCamera.policy";
        EXPECT_EQ(c.projection, d.projection) << w << " shadowCamera.projection";
        vec(c.target, d.target, w + " shadowCamera.target");
        vec(c.up, d.up, w + " shadowCamera.up");
        num(c.fovyDegrees, d.fovyDegrees, w + " shadowCamera.fovyDegrees");
        num(c.aspect, d.aspect, w + " shadowCamera.aspect");
        num(c.near, d.near, w + " shadowCamera.near");
        num(c.far, d.far, w + " shadowCamera.far");
        num(c.left, d.left, w + " shadowCamera.left");
        num(c.right, d.right, w + " shadowCamera.right");
        num(c.bottom, d.bottom, w + " shadowCamera.bottom");
        num(c.top, d.top, w + " shadowCamera.top");
    }

    void camera(const Camera& a, const Camera& e) const {
        vec(a.eye, e.eye, "camera.eye");
        vec(a.centre, e.centre, "camera.centre");
        vec(a.up, e.up, "camera.up");
        EXPECT_EQ(a.projection, e.projection) << "camera.projection";
        num(a.fovyDegrees, e.fovyDegrees, "camera.fovyDegrees");
        num(a.aspect, e.aspect, "camera.aspect");
        num(a.near, e.near, "camera.near");
        num(a.far, e.far, "camera.far");
        num(a.left, e.left, "camera.left");
        num(a.right, e.right, "camera.right");
        num(a.bottom, e.bottom, "camera.bottom");
        num(a.top, e.top, "camera.top");
    }

    // Meshes, materials and objects, including every object's triangles in world space.
    void geometry(const Scene& a, const Scene& e) const {
        ASSERT_EQ(a.meshes.size(), e.meshes.size()) << "mesh count";
        for (std::size_t m = 0; m < a.meshes.size(); ++m) {
            const std::string w = "meshes[" + std::to_string(m) + "]";
            EXPECT_EQ(a.meshes[m].name, e.meshes[m].name) << w;
            vecs(a.meshes[m].positions, e.meshes[m].positions, w + ".positions");
            vecs(a.meshes[m].normals, e.meshes[m].normals, w + ".normals");
            vecs(a.meshes[m].colours, e.meshes[m].colours, w + ".colours");
            EXPECT_EQ(a.meshes[m].uvs.size(), e.meshes[m].uvs.size()) << w;
            EXPECT_EQ(a.meshes[m].indices, e.meshes[m].indices) << w << ".indices";
        }
        ASSERT_EQ(a.materials.size(), e.materials.size()) << "material count";
        for (std::size_t m = 0; m < a.materials.size(); ++m) {
            const Material &x = a.materials[m], &y = e.materials[m];
            const std::string w = "materials[" + std::to_string(m) + "] " + y.name;
            EXPECT_EQ(x.name, y.name) << w;
            vec(x.baseColour, y.baseColour, w + " baseColour");
            num(x.specular, y.specular, w + " specular");
            num(x.shininess, y.shininess, w + " shininess");
            EXPECT_EQ(x.unlit, y.unlit) << w << " unlit";
            EXPECT_EQ(x.doubleSided, y.doubleSided) << w << " doubleSided";
            num(x.alpha, y.alpha, w + " alpha");
            EXPECT_EQ(x.baseColourTexture, y.baseColourTexture) << w;
            EXPECT_EQ(x.alphaMode, y.alphaMode) << w << " alphaMode";
            num(x.alphaCutoff, y.alphaCutoff, w + " alphaCutoff");
        }
        EXPECT_EQ(a.textures.size(), e.textures.size());
        ASSERT_EQ(a.objects.size(), e.objects.size()) << "object count";
        for (std::size_t o = 0; o < a.objects.size(); ++o) {
            const Object &x = a.objects[o], &y = e.objects[o];
            const std::string w = "objects[" + std::to_string(o) + "] " + y.name;
            EXPECT_EQ(x.name, y.name) << w;
            ASSERT_EQ(x.mesh, y.mesh) << w << " mesh";
            EXPECT_EQ(x.material, y.material) << w << " material";
            mat(x.worldFromModel, y.worldFromModel, w + " worldFromModel");
            vec(x.spin.axis, y.spin.axis, w + " spin.axis");
            num(x.spin.degreesPerSecond, y.spin.degreesPerSecond, w + " spin.degreesPerSecond");
            vec(x.spin.pivot, y.spin.pivot, w + " spin.pivot");
            EXPECT_EQ(x.castsShadows, y.castsShadows) << w << " castsShadows";
            EXPECT_EQ(x.receivesShadows, y.receivesShadows) << w << " receivesShadows";
            // The triangles where they are drawn, posed at a time the spin matters.
            const glm::mat4 xa = x.worldFromModelAt(1.5), ya = y.worldFromModelAt(1.5);
            const Mesh &xm = a.meshes[x.mesh], &ym = e.meshes[y.mesh];
            for (std::size_t i = 0; i < std::min(xm.positions.size(), ym.positions.size()); ++i) {
                vec(glm::vec3(xa * glm::vec4(xm.positions[i], 1.0f)),
                    glm::vec3(ya * glm::vec4(ym.positions[i], 1.0f)),
                    w + " world position " + std::to_string(i));
            }
        }
    }

    void scene(const Scene& a, const Scene& e) const {
        EXPECT_EQ(a.name, e.name);
        EXPECT_EQ(a.description, e.description);
        geometry(a, e);
        ASSERT_EQ(a.lights.size(), e.lights.size()) << "light count";
        for (std::size_t l = 0; l < a.lights.size(); ++l)
            light(a.lights[l], e.lights[l], "lights[" + std::to_string(l) + "]");
        camera(a.camera, e.camera);
        vec(a.ambient, e.ambient, "ambient");
        options(a.options, e.options, "options");
        ASSERT_EQ(a.textbookOptions.has_value(), e.textbookOptions.has_value());
        if (e.textbookOptions) options(*a.textbookOptions, *e.textbookOptions, "textbook options");
    }
};

inline std::string readText(const fs::path& p) {
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

inline void writeText(const fs::path& p, const std::string& text) {
    std::ofstream(p) << text;
}

// The message loading `path` fails with ("" when it loads).
inline std::string errorOf(const std::string& path) {
    try {
        (void)loadSceneFile(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

// The message a file with `text` fails with.
inline std::string errorOfText(const ScopedTempDir& dir, const std::string& text) {
    const fs::path p = dir.path() / "bad.json";
    writeText(p, text);
    return errorOf(p.string());
}

}  // namespace gnomon::test
