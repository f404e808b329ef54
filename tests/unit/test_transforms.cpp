// View and projection matrices of shadow/ShadowMath.h (viewFromWorld, clipFromView,
// safeLookAt) against values computed by hand below, not against glm calls, so a wrong
// convention (handedness, depth range, row/column order) shows up as a wrong number.
#include <cmath>

#include <gtest/gtest.h>

#include "UnitTestUtil.h"
#include "shadow/ShadowMath.h"

namespace gnomon {
namespace {

using test::matNear;

// lookAt from eye (0, 7, 9) to the origin with up +y (the book's view camera):
//   f = normalize(centre - eye) = (0, -7, -9) / sqrt(130)    sqrt(130) = 11.401754
//     = (0, -0.6139406, -0.7893522)
//   s = normalize(f x up) = normalize((-f.z, 0, f.x)) = (1, 0, 0)
//   u = s x f = (0, -f.z, f.y) = (0, 0.7893522, -0.6139406)
//   rows of the view matrix: s, u, -f; translation (-s.eye, -u.eye, f.eye)
//   -s.eye = 0; -u.eye = -(7 * 0.7893522 - 9 * 0.6139406) = 0; f.eye = -sqrt(130)
glm::mat4 handBookView() {
    const float a = 0.7893522f, b = 0.6139406f;
    glm::mat4 m(1.0f);
    m[0] = {1.0f, 0.0f, 0.0f, 0.0f};  // column 0: (s.x, u.x, -f.x)
    m[1] = {0.0f, a, b, 0.0f};        // column 1: (s.y, u.y, -f.y)
    m[2] = {0.0f, -b, a, 0.0f};       // column 2: (s.z, u.z, -f.z)
    m[3] = {0.0f, 0.0f, -11.401754f, 1.0f};
    return m;
}

Camera bookView() {
    Camera c;
    c.eye = {0.0f, 7.0f, 9.0f};
    c.centre = {0.0f, 0.0f, 0.0f};
    c.up = {0.0f, 1.0f, 0.0f};
    c.fovyDegrees = 45.0f;
    c.aspect = 0.0f;
    c.near = 1.0f;
    c.far = 100.0f;
    return c;
}

TEST(Transforms, ViewFromWorldMatchesHandComputedLookAt) {
    const glm::mat4 v = gnomon::viewFromWorld(bookView());
    EXPECT_PRED_FORMAT3(matNear, v, handBookView(), 1e-5f);
}

TEST(Transforms, ViewFromWorldPutsEyeAtOriginAndCentreDownMinusZ) {
    const glm::mat4 v = gnomon::viewFromWorld(bookView());
    const glm::vec4 eye = v * glm::vec4(0.0f, 7.0f, 9.0f, 1.0f);
    EXPECT_NEAR(glm::length(glm::vec3(eye)), 0.0f, 1e-5f);
    // The centre lies straight ahead at distance |eye| = sqrt(130).
    const glm::vec4 centre = v * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    EXPECT_NEAR(centre.x, 0.0f, 1e-5f);
    EXPECT_NEAR(centre.y, 0.0f, 1e-5f);
    EXPECT_NEAR(centre.z, -11.401754f, 1e-4f);
    // World up (a direction) keeps a positive view-space y: the image is not upside down.
    EXPECT_GT((v * glm::vec4(0.0f, 1.0f, 0.0f, 0.0f)).y, 0.5f);
    test::expectRotationPart(v);
}

// Perspective 45 deg, aspect 1, near 1, far 100 (OpenGL clip z in [-1, 1]):
//   m[0][0] = m[1][1] = 1 / tan(22.5 deg) = 2.4142136
//   m[2][2] = -(f + n) / (f - n) = -101 / 99 = -1.0202020
//   m[3][2] = -2 f n / (f - n)   = -200 / 99 = -2.0202020
//   m[2][3] = -1 (w = -z_view), everything else 0
TEST(Transforms, PerspectiveMatchesHandComputedValues) {
    Camera c = bookView();
    c.aspect = 1.0f;
    glm::mat4 expected(0.0f);
    expected[0][0] = 2.4142136f;
    expected[1][1] = 2.4142136f;
    expected[2][2] = -1.0202020f;
    expected[3][2] = -2.0202020f;
    expected[2][3] = -1.0f;
    EXPECT_PRED_FORMAT3(matNear, gnomon::clipFromView(c, 3.0f), expected, 1e-5f);
}

TEST(Transforms, PerspectiveAspectComesFromOutputWhenCameraHasNone) {
    Camera c = bookView();  // aspect 0: the output's aspect is used
    // Aspect 2: m[0][0] = 2.4142136 / 2 = 1.2071068, m[1][1] unchanged.
    const glm::mat4 wide = gnomon::clipFromView(c, 2.0f);
    EXPECT_NEAR(wide[0][0], 1.2071068f, 1e-5f);
    EXPECT_NEAR(wide[1][1], 2.4142136f, 1e-5f);
    // A camera with its own aspect ignores the output's.
    c.aspect = 1.0f;
    const glm::mat4 own = gnomon::clipFromView(c, 2.0f);
    EXPECT_NEAR(own[0][0], 2.4142136f, 1e-5f);
}

TEST(Transforms, PerspectiveMapsNearAndFarToMinusOneAndOne) {
    Camera c = bookView();
    c.aspect = 1.0f;
    const glm::mat4 p = gnomon::clipFromView(c, 1.0f);
    const glm::vec4 n = p * glm::vec4(0.0f, 0.0f, -1.0f, 1.0f);
    const glm::vec4 f = p * glm::vec4(0.0f, 0.0f, -100.0f, 1.0f);
    EXPECT_NEAR(n.z / n.w, -1.0f, 1e-5f);
    EXPECT_NEAR(f.z / f.w, 1.0f, 1e-5f);
    // A point on the top edge of the 45 deg frustum at depth 10: y = 10 tan(22.5 deg).
    const glm::vec4 top = p * glm::vec4(0.0f, 10.0f * std::tan(glm::radians(22.5f)), -10.0f, 1.0f);
    EXPECT_NEAR(top.y / top.w, 1.0f, 1e-5f);
}

// Orthographic left/bottom -2, right/top 2, near 1, far 20:
//   m[0][0] = m[1][1] = 2 / (r - l) = 0.5
//   m[2][2] = -2 / (f - n)         = -2 / 19  = -0.1052632
//   m[3][2] = -(f + n) / (f - n)   = -21 / 19 = -1.1052632
//   m[3][0] = m[3][1] = 0 (symmetric), m[3][3] = 1
TEST(Transforms, OrthographicMatchesHandComputedValues) {
    Camera c;
    c.projection = Projection::Orthographic;
    c.left = c.bottom = -2.0f;
    c.right = c.top = 2.0f;
    c.near = 1.0f;
    c.far = 20.0f;
    glm::mat4 expected(0.0f);
    expected[0][0] = 0.5f;
    expected[1][1] = 0.5f;
    expected[2][2] = -0.1052632f;
    expected[3][2] = -1.1052632f;
    expected[3][3] = 1.0f;
    // The output aspect does not stretch an orthographic volume given in numbers.
    EXPECT_PRED_FORMAT3(matNear, gnomon::clipFromView(c, 1.0f), expected, 1e-6f);
    EXPECT_PRED_FORMAT3(matNear, gnomon::clipFromView(c, 2.5f), expected, 1e-6f);
}

// Asymmetric volume l = -1, r = 3, b = 0, t = 2:
//   m[0][0] = 2/4 = 0.5, m[1][1] = 2/2 = 1, m[3][0] = -(r+l)/(r-l) = -0.5, m[3][1] = -1.
TEST(Transforms, OrthographicAsymmetricVolumeIsOffCentre) {
    Camera c;
    c.projection = Projection::Orthographic;
    c.left = -1.0f;
    c.right = 3.0f;
    c.bottom = 0.0f;
    c.top = 2.0f;
    c.near = 1.0f;
    c.far = 20.0f;
    const glm::mat4 m = gnomon::clipFromView(c, 1.0f);
    EXPECT_NEAR(m[0][0], 0.5f, 1e-6f);
    EXPECT_NEAR(m[1][1], 1.0f, 1e-6f);
    EXPECT_NEAR(m[3][0], -0.5f, 1e-6f);
    EXPECT_NEAR(m[3][1], -1.0f, 1e-6f);
    // The volume's corner (3, 2, -20) lands on (1, 1, 1).
    const glm::vec4 corner = m * glm::vec4(3.0f, 2.0f, -20.0f, 1.0f);
    EXPECT_NEAR(corner.x, 1.0f, 1e-6f);
    EXPECT_NEAR(corner.y, 1.0f, 1e-6f);
    EXPECT_NEAR(corner.z, 1.0f, 1e-5f);
}

// Looking straight down from (0, 5, 0) with up +y: up is parallel to the view direction.
// The direction (0, -1, 0) is least aligned with x, so x is used as up:
//   f = (0, -1, 0), s = f x x = (0, 0, 1), u = s x f = (1, 0, 0), translation (0, 0, -5).
TEST(Transforms, SafeLookAtWithUpParallelToViewIsFiniteAndOrthonormal) {
    const glm::mat4 m =
        gnomon::safeLookAt({0.0f, 5.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    ASSERT_TRUE(test::allFinite(m));
    test::expectRotationPart(m);
    glm::mat4 expected(1.0f);
    expected[0] = {0.0f, 1.0f, 0.0f, 0.0f};  // (s.x, u.x, -f.x)
    expected[1] = {0.0f, 0.0f, 1.0f, 0.0f};  // (s.y, u.y, -f.y)
    expected[2] = {1.0f, 0.0f, 0.0f, 0.0f};  // (s.z, u.z, -f.z)
    expected[3] = {0.0f, 0.0f, -5.0f, 1.0f};
    EXPECT_PRED_FORMAT3(matNear, m, expected, 1e-6f);
}

TEST(Transforms, SafeLookAtSurvivesAntiParallelAndNearlyParallelUp) {
    const glm::vec3 eyes[] = {{0.0f, -3.0f, 0.0f}, {0.0f, 0.0f, 4.0f}, {2.0f, 0.0f, 0.0f}};
    for (const glm::vec3& eye : eyes) {
        const glm::vec3 dir = glm::normalize(-eye);
        for (const glm::vec3& up : {dir, -dir, dir + glm::vec3(1e-5f, 0.0f, 1e-5f)}) {
            SCOPED_TRACE(testing::Message()
                         << "eye (" << eye.x << ", " << eye.y << ", " << eye.z << ") up (" << up.x
                         << ", " << up.y << ", " << up.z << ")");
            const glm::mat4 m = gnomon::safeLookAt(eye, glm::vec3(0.0f), up);
            ASSERT_TRUE(test::allFinite(m));
            test::expectRotationPart(m);
            // Still a look-at: the eye goes to the origin, the centre straight ahead.
            const glm::vec4 c = m * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
            EXPECT_NEAR(c.x, 0.0f, 1e-5f);
            EXPECT_NEAR(c.y, 0.0f, 1e-5f);
            EXPECT_NEAR(c.z, -glm::length(eye), 1e-5f);
        }
    }
}

TEST(Transforms, SafeLookAtWithUsableUpKeepsThatUp) {
    // Up tilted but not parallel: the camera's up is the given up made orthogonal to the
    // view direction, so the view-space x axis is orthogonal to the given up.
    const glm::vec3 up = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
    const glm::mat4 m = gnomon::safeLookAt({1.0f, 2.0f, 8.0f}, {0.0f, 0.0f, 0.0f}, up);
    const glm::vec3 s(m[0][0], m[1][0], m[2][0]);
    const glm::vec3 u(m[0][1], m[1][1], m[2][1]);
    const glm::vec3 forward = glm::normalize(-glm::vec3(1.0f, 2.0f, 8.0f));
    EXPECT_NEAR(glm::dot(s, up), 0.0f, 1e-6f);
    // u is up minus its component along the view direction, renormalised.
    const float along = glm::dot(up, forward);
    EXPECT_NEAR(glm::dot(u, up), std::sqrt(1.0f - along * along), 1e-5f);
}

TEST(Transforms, SafeLookAtWithZeroUpIsFinite) {
    // A zero up vector is "parallel" to every direction; the documented promise is a usable
    // matrix whenever up cannot define the roll.
    const glm::mat4 m =
        gnomon::safeLookAt({0.0f, 7.0f, 9.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f});
    ASSERT_TRUE(test::allFinite(m));
    test::expectRotationPart(m);
}

// depthFitted: the view's planes move in to the depths the scene's box spans (camera on +z
// looking at the origin, so view depth = 10 - z), and only in.
TEST(Transforms, DepthFittedSpansTheSceneBox) {
    Camera c;
    c.eye = {0.0f, 0.0f, 10.0f};
    c.centre = {0.0f, 0.0f, 0.0f};
    c.near = 0.01f;
    c.far = 1e6f;
    const Aabb box{{-1.0f, -1.0f, -2.0f}, {1.0f, 1.0f, 2.0f}};  // depths 8 to 12
    const Camera f = shadow::depthFitted(c, box);
    EXPECT_GT(f.near, 7.5f);
    EXPECT_LT(f.near, 8.0f);
    EXPECT_GT(f.far, 12.0f);
    EXPECT_LT(f.far, 12.5f);
    EXPECT_EQ(f.eye, c.eye);
    // Planes already inside the box's depths stay where they are.
    Camera tight = c;
    tight.near = 9.0f;
    tight.far = 11.0f;
    EXPECT_EQ(shadow::depthFitted(tight, box), tight);
    // An eye inside the box keeps its near plane; a box behind the eye or an empty one
    // changes nothing.
    Camera inside = c;
    inside.eye = {0.0f, 0.0f, 1.0f};
    EXPECT_EQ(shadow::depthFitted(inside, box).near, c.near);
    EXPECT_LT(shadow::depthFitted(inside, box).far, 3.5f);
    Camera away = c;
    away.centre = {0.0f, 0.0f, 20.0f};
    EXPECT_EQ(shadow::depthFitted(away, box), away);
    EXPECT_EQ(shadow::depthFitted(c, Aabb{}), c);
    // Orthographic: the same depths, with no perspective margin.
    Camera ortho = c;
    ortho.projection = Projection::Orthographic;
    const Camera o = shadow::depthFitted(ortho, box);
    EXPECT_GT(o.near, 7.9f);
    EXPECT_LT(o.far, 12.2f);
}

}  // namespace
}  // namespace gnomon
