// Renderer behaviour beyond "shadows are where geometry says": the shadowed-fragment rules
// of the Blinn-Phong shading, the outside-the-map policies (lit or clamped), light switches, and
// clear errors for bad input.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include "GeometryShadows.h"
#include "GlTest.h"
#include "render/GpuScene.h"
#include "scene/MeshBuilder.h"

namespace gnomon::test {
namespace {

RenderOptions small(const Scene& s) {
    RenderOptions o = s.options;
    o.width = o.height = 256;
    return o;
}

// The label `gles` runs these tests on OpenGL ES, the others on OpenGL 4.5 core: each on the
// API it names, so that a silent fallback cannot pass for the web's path.
TEST(Renderer, RunsOnTheApiAskedFor) {
    const std::string info = sharedRenderer().glInfo();
    EXPECT_EQ(info.find("OpenGL ES") != std::string::npos, testsGles()) << info;
}

TEST(Renderer, BookShadowIsColourTimesFactor) {
    const Scene s = builtinScene("book-triangle");
    RenderOptions o = small(s);
    RenderOptions off = o;
    off.shadow.enabled = false;
    const Image on = sharedRenderer().render(s, o), plain = sharedRenderer().render(s, off);
    const GeometryShadows truth = classifyPixels(s, o, 3);
    int checked = 0;
    for (int y = 0; y < 256; ++y) {
        for (int x = 0; x < 256; ++x) {
            if (truth.classes[size_t(y) * 256 + x] != PixelClass::Shadowed) continue;
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(on.at(x, y)[c], 0.7 * plain.at(x, y)[c], 1.5) << x << "," << y;
            }
            ++checked;
        }
    }
    EXPECT_GT(checked, 20);
}

TEST(Renderer, AmbientOnlyRuleDropsTheLightsContribution) {
    Scene s = builtinScene("tutorial-room");
    RenderOptions o = small(s);
    o.shading.shadowedRule = ShadowedRule::AmbientOnly;
    s.lights[0].intensity = 0.0f;  // the same view with the sun contributing nothing
    const Image noSun = sharedRenderer().render(s, o);
    const Scene lit = builtinScene("tutorial-room");
    const Image on = sharedRenderer().render(lit, o);
    const GeometryShadows truth = classifyPixels(lit, o, 3);
    int checked = 0;
    for (int y = 0; y < 256; ++y) {
        for (int x = 0; x < 256; ++x) {
            if (truth.classes[size_t(y) * 256 + x] != PixelClass::Shadowed) continue;
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(on.at(x, y)[c], noSun.at(x, y)[c], 1.5);
            ++checked;
        }
    }
    EXPECT_GT(checked, 20);
}

// A box straddles the edge of a light's orthographic map: with clamp-to-edge, the floor
// beyond the edge reads the box's depth from the edge texels and gets a false shadow streak
// (the textbooks' "almost certainly wrong"); with the outside-is-lit policy it is lit.
TEST(Renderer, ClampOutsideTheMapShowsTheTextbookError) {
    Scene s;
    s.name = "edge streak";
    s.materials.push_back(Material{});
    s.meshes.push_back(mesh::quad("floor", {-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}));
    s.meshes.push_back(mesh::box("box", {4.8f, 0.5f, 0.0f}, glm::vec3(1.0f)));
    s.objects.push_back({"floor", 0, 0, glm::mat4(1.0f), {}, true, true});
    s.objects.push_back({"box", 1, 0, glm::mat4(1.0f), {}, true, true});
    Light l;
    l.type = LightType::Directional;
    l.direction = {0.0f, -1.0f, 0.0f};
    l.position = {0.0f, 10.0f, 0.0f};
    l.shadowMapSize = 256;
    l.shadowCamera.policy = ShadowCameraPolicy::Manual;
    l.shadowCamera.projection = Projection::Orthographic;
    l.shadowCamera.up = {0.0f, 0.0f, -1.0f};
    l.shadowCamera.left = l.shadowCamera.bottom = -5.0f;
    l.shadowCamera.right = l.shadowCamera.top = 5.0f;
    l.shadowCamera.near = 1.0f;
    l.shadowCamera.far = 20.0f;
    s.lights.push_back(l);
    s.camera.eye = {0.0f, 18.0f, 8.0f};
    s.ambient = glm::vec3(0.2f);

    RenderOptions lit, clamp, off;
    lit.width = lit.height = clamp.width = clamp.height = off.width = off.height = 256;
    clamp.shadow.outside = OutsidePolicy::Clamp;
    off.shadow.enabled = false;
    const Image a = sharedRenderer().render(s, lit), b = sharedRenderer().render(s, clamp),
                c = sharedRenderer().render(s, off);
    // Floor pixels beyond the map's +x edge (x > 5.2), away from the box.
    const glm::mat4 clipFromWorld = [&] {
        Camera cam = s.camera;
        return glm::perspective(glm::radians(cam.fovyDegrees), 1.0f, cam.near, cam.far) *
               glm::lookAt(cam.eye, cam.centre, cam.up);
    }();
    int streak = 0, litUnchanged = 0, probes = 0;
    for (float x = 6.0f; x < 7.5f; x += 0.25f) {  // inside the view
        for (float z = -0.3f; z <= 0.3f; z += 0.3f) {
            const glm::vec4 p = clipFromWorld * glm::vec4(x, 0.0f, z, 1.0f);
            const int px = int((p.x / p.w * 0.5f + 0.5f) * 256);
            const int py = int((0.5f - p.y / p.w * 0.5f) * 256);
            ++probes;
            streak += luminance(b.at(px, py)) + 30 < luminance(c.at(px, py));
            litUnchanged += luminance(a.at(px, py)) == luminance(c.at(px, py));
        }
    }
    EXPECT_EQ(streak, probes) << "clamp-to-edge should streak the box's depth beyond the edge";
    EXPECT_EQ(litUnchanged, probes) << "outside the map must be lit";
}

TEST(Renderer, LightOnlySelectsOneLight) {
    const Scene s = builtinScene("course-two-lights");
    RenderOptions o0 = small(s), o1 = small(s);
    o0.lightOnly = 0;
    o1.lightOnly = 1;
    const Image a = sharedRenderer().render(s, o0);
    EXPECT_EQ(sharedRenderer().lastFrameStats().shadowPasses, 1);
    const Image b = sharedRenderer().render(s, o1);
    EXPECT_GT(compareImages(a, b, 8).failingFraction, 0.05);
    RenderOptions bad = small(s);
    bad.lightOnly = 2;
    EXPECT_THROW(sharedRenderer().render(s, bad), Error);
}

TEST(Renderer, InvalidOptionsAreRejectedByName) {
    const Scene s = builtinScene("book-triangle");
    RenderOptions o = small(s);
    o.shadow.pcfSize = 4;
    try {
        sharedRenderer().render(s, o);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::InvalidInput);
        EXPECT_NE(std::string(e.what()).find("pcf-size"), std::string::npos) << e.what();
    }
}

