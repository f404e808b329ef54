// gnomon score over a path (temporal stability): nothing moving gives no flicker; a dolly
// with unstabilised fitted maps shimmers (their texel grid slides with the view) and the
// same dolly with stabilised maps holds still on a scene whose quantised sizes do not step;
// frames that follow one another keep their maps.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "GlTest.h"

namespace gnomon::test {
namespace {

PathScoreResult dolly(const std::string& pathName, bool stabilise) {
    Scene s = builtinScene("tutorial-room");
    RenderOptions o = s.options;
    o.width = o.height = 128;
    o.shadow.mapSize = 256;  // coarse texels: a slide of a fraction of one moves many edges
    o.shadow.stabilise = stabilise;
    o.shadow.shadowRays = ShadowRayMode::Off;  // the maps' shimmer
    const ScenePath path = makeScenePath(pathName, s, 6);
    const Camera before = s.camera;
    PathScoreResult r = scorePath(sharedRenderer(), s, o, path, {}, true);
    // The scene's view is put back.
    EXPECT_EQ(s.camera.eye, before.eye);
    return r;
}

TEST(Flicker, StillPathIsZero) {
    const PathScoreResult r = dolly("still", false);
    ASSERT_EQ(r.frames.size(), 6u);
    EXPECT_FALSE(r.interrupted);
    for (std::size_t i = 1; i < r.frames.size(); ++i) {
        EXPECT_GT(r.frames[i].compared, 1000);
        EXPECT_EQ(r.frames[i].flickered, 0) << "frame " << i;
    }
    EXPECT_EQ(r.meanFlicker, 0.0);
}

TEST(Flicker, UnstabilisedMapsShimmerAndStabilisedOnesHoldStill) {
    const PathScoreResult off = dolly("dolly", false);
    const PathScoreResult on = dolly("dolly", true);
    ASSERT_EQ(off.frames.size(), 6u);
    ASSERT_EQ(on.frames.size(), 6u);
    EXPECT_GT(off.meanFlicker, 0.0001);
    EXPECT_EQ(on.meanFlicker, 0.0);
    // Flicker shows in the frame's error map in yellow.
    long yellow = 0;
    for (const PathFrameScore& f : off.frames) {
        for (std::size_t p = 0; p + 3 < f.errors.pixels.size(); p += 4)
            yellow += f.errors.pixels[p] == 255 && f.errors.pixels[p + 1] == 220 &&
                      f.errors.pixels[p + 2] == 0;
    }
    long flickered = 0;
    for (const PathFrameScore& f : off.frames)
        flickered += f.flickered;
    EXPECT_GT(yellow, 0);
    EXPECT_LE(yellow, flickered);  // a pixel flickers for one light here: at most one each
    const nlohmann::json j = nlohmann::json::parse(toJson(off, "tutorial-room", RenderOptions{}));
    EXPECT_EQ(j["frames"].size(), 6u);
    EXPECT_DOUBLE_EQ(j["mean_flicker"].get<double>(), off.meanFlicker);
}

// Frames that follow one another hold a stabilised map's extent while it covers the view:
// a camera moved 3 % closer draws no shadow map again, while a single render of the new
// view (fitted afresh) needs another map. Shown by the maps rendered in the second frame.
TEST(Flicker, FollowingFramesHoldTheirMaps) {
    Scene s = builtinScene("tutorial-room");
    RenderOptions o = s.options;
    o.width = o.height = 128;
    const Camera start = s.camera;
    auto passesAfterMove = [&](bool following) {
        Renderer& r = sharedRenderer();
        r.setFollowing(following);
        r.invalidateShadowMaps();
        s.camera = start;
        (void)r.render(s, o);
        s.camera.eye = start.centre + 0.97f * (start.eye - start.centre);
        (void)r.render(s, o);
        r.setFollowing(false);
        return r.lastFrameStats().shadowPasses;
    };
    EXPECT_GE(passesAfterMove(false), 1);
    EXPECT_EQ(passesAfterMove(true), 0);
    s.camera = start;
}

}  // namespace
}  // namespace gnomon::test
