// Light tiles (--light-tiles): the main pass drawn in screen tiles, each with only the lights
// that reach it, must give the very image of the untiled pass, and must actually tile where
// spot lights leave parts of the screen unlit.
#include <gtest/gtest.h>

#include "GlTest.h"

namespace gnomon::test {
namespace {

struct Rendered {
    Image image;
    int tiles = 0;
};

Rendered renderWithTiles(const Scene& s, bool tiles, int size) {
    RenderOptions o = s.options;
    o.width = o.height = size;
    o.shading.lightTiles = tiles;
    Renderer& r = sharedRenderer();
    Rendered out{r.render(s, o), 0};
    out.tiles = r.lastFrameStats().lightTiles;
    return out;
}

void expectSameImageTiled(const Scene& s, int size) {
    const Rendered tiled = renderWithTiles(s, true, size);
    const Rendered plain = renderWithTiles(s, false, size);
    EXPECT_GT(tiled.tiles, 1) << s.name << ": the main pass was not tiled";
    EXPECT_EQ(plain.tiles, 0);
    ASSERT_EQ(tiled.image.pixels.size(), plain.image.pixels.size());
    long differing = 0;
    for (std::size_t i = 0; i < plain.image.pixels.size(); ++i)
        differing += tiled.image.pixels[i] != plain.image.pixels[i];
    EXPECT_EQ(differing, 0) << s.name << ": tiles changed " << differing << " bytes";
}

TEST(LightTiles, MixedLightsSameImageInTiles) {
    expectSameImageTiled(builtinScene("mixed-lights"), 256);
}

TEST(LightTiles, SpotsOnEitherSideSameImageInTiles) {
    // Two narrow spots lighting the left and the right of tutorial-spot's floor: the tiles
    // between and beyond their pools drop both lookups.
    Scene s = builtinScene("tutorial-spot");
    ASSERT_FALSE(s.lights.empty());
    Light left = s.lights.front();
    left.type = LightType::Spot;
    left.outerConeDegrees = 12.0f;
    left.innerConeDegrees = 8.0f;
    Light right = left;
    left.position.x -= 3.0f;
    right.position.x += 3.0f;
    s.lights = {left, right};
    expectSameImageTiled(s, 256);
}

}  // namespace
}  // namespace gnomon::test
