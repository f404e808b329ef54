// core/Aabb.h, the unit of shadow-camera fitting: a default box is empty, extend()
// grows it by points and boxes (an empty box adds nothing), corners() lists all eight
// combinations, transformed() bounds a rotated box (90 and 45 degrees about y, by hand).
#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "UnitTestUtil.h"
#include "core/Aabb.h"

namespace gnomon {
namespace {

Aabb box(const glm::vec3& lo, const glm::vec3& hi) {
    Aabb b;
    b.extend(lo);
    b.extend(hi);
    return b;
}

TEST(Aabb, DefaultIsEmptyAndOnePointIsNot) {
    Aabb b;
    EXPECT_TRUE(b.empty());
    b.extend(glm::vec3(1.0f, -2.0f, 3.0f));
    EXPECT_FALSE(b.empty());
    test::expectVec(b.min, {1.0f, -2.0f, 3.0f}, 0.0f);
    test::expectVec(b.max, {1.0f, -2.0f, 3.0f}, 0.0f);
    EXPECT_FLOAT_EQ(b.radius(), 0.0f);
}

TEST(Aabb, ExtendByPointsTakesComponentwiseMinAndMax) {
    Aabb b;
    b.extend(glm::vec3(1.0f, 5.0f, -1.0f));
    b.extend(glm::vec3(-2.0f, 3.0f, 4.0f));
    b.extend(glm::vec3(0.0f, 7.0f, 0.0f));  // inside on x and z, grows y
    test::expectVec(b.min, {-2.0f, 3.0f, -1.0f}, 0.0f);
    test::expectVec(b.max, {1.0f, 7.0f, 4.0f}, 0.0f);
    test::expectVec(b.centre(), {-0.5f, 5.0f, 1.5f});
    test::expectVec(b.extent(), {3.0f, 4.0f, 5.0f});
    // Half the diagonal: 0.5 * sqrt(9 + 16 + 25) = 3.5355339.
    EXPECT_NEAR(b.radius(), 3.5355339f, 1e-6f);
}

TEST(Aabb, ExtendByEmptyBoxChangesNothing) {
    Aabb b = box({0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f});
    b.extend(Aabb{});
    test::expectVec(b.min, glm::vec3(0.0f), 0.0f);
    test::expectVec(b.max, glm::vec3(1.0f), 0.0f);

    Aabb e;
    e.extend(Aabb{});
    EXPECT_TRUE(e.empty());
}

TEST(Aabb, ExtendByBoxIsTheUnion) {
    Aabb b = box({0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f});
    b.extend(box({-1.0f, 0.5f, 2.0f}, {0.5f, 3.0f, 2.5f}));
    test::expectVec(b.min, {-1.0f, 0.0f, 0.0f}, 0.0f);
    test::expectVec(b.max, {1.0f, 3.0f, 2.5f}, 0.0f);

    Aabb e;  // an empty box extended by a box becomes that box
    e.extend(box({2.0f, 2.0f, 2.0f}, {3.0f, 4.0f, 5.0f}));
    test::expectVec(e.min, {2.0f, 2.0f, 2.0f}, 0.0f);
    test::expectVec(e.max, {3.0f, 4.0f, 5.0f}, 0.0f);
}

TEST(Aabb, EmptyWhenAnyAxisIsInverted) {
    Aabb b = box(glm::vec3(0.0f), glm::vec3(1.0f));
    b.min.z = 2.0f;  // inverted on z only
    EXPECT_TRUE(b.empty());
    // A flat box (zero thickness) is not empty: a floor quad still has bounds.
    EXPECT_FALSE(box({-1.0f, 0.0f, -1.0f}, {1.0f, 0.0f, 1.0f}).empty());
}

TEST(Aabb, CornersAreTheEightCombinations) {
    const Aabb b = box({-1.0f, 2.0f, -3.0f}, {4.0f, 5.0f, 6.0f});
    std::set<std::tuple<float, float, float>> seen;
    for (const glm::vec3& c : b.corners()) {
        EXPECT_TRUE(c.x == -1.0f || c.x == 4.0f);
        EXPECT_TRUE(c.y == 2.0f || c.y == 5.0f);
        EXPECT_TRUE(c.z == -3.0f || c.z == 6.0f);
        seen.insert({c.x, c.y, c.z});
    }
    EXPECT_EQ(seen.size(), 8u);
    // The first is min, the last max.
    test::expectVec(b.corners().front(), b.min, 0.0f);
    test::expectVec(b.corners().back(), b.max, 0.0f);
}

TEST(Aabb, TransformedEmptyStaysEmpty) {
    const glm::mat4 t = glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_TRUE(Aabb{}.transformed(t).empty());
}

TEST(Aabb, TransformedByTranslationMovesTheBox) {
    const Aabb b = box({0.0f, 0.0f, 0.0f}, {1.0f, 2.0f, 3.0f});
    const Aabb t = b.transformed(glm::translate(glm::mat4(1.0f), glm::vec3(-4.0f, 0.0f, -4.0f)));
    test::expectVec(t.min, {-4.0f, 0.0f, -4.0f});
    test::expectVec(t.max, {-3.0f, 2.0f, -1.0f});
}

// Rotation by +90 degrees about y maps (x, y, z) to (z, y, -x). The box [1,2]x[0,1]x[0,3]
// becomes x in [0, 3] (from z), y unchanged, z in [-2, -1] (from -x).
TEST(Aabb, TransformedByNinetyDegreesAboutY) {
    const Aabb b = box({1.0f, 0.0f, 0.0f}, {2.0f, 1.0f, 3.0f});
    const glm::mat4 r = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 1, 0));
    const Aabb t = b.transformed(r);
    test::expectVec(t.min, {0.0f, 0.0f, -2.0f});
    test::expectVec(t.max, {3.0f, 1.0f, -1.0f});
    // A quarter turn keeps the volume: extents are a permutation.
    EXPECT_NEAR(t.extent().x * t.extent().y * t.extent().z, 3.0f, 1e-5f);
}

