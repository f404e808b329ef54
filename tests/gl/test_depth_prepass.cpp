// The main pass started from the view depth pass's depth (--depth-prepass): it must give the
// very image the pass gives on its own, masked and blended surfaces included, and it must
// actually start from that depth where the view depth pass is drawn for the view.
#include <gtest/gtest.h>

#include <filesystem>

#include "GlTest.h"

namespace gnomon::test {
namespace {

struct Rendered {
    Image image;
    bool fromViewDepth = false;
};

Rendered renderWithPrepass(const Scene& s, bool prepass, int size) {
    RenderOptions o = s.options;
    o.width = o.height = size;
    o.shading.depthPrepass = prepass;
    Renderer& r = sharedRenderer();
    Rendered out{r.render(s, o), false};
    out.fromViewDepth = r.lastFrameStats().mainFromViewDepth;
    return out;
}

void expectSameImageFromViewDepth(const Scene& s, int size) {
    const Rendered with = renderWithPrepass(s, true, size);
    const Rendered without = renderWithPrepass(s, false, size);
    EXPECT_TRUE(with.fromViewDepth)
        << s.name << ": the main pass did not start from the view depth";
    EXPECT_FALSE(without.fromViewDepth);
    ASSERT_EQ(with.image.pixels.size(), without.image.pixels.size());
    long differing = 0;
    for (std::size_t i = 0; i < without.image.pixels.size(); ++i)
        differing += with.image.pixels[i] != without.image.pixels[i];
    if (differing) {
        writePng(std::string(GNOMON_TEST_OUTPUT_DIR) + "/prepass-" + s.name + "-on.png",
                 with.image);
        writePng(std::string(GNOMON_TEST_OUTPUT_DIR) + "/prepass-" + s.name + "-off.png",
                 without.image);
    }
    EXPECT_EQ(differing, 0) << s.name << ": the view depth changed " << differing << " bytes";
}

TEST(DepthPrepass, MixedLightsSameImage) {
    // Its objects stand on a floor drawn first: the floor under them is no longer shaded.
    expectSameImageFromViewDepth(builtinScene("mixed-lights"), 256);
}

TEST(DepthPrepass, TutorialRoomSameImage) {
    expectSameImageFromViewDepth(builtinScene("tutorial-room"), 256);
}

TEST(DepthPrepass, MaskedAndBlendedSurfacesSameImage) {
    // Masked panels are cut in the view depth as in the main pass; blended ones are not in
    // it and are drawn over what it holds.
    const std::string file =
        std::string(GNOMON_SHARED_SCENES) + "/AlphaBlendModeTest/AlphaBlendModeTest.glb";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " is absent";
    Scene s = loadScene(file);
    addGround(s);
    expectSameImageFromViewDepth(s, 192);
}

TEST(DepthPrepass, NotWhereNoViewDepthIsDrawn) {
    // Fitted to boxes, without tiles or contact shadows, no view depth pass is drawn, and
    // none is drawn for the main pass alone.
    Scene s = builtinScene("tutorial-room");
    s.options.shadow.fitTo = FitTo::Boxes;
    s.options.shading.lightTiles = LightTiles::Off;
    EXPECT_FALSE(renderWithPrepass(s, true, 128).fromViewDepth);
}

}  // namespace
}  // namespace gnomon::test
