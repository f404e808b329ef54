// Which faces of a point light's cube the view looks up (shadow::cubeFacesSeen): a face no
// pixel of the view falls in, grown by its pad and the lookups' reach, is skipped; one any
// such pixel falls in never is. Checked on hand-placed samples and, as a property, on random
// ones: every point of a sample's segment, moved within its pad and the margin, lies in a
// face the mask holds.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "shadow/ShadowMath.h"
#include "shadow/ViewSamples.h"

namespace gnomon {
namespace {

constexpr std::uint8_t bit(int face) {
    return std::uint8_t(1u << face);
}

// The face (0..5: +X, -X, +Y, -Y, +Z, -Z) of a direction: its largest axis.
int faceOf(const glm::vec3& d) {
    const glm::vec3 a = glm::abs(d);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    return 2 * axis + (d[axis] < 0.0f ? 1 : 0);
}

shadow::ViewSamples samplesAt(std::initializer_list<glm::vec3> points, float pad = 0.001f) {
    shadow::ViewSamples s;
    for (const glm::vec3& p : points) {
        s.points.emplace_back(p, 1.0f);
        s.farthestNext.push_back(false);
    }
    s.padConstant = pad;
    return s;
}

TEST(CubeFacesSeen, APointWellInsideAFaceNeedsThatFaceAlone) {
    const glm::vec3 light(1.0f, 2.0f, 3.0f);
    for (int face = 0; face < 6; ++face) {
        glm::vec3 d(0.1f, -0.2f, 0.15f);
        d[face / 2] = face % 2 ? -5.0f : 5.0f;
        EXPECT_EQ(shadow::cubeFacesSeen(samplesAt({light + d}), light, 0.01f), bit(face));
    }
}

TEST(CubeFacesSeen, APointByAnEdgeNeedsBothFacesItsLookupsReach) {
    // 0.3 degrees from the edge between +X and +Y: a margin of a degree reaches across.
    const glm::vec3 d(1.0f, std::tan(glm::radians(44.7f)), 0.0f);
    EXPECT_EQ(shadow::cubeFacesSeen(samplesAt({d}), glm::vec3(0.0f), 0.0175f), bit(0) | bit(2));
    EXPECT_EQ(shadow::cubeFacesSeen(samplesAt({d}), glm::vec3(0.0f), 0.001f), bit(0));
}

TEST(CubeFacesSeen, ACellsDepthRangeNeedsTheFacesBetweenItsEnds) {
    // Ends in +X and +Z; the segment between passes over +Y (its middle is (5, 9, 5)).
    const glm::vec3 a(10.0f, 9.0f, 0.0f), b(0.0f, 9.0f, 10.0f);
    shadow::ViewSamples s = samplesAt({a, b});
    EXPECT_EQ(shadow::cubeFacesSeen(s, glm::vec3(0.0f), 0.001f), bit(0) | bit(4));
    s.farthestNext[0] = true;  // one cell's nearest and farthest
    EXPECT_EQ(shadow::cubeFacesSeen(s, glm::vec3(0.0f), 0.001f), bit(0) | bit(2) | bit(4));
}

TEST(CubeFacesSeen, PadsOrMarginsTooWideToBoundNeedEveryFace) {
    const glm::vec3 d(5.0f, 0.0f, 0.0f);
    EXPECT_EQ(shadow::cubeFacesSeen(samplesAt({d}, 6.0f), glm::vec3(0.0f), 0.0f),
              shadow::kAllCubeFaces);
    EXPECT_EQ(shadow::cubeFacesSeen(samplesAt({d}, 1.0f), glm::vec3(0.0f), 0.0f),
              shadow::kAllCubeFaces);
    EXPECT_EQ(shadow::cubeFacesSeen(samplesAt({d}), glm::vec3(0.0f), 0.2f), shadow::kAllCubeFaces);
}

TEST(CubeFacesSeen, EveryPointWithinReachOfASampleLiesInAFaceDrawn) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    auto direction = [&] {
        glm::vec3 v;
        do
            v = glm::vec3(u(rng), u(rng), u(rng));
        while (glm::length(v) < 0.1f || glm::length(v) > 1.0f);
        return glm::normalize(v);
    };
    const glm::vec3 light(0.5f, -1.0f, 2.0f);
    int skipped = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const glm::vec3 a = light + (3.0f + 5.0f * std::abs(u(rng))) * direction();
        const glm::vec3 b = a + 2.0f * u(rng) * direction();
        const bool pair = trial % 2 == 0;
        const float pad = 0.05f * std::abs(u(rng)), margin = 0.03f * std::abs(u(rng));
        shadow::ViewSamples s = samplesAt(
            pair ? std::initializer_list<glm::vec3>{a, b} : std::initializer_list<glm::vec3>{a},
            pad);
        if (pair) s.farthestNext[0] = true;
        const std::uint8_t faces = shadow::cubeFacesSeen(s, light, margin);
        skipped += faces != shadow::kAllCubeFaces;
        for (int k = 0; k < 50; ++k) {
            const glm::vec3 onSegment = pair ? glm::mix(a, b, 0.5f + 0.5f * u(rng)) : a;
            const glm::vec3 padded = onSegment + pad * std::abs(u(rng)) * direction();
            // Turned by up to `margin` about the light: what a lookup reads around the point.
            const glm::vec3 d = padded - light;
            const glm::vec3 across = glm::normalize(glm::cross(d, direction()));
            const float turn = margin * std::abs(u(rng));
            const glm::vec3 read = std::cos(turn) * d + std::sin(turn) * glm::length(d) * across;
            EXPECT_TRUE(faces & bit(faceOf(read)))
                << "trial " << trial << ": face " << faceOf(read) << " not in " << int(faces);
        }
    }
    EXPECT_GT(skipped, 1000);  // the test means something: most masks leave faces out
}

TEST(CubeFacesSeen, LookupReachGrowsWithTheFilterAndTheNormalOffset) {
    const float pcf3 = shadow::cubeLookupReachTexels(ShadowOptions{});
    ShadowOptions o;
    o.pcfSize = 7;
    EXPECT_GT(shadow::cubeLookupReachTexels(o), pcf3);
    o = ShadowOptions{};
    o.normalOffset = 2.0f;
    EXPECT_GT(shadow::cubeLookupReachTexels(o), pcf3);
    o.filter = ShadowFilter::Pcss;
    EXPECT_GE(shadow::cubeLookupReachTexels(o), 49.0f);  // its search reaches 48 texels
}

}  // namespace
}  // namespace gnomon
