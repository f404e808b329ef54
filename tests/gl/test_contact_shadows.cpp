// Screen-space contact shadows (--contact-length): on tutorial-room-thin with a tolerance
// large enough to detach the shadows from their casters (peter-panning, the failure they
// are for), a march of one unit towards the sun gives back the contacts: the leak, scored
// against the ray-traced reference, falls to under half, and false shadow barely rises.
#include <gtest/gtest.h>

#include "GlTest.h"

namespace gnomon::test {
namespace {

RenderOptions detached(const Scene& s) {
    RenderOptions o = s.options;
    o.width = o.height = 256;
    o.shadow.biasConstant = 0.06f;
    return o;
}

TEST(ContactShadows, HalveTheLeakAtDetachedContacts) {
    const Scene s = builtinScene("tutorial-room-thin");
    RenderOptions off = detached(s), on = detached(s);
    on.shadow.contactLength = 1.0f;
    ScoreOptions contacts;
    contacts.contactRange = 1.0f;  // the leak over the pixels shadowed within the march, too
    const ScoreResult without = score(sharedRenderer(), s, off, contacts);
    const ScoreResult with = score(sharedRenderer(), s, on, contacts);
    ASSERT_GT(without.overall.leak, 0.0005) << "the tolerance no longer detaches the shadows";
    EXPECT_LT(with.overall.leak, 0.5 * without.overall.leak)
        << "leak " << with.overall.leak << " with contact shadows, " << without.overall.leak
        << " without";
    ASSERT_GT(without.overall.contactPixels, 100);
    EXPECT_EQ(with.overall.contactPixels, without.overall.contactPixels);
    EXPECT_LT(with.overall.contactLeak, 0.5 * without.overall.contactLeak)
        << "leak at contacts " << with.overall.contactLeak << " with contact shadows, "
        << without.overall.contactLeak << " without";
    EXPECT_LT(with.overall.falseShadow, without.overall.falseShadow + 0.0002)
        << "false shadow " << with.overall.falseShadow << " with, " << without.overall.falseShadow
        << " without";
}

// Where the map already has the contacts (the defaults), the march adds no false shadow.
TEST(ContactShadows, AddNoFalseShadowWhereTheMapIsRight) {
    const Scene s = builtinScene("tutorial-room");
    RenderOptions off = s.options;
    off.width = off.height = 256;
    RenderOptions on = off;
    on.shadow.contactLength = 0.5f;
    const ScoreResult without = score(sharedRenderer(), s, off);
    const ScoreResult with = score(sharedRenderer(), s, on);
    EXPECT_LT(with.overall.falseShadowOutsideBand, 0.0005);
    EXPECT_LT(with.overall.misclassified, without.overall.misclassified + 0.0005)
        << with.overall.misclassified << " with contact shadows, " << without.overall.misclassified
        << " without";
}

// A march shorter than the receiver's depth change across a pixel, under a sun that comes
// from behind the surfaces as the camera sees them (the march moves away from the camera):
// its first steps read the depth buffer at the fragment's own pixel and its neighbours,
// where the receiver itself lies nearer the camera than the step. They must not take it for
// an occluder (the march of 0.01), nor the two depth passes' rounding of the same surface
// (the march of 0.001).
TEST(ContactShadows, AShortMarchDoesNotShadowItsOwnReceiver) {
    Scene s = builtinScene("tutorial-room");
    ASSERT_EQ(s.lights.size(), 1u);
    s.lights[0].direction = -glm::vec3(0.0f, 0.5f, 0.8660254f);  // --sun 0,30
    RenderOptions off = s.options;
    off.width = off.height = 192;
    const ScoreResult without = score(sharedRenderer(), s, off);
    for (const float length : {0.001f, 0.01f}) {
        RenderOptions on = off;
        on.shadow.contactLength = length;
        const ScoreResult with = score(sharedRenderer(), s, on);
        EXPECT_LT(with.overall.falseShadow, without.overall.falseShadow + 0.0002)
            << "march " << length << ": false shadow " << with.overall.falseShadow << " with, "
            << without.overall.falseShadow << " without";
    }
}

}  // namespace
}  // namespace gnomon::test