// The cube [-1,1]^3 turned 45 degrees about y: its corners (+-1, y, +-1) reach
// x, z = +-sqrt(2) = +-1.4142136, y stays [-1, 1]. The bounds grow (they are axis aligned).
TEST(Aabb, TransformedByFortyFiveDegreesGrows) {
    const Aabb b = box(glm::vec3(-1.0f), glm::vec3(1.0f));
    const glm::mat4 r = glm::rotate(glm::mat4(1.0f), glm::radians(45.0f), glm::vec3(0, 1, 0));
    const Aabb t = b.transformed(r);
    test::expectVec(t.min, {-1.4142136f, -1.0f, -1.4142136f});
    test::expectVec(t.max, {1.4142136f, 1.0f, 1.4142136f});
}

TEST(Aabb, TransformedHoldsEveryTransformedPoint) {
    // A composite affine transform: every point of the box (sampled) lands in the result.
    const Aabb b = box({-0.5f, 0.0f, -2.0f}, {1.5f, 3.0f, 0.25f});
    glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(3.0f, -1.0f, 2.0f));
    m = glm::rotate(m, 0.7f, glm::normalize(glm::vec3(1.0f, 2.0f, -0.5f)));
    m = glm::scale(m, glm::vec3(2.0f, 0.5f, 1.0f));
    const Aabb t = b.transformed(m);
    for (int i = 0; i <= 4; ++i)
        for (int j = 0; j <= 4; ++j)
            for (int k = 0; k <= 4; ++k) {
                const glm::vec3 p = glm::mix(b.min, b.max, glm::vec3(i, j, k) / 4.0f);
                const glm::vec3 q = glm::vec3(m * glm::vec4(p, 1.0f));
                for (int a = 0; a < 3; ++a) {
                    EXPECT_GE(q[a], t.min[a] - 1e-5f);
                    EXPECT_LE(q[a], t.max[a] + 1e-5f);
                }
            }
}

}  // namespace
}  // namespace gnomon
