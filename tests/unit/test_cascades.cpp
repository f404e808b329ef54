// Cascaded shadow maps: the uniform/log split blend, and stabilised cascade
// cameras: every point of the view slice inside the cascade, a size that does not change as
// the view turns, and an origin that moves in whole texels as the view moves.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "shadow/ShadowMath.h"

namespace gnomon {
namespace {

TEST(Cascades, SplitsBlendUniformAndLogarithmic) {
    const auto uniform = shadow::cascadeSplits(1.0f, 101.0f, 4, 0.0f);
    const auto log = shadow::cascadeSplits(1.0f, 100.0f, 2, 1.0f);
    ASSERT_EQ(uniform.size(), 5u);
    for (int i = 0; i <= 4; ++i)
        EXPECT_NEAR(uniform[size_t(i)], 1.0f + 25.0f * float(i), 1e-4f);
    EXPECT_NEAR(log[1], 10.0f, 1e-4f);  // sqrt(1 * 100)
    const auto half = shadow::cascadeSplits(1.0f, 100.0f, 2, 0.5f);
    EXPECT_NEAR(half[1], 0.5f * 10.0f + 0.5f * 50.5f, 1e-4f);
    for (float lambda : {0.0f, 0.3f, 0.75f, 1.0f}) {
        const auto s = shadow::cascadeSplits(0.5f, 80.0f, 4, lambda);
        EXPECT_EQ(s.front(), 0.5f);
        EXPECT_EQ(s.back(), 80.0f);
        for (size_t i = 1; i < s.size(); ++i)
            EXPECT_GT(s[i], s[i - 1]);
    }
}

Camera viewCamera(const glm::vec3& eye, const glm::vec3& centre) {
    Camera c;
    c.eye = eye;
    c.centre = centre;
    c.fovyDegrees = 50.0f;
    c.near = 0.5f;
    c.far = 80.0f;
    return c;
}

const glm::vec3 kSun = glm::normalize(glm::vec3(0.267f, -0.802f, 0.535f));

Aabb scene() {
    Aabb b;
    b.extend(glm::vec3(-10.0f, -0.5f, -10.0f));
    b.extend(glm::vec3(10.0f, 6.0f, 10.0f));
    return b;
}

TEST(Cascades, SliceIsInsideItsCascade) {
    const Camera view = viewCamera({-14.0f, 9.0f, -3.0f}, {2.0f, 1.0f, 3.0f});
    const auto splits = shadow::cascadeSplits(view.near, 30.0f, 4, 0.75f);
    for (int c = 0; c < 4; ++c) {
        const auto f = shadow::cascadeFrame(kSun, view, 1.0f, splits[size_t(c)],
                                            splits[size_t(c) + 1], scene(), 1024);
        const glm::mat4 worldFromView = glm::inverse(gnomon::viewFromWorld(view));
        const float tanY = std::tan(glm::radians(25.0f));
        for (int i = 0; i < 8; ++i) {
            const float d = (i & 4) ? splits[size_t(c) + 1] : splits[size_t(c)];
            const glm::vec3 vs((i & 1 ? 1 : -1) * tanY * d, (i & 2 ? 1 : -1) * tanY * d, -d);
            const glm::vec4 clip = f.clipFromWorld() * worldFromView * glm::vec4(vs, 1.0f);
            for (int k = 0; k < 3; ++k)
                EXPECT_LE(std::abs(clip[k]), 1.0f + 1e-4f) << c;
        }
        // Every scene corner between the light and the slice is inside the depth range.
        for (const glm::vec3& corner : scene().corners()) {
            const glm::vec4 clip = f.clipFromWorld() * glm::vec4(corner, 1.0f);
            EXPECT_GE(clip.z, -1.0f - 1e-4f) << "a caster towards the light is cut off";
        }
    }
}

TEST(Cascades, TurningTheViewKeepsTheCascadeSize) {
    const Camera a = viewCamera({0.0f, 5.0f, 0.0f}, {10.0f, 0.0f, 0.0f});
    const Camera b = viewCamera({0.0f, 5.0f, 0.0f}, {7.0f, 0.0f, 7.0f});
    const auto fa = shadow::cascadeFrame(kSun, a, 1.0f, 0.5f, 10.0f, scene(), 1024);
    const auto fb = shadow::cascadeFrame(kSun, b, 1.0f, 0.5f, 10.0f, scene(), 1024);
    EXPECT_FLOAT_EQ(fa.clipFromLight[0][0], fb.clipFromLight[0][0]);
    EXPECT_FLOAT_EQ(fa.texelWorldSize, fb.texelWorldSize);
}

TEST(Cascades, MovingTheViewMovesTheCascadeInWholeTexels) {
    for (float dx : {0.001f, 0.0137f, 0.25f, 1.3f}) {
        const Camera a = viewCamera({0.0f, 5.0f, 0.0f}, {10.0f, 0.0f, 0.0f});
        const Camera b = viewCamera({dx, 5.0f, 0.0f}, {10.0f + dx, 0.0f, 0.0f});
        const auto fa = shadow::cascadeFrame(kSun, a, 1.0f, 0.5f, 10.0f, scene(), 1024);
        const auto fb = shadow::cascadeFrame(kSun, b, 1.0f, 0.5f, 10.0f, scene(), 1024);
        // A fixed world point lands on the same sub-texel position in both maps.
        const glm::vec3 p(3.3f, 0.0f, 1.7f);
        const glm::vec4 ca = fa.clipFromWorld() * glm::vec4(p, 1.0f);
        const glm::vec4 cb = fb.clipFromWorld() * glm::vec4(p, 1.0f);
        for (int k = 0; k < 2; ++k) {
            const double ta = (ca[k] * 0.5 + 0.5) * 1024.0, tb = (cb[k] * 0.5 + 0.5) * 1024.0;
            const double shift = ta - tb;
            EXPECT_NEAR(shift, std::round(shift), 2e-3) << "dx " << dx << " axis " << k;
        }
    }
}

}  // namespace
}  // namespace gnomon