TEST(Renderer, BrokenSceneIsRejectedWithItsLocation) {
    Scene s = builtinScene("book-triangle");
    s.meshes[1].positions[2].y = std::nanf("");
    try {
        sharedRenderer().render(s, small(s));
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("meshes[1]"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("not finite"), std::string::npos) << e.what();
    }
}

// The CLI warns of a camera that shows none of the scene; the test behind it is conservative:
// false only where the scene's bounds lie wholly beyond one side of the view volume, or in
// front of the camera within less than a pixel.
TEST(Renderer, CameraSeesSceneUnlessTheBoundsLieBeyondOneSideOrWithinAPixel) {
    Scene s = builtinScene("tutorial-room");
    EXPECT_TRUE(cameraSeesScene(s, 64, 64));
    s.camera.eye = {0.0f, 5.0f, 30.0f};  // outside the room, turned away from it
    s.camera.centre = {0.0f, 5.0f, 60.0f};
    EXPECT_FALSE(cameraSeesScene(s, 64, 64));
    s.camera.centre = {0.0f, 5.0f, 0.0f};  // turned back towards it
    EXPECT_TRUE(cameraSeesScene(s, 64, 64));
    s.camera.far = 1.0f;  // but it all lies past the far plane
    EXPECT_FALSE(cameraSeesScene(s, 64, 64));
    s.camera.far = 100.0f;
    s.camera.centre = {300.0f, 5.0f, 30.0f};  // off to the side: it lies past the left plane
    EXPECT_FALSE(cameraSeesScene(s, 64, 64));
    s.camera.centre = {0.0f, 5.0f, 0.0f};
    s.camera.far = 1e7f;
    s.camera.eye = {0.0f, 5.0f, 300.0f};  // far down the axis: the room spans a few pixels
    EXPECT_TRUE(cameraSeesScene(s, 64, 64));
    s.camera.eye = {0.0f, 5.0f, 1e4f};  // further: under a pixel
    EXPECT_FALSE(cameraSeesScene(s, 64, 64));
    EXPECT_TRUE(cameraSeesScene(s, 4096, 4096)) << "a larger image resolves it";
    EXPECT_TRUE(cameraSeesScene(Scene{}, 64, 64)) << "nothing to see is not a camera's fault";
}

TEST(Renderer, ShadowsOffRendersNoShadowPass) {
    const Scene s = builtinScene("course-cubes");
    RenderOptions o = small(s);
    o.shadow.enabled = false;
    sharedRenderer().render(s, o);
    EXPECT_EQ(sharedRenderer().lastFrameStats().shadowPasses, 0);
    EXPECT_EQ(sharedRenderer().lastFrameStats().shadowMapBytes, 0u);
    EXPECT_TRUE(sharedRenderer().shadowMaps().empty());
}

// Object records reach the vertex stages as texels of a buffer texture (render::GpuScene): a
// scene whose records outgrow the driver's limit is refused with one sentence naming the
// counts, not a GL error or a wrong image. The limit itself (2^27 texels on llvmpipe) is out
// of a test's reach, so the sentence is checked against a small one.
TEST(Renderer, ObjectRecordsBeyondTheBufferTextureLimitAreNamed) {
    EXPECT_EQ(render::objectRecordsOverflow(10, 130), "");
    const std::string why = render::objectRecordsOverflow(11, 130);
    EXPECT_NE(why.find("11 objects"), std::string::npos) << why;
    EXPECT_NE(why.find("143 texels"), std::string::npos) << why;
    EXPECT_NE(why.find("130"), std::string::npos) << why;
    (void)sharedRenderer().glInfo();  // makes its context current
    GLint most = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &most);
    EXPECT_GE(most, 65536) << "GL 4.5's minimum";
}

}  // namespace
}  // namespace gnomon::test
