// The clip -> texture mapping of (shadow::textureFromClip) and the stored depth it
// produces: NDC corners and centre, a world point seen by the WebGL book's light, and the
// perspective depth formula of (stored depth grows non-linearly with distance).
#include <cmath>

#include <gtest/gtest.h>

#include "UnitTestUtil.h"
#include "shadow/ShadowMath.h"

namespace gnomon {
namespace {

glm::vec3 toTexture(const glm::mat4& textureFromWorld, const glm::vec3& world) {
    const glm::vec4 t = textureFromWorld * glm::vec4(world, 1.0f);
    return glm::vec3(t) / t.w;
}

TEST(TextureMapping, NdcCornersMapToUnitCubeCorners) {
    const glm::mat4 m = shadow::textureFromClip();
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 ndc((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f);
        const glm::vec4 t = m * glm::vec4(ndc, 1.0f);
        SCOPED_TRACE(testing::Message() << "corner " << i);
        EXPECT_FLOAT_EQ(t.x, (i & 1) ? 1.0f : 0.0f);
        EXPECT_FLOAT_EQ(t.y, (i & 2) ? 1.0f : 0.0f);
        EXPECT_FLOAT_EQ(t.z, (i & 4) ? 1.0f : 0.0f);
        EXPECT_FLOAT_EQ(t.w, 1.0f);
    }
    const glm::vec4 centre = m * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    EXPECT_FLOAT_EQ(centre.x, 0.5f);
    EXPECT_FLOAT_EQ(centre.y, 0.5f);
    EXPECT_FLOAT_EQ(centre.z, 0.5f);
}

TEST(TextureMapping, KeepsWSoItCanBeAppliedBeforeTheDivide) {
    // Row 3 is (0, 0, 0, 1): w passes through unchanged, so textureFromClip can be folded
    // into the light's matrix and the divide done per fragment.
    const glm::mat4 m = shadow::textureFromClip();
    EXPECT_FLOAT_EQ(m[0][3], 0.0f);
    EXPECT_FLOAT_EQ(m[1][3], 0.0f);
    EXPECT_FLOAT_EQ(m[2][3], 0.0f);
    EXPECT_FLOAT_EQ(m[3][3], 1.0f);
    const glm::vec4 clip(1.5f, -0.75f, 2.0f, 3.0f);
    const glm::vec4 before = m * clip;
    const glm::vec4 after = m * (clip / clip.w);
    EXPECT_NEAR(before.x / before.w, after.x, 1e-6f);
    EXPECT_NEAR(before.y / before.w, after.y, 1e-6f);
    EXPECT_NEAR(before.z / before.w, after.z, 1e-6f);
    // (1.5/3, -0.75/3, 2/3) -> (0.75, 0.375, 0.8333)
    EXPECT_NEAR(after.x, 0.75f, 1e-6f);
    EXPECT_NEAR(after.y, 0.375f, 1e-6f);
    EXPECT_NEAR(after.z, 5.0f / 6.0f, 1e-6f);
}

// The book's light: eye (0, 7, 2) looking at the origin, up +y, perspective 70 deg, aspect 1,
// near 1, far 100.
class BookLight : public testing::Test {
protected:
    void SetUp() override {
        Light light;
        light.position = {0.0f, 7.0f, 2.0f};
        light.shadowCamera.policy = ShadowCameraPolicy::Manual;
        light.shadowCamera.projection = Projection::Perspective;
        light.shadowCamera.target = glm::vec3(0.0f);
        light.shadowCamera.up = {0.0f, 1.0f, 0.0f};
        light.shadowCamera.fovyDegrees = 70.0f;
        light.shadowCamera.aspect = 1.0f;
        light.shadowCamera.near = 1.0f;
        light.shadowCamera.far = 100.0f;
        frame = shadow::lightCameraFrame(light, Camera{}, Aabb{}, 2048);
        textureFromWorld = shadow::textureFromClip() * frame.clipFromWorld();
    }
    shadow::LightCameraFrame frame;
    glm::mat4 textureFromWorld{1.0f};
};

// The origin is the look-at target, at distance d = sqrt(49 + 4) = sqrt(53) = 7.2801099:
// texture (0.5, 0.5) and stored depth ((101 - 200/d) / 99) * 0.5 + 0.5 = 0.8713530.
TEST_F(BookLight, OriginLandsAtMapCentre) {
    ASSERT_TRUE(frame.valid);
    const glm::vec3 t = toTexture(textureFromWorld, glm::vec3(0.0f));
    EXPECT_NEAR(t.x, 0.5f, 1e-6f);
    EXPECT_NEAR(t.y, 0.5f, 1e-6f);
    EXPECT_NEAR(t.z, 0.8713530f, 1e-5f);
}

// World +x is the light's right (s = (1, 0, 0), see test_transforms.cpp for the method), and
// (1, 0, 0) has light-view coordinates (1, 0, -sqrt(53)):
//   u = 0.5 + 0.5 * (1 / tan(35 deg)) * 1 / sqrt(53) = 0.5 + 0.5 * 1.4281480 / 7.2801099
//     = 0.5980856, v = 0.5, same stored depth as the origin (same view depth).
TEST_F(BookLight, PointBesideOriginMovesRightInTheMap) {
    const glm::vec3 t = toTexture(textureFromWorld, {1.0f, 0.0f, 0.0f});
    EXPECT_NEAR(t.x, 0.5980856f, 1e-5f);
    EXPECT_NEAR(t.y, 0.5f, 1e-5f);
    EXPECT_NEAR(t.z, 0.8713530f, 1e-5f);
}

TEST_F(BookLight, TriangleAndPlaneAreInsideTheMap) {
    // The book's triangle (y = 3.5) and the plane's corners (before its tilt, |x| <= 3,
    // |z| <= 2.5 at y = -1.7) are inside the light's 70 degree frustum.
    const glm::vec3 points[] = {{-0.8f, 3.5f, 0.0f},
                                {0.8f, 3.5f, 0.0f},
                                {0.0f, 3.5f, 1.8f},
                                {3.0f, -1.7f, 2.5f},
                                {-3.0f, -1.7f, -2.5f}};
    for (const glm::vec3& p : points) {
        const glm::vec3 t = toTexture(textureFromWorld, p);
        SCOPED_TRACE(testing::Message() << "point (" << p.x << ", " << p.y << ", " << p.z << ")");
        for (int k = 0; k < 3; ++k) {
            EXPECT_GT(t[k], 0.0f);
            EXPECT_LT(t[k], 1.0f);
        }
    }
    // The triangle is nearer the light than the origin: smaller stored depth.
    EXPECT_LT(toTexture(textureFromWorld, {0.0f, 3.5f, 1.8f}).z, 0.8713530f);
}

// with c1 = 2nf/(n - f) and c2 = (f + n)/(f - n), a point at view depth d (z = -d)
// has clip z = c1 + d c2 and w = d, so stored = ((f + n)/(f - n) - 2fn/((f - n) d)) * 0.5 + 0.5.
double storedDepth(double n, double f, double d) {
    return ((f + n) / (f - n) - 2.0 * f * n / ((f - n) * d)) * 0.5 + 0.5;
}

TEST_F(BookLight, StoredDepthFollowsTheClosedForm) {
    // Hand values for n = 1, f = 100: d = 1 -> 0, d = 4 -> 0.7575758, d = 50 -> 0.9898990,
    // d = 100 -> 1.
    const struct {
        float d;
        float expected;
    } cases[] = {{1.0f, 0.0f}, {4.0f, 0.7575758f}, {50.0f, 0.9898990f}, {100.0f, 1.0f}};
    const glm::mat4 textureFromLight = shadow::textureFromClip() * frame.clipFromLight;
    for (const auto& c : cases) {
        SCOPED_TRACE(testing::Message() << "d = " << c.d);
        const glm::vec4 t = textureFromLight * glm::vec4(0.0f, 0.0f, -c.d, 1.0f);
        EXPECT_NEAR(t.w, c.d, 1e-5f);
        EXPECT_NEAR(t.z / t.w, float(storedDepth(1.0, 100.0, c.d)), 1e-5f);
        EXPECT_NEAR(t.z / t.w, c.expected, 1e-5f);
    }
}

TEST_F(BookLight, StoredDepthSpacingGrowsWithDistance) {
    // d(stored)/dd = fn / ((f - n) d^2): a step in distance at d = 50 moves the stored depth
    // (50/4)^2 = 156.25 times less than at d = 4, which is why the tolerance must follow depth.
    const glm::mat4 textureFromLight = shadow::textureFromClip() * frame.clipFromLight;
    auto stored = [&](float d) {
        const glm::vec4 t = textureFromLight * glm::vec4(0.0f, 0.0f, -d, 1.0f);
        return double(t.z) / double(t.w);
    };
    const double h = 0.1;  // central difference: O(h^2/d^2) error, float noise ~0.1%
    const double slopeNear = (stored(4.0f + float(h)) - stored(4.0f - float(h))) / (2 * h);
    const double slopeFar = (stored(50.0f + float(h)) - stored(50.0f - float(h))) / (2 * h);
    EXPECT_NEAR(slopeNear, 100.0 / (99.0 * 16.0), 1e-3);
    EXPECT_NEAR(slopeNear / slopeFar, 156.25, 156.25 * 0.05);
}

TEST(TextureMapping, OrthographicStoredDepthIsLinear) {
    // Orthographic near 1, far 20: stored = (d - n) / (f - n), so d = 10.5 -> 0.5.
    Light light;
    light.shadowCamera.policy = ShadowCameraPolicy::Manual;
    light.shadowCamera.projection = Projection::Orthographic;
    light.shadowCamera.left = light.shadowCamera.bottom = -2.0f;
    light.shadowCamera.right = light.shadowCamera.top = 2.0f;
    light.shadowCamera.near = 1.0f;
    light.shadowCamera.far = 20.0f;
    light.position = {0.0f, 0.0f, 5.0f};
    const shadow::LightCameraFrame f = shadow::lightCameraFrame(light, Camera{}, Aabb{}, 512);
    const glm::mat4 m = shadow::textureFromClip() * f.clipFromLight;
    for (float d : {1.0f, 5.75f, 10.5f, 20.0f}) {
        const glm::vec4 t = m * glm::vec4(0.0f, 0.0f, -d, 1.0f);
        EXPECT_FLOAT_EQ(t.w, 1.0f);
        EXPECT_NEAR(t.z, (d - 1.0f) / 19.0f, 1e-6f) << "d = " << d;
    }
}

}  // namespace
}  // namespace gnomon
