// Light tiles (--light-tiles): the main pass drawn in screen tiles (draws), or drawn once with
// each pixel reading its tile's lights (lists), each tile with only the lights that reach it,
// must give the image of the untiled pass, and must actually tile where spot or ranged lights
// leave parts of the screen unlit. The lists' texels for a known layout are checked against
// what each tile's lights must be.
#include <algorithm>
#include <set>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "GlTest.h"
#include "render/TiledLights.h"

namespace gnomon::test {
namespace {

struct Rendered {
    Image image;
    int tiles = 0, lists = 0;
};

Rendered renderWithTiles(const Scene& s, LightTiles mode, int size) {
    RenderOptions o = s.options;
    o.width = o.height = size;
    o.shading.lightTiles = mode;
    Renderer& r = sharedRenderer();
    Rendered out{r.render(s, o), 0, 0};
    out.tiles = r.lastFrameStats().lightTiles;
    out.lists = r.lastFrameStats().lightLists;
    return out;
}

// Bytes that differ between two images, and by how much at most.
struct Difference {
    long bytes = 0;
    int most = 0;
};
Difference difference(const Image& a, const Image& b) {
    Difference d;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const int delta = std::abs(int(a.pixels[i]) - int(b.pixels[i]));
        d.bytes += delta != 0;
        d.most = std::max(d.most, delta);
    }
    return d;
}

// `mode` tiles the frame and gives the untiled image: the same bytes, or within a rounding
// step on at most `share` of them (lights shaded in the same order either way, but in loops
// where the untiled draw may write them out).
void expectSameImage(const Scene& s, LightTiles mode, int size, double share = 0.0) {
    const Rendered tiled = renderWithTiles(s, mode, size);
    const Rendered plain = renderWithTiles(s, LightTiles::Off, size);
    if (mode == LightTiles::Lists) {
        EXPECT_GT(tiled.lists, 1) << s.name << ": no light lists";
        EXPECT_EQ(tiled.tiles, 0);
    } else {
        EXPECT_GT(tiled.tiles, 1) << s.name << ": the main pass was not tiled";
        EXPECT_EQ(tiled.lists, 0);
    }
    EXPECT_EQ(plain.tiles + plain.lists, 0);
    ASSERT_EQ(tiled.image.pixels.size(), plain.image.pixels.size());
    const Difference d = difference(tiled.image, plain.image);
    EXPECT_LE(d.most, share > 0.0 ? 1 : 0) << s.name << ": tiles changed a byte by " << d.most;
    EXPECT_LE(double(d.bytes), share * double(plain.image.pixels.size()))
        << s.name << ": tiles changed " << d.bytes << " bytes";
}

TEST(LightTiles, MixedLightsSameImageInTiles) {
    expectSameImage(builtinScene("mixed-lights"), LightTiles::Draws, 256);
}

TEST(LightTiles, MixedLightsSameImageFromLists) {
    expectSameImage(builtinScene("mixed-lights"), LightTiles::Lists, 256);
}

// Two narrow spots lighting the left and the right of tutorial-spot's floor: the tiles
// between and beyond their pools drop both lookups.
Scene spotsOnEitherSide() {
    Scene s = builtinScene("tutorial-spot");
    Light left = s.lights.front();
    left.type = LightType::Spot;
    left.outerConeDegrees = 12.0f;
    left.innerConeDegrees = 8.0f;
    Light right = left;
    left.position.x -= 3.0f;
    right.position.x += 3.0f;
    s.lights = {left, right};
    return s;
}

TEST(LightTiles, SpotsOnEitherSideSameImageInTiles) {
    expectSameImage(spotsOnEitherSide(), LightTiles::Draws, 256);
}

TEST(LightTiles, SpotsOnEitherSideSameImageFromLists) {
    // Two lights: the untiled draw writes its loops out, the lists loop.
    expectSameImage(spotsOnEitherSide(), LightTiles::Lists, 256, 0.001);
}

// tutorial-room's sun with ranged point lights and narrow spots over its floor, all casting
// shadows: every tile has its own few of them.
Scene rangedLights() {
    Scene s = builtinScene("tutorial-room");
    s.lights.front().intensity *= 0.5f;
    for (int i = 0; i < 6; ++i) {
        Light point = builtinScene("tutorial-point").lights.front();
        point.position = {-7.0f + 3.0f * float(i), 1.5f, -6.0f + 2.5f * float(i % 3)};
        point.range = 3.5f;
        point.intensity = 6.0f;
        s.lights.push_back(point);
        Light spot = builtinScene("tutorial-spot").lights.front();
        spot.position = {-6.0f + 3.0f * float(i), 4.5f, 6.0f - 3.0f * float(i % 2)};
        spot.direction = glm::normalize(glm::vec3(0.3f, -1.0f, -0.2f));
        spot.outerConeDegrees = 18.0f;
        spot.innerConeDegrees = 12.0f;
        spot.range = 9.0f;
        spot.intensity = 40.0f;
        s.lights.push_back(spot);
    }
    return s;
}

TEST(LightTiles, RangedLightsSameImageFromLists) {
    expectSameImage(rangedLights(), LightTiles::Lists, 256, 0.001);
}

TEST(LightTiles, RangedLightsSameImageInTiles) {
    expectSameImage(rangedLights(), LightTiles::Draws, 256);
}

TEST(LightTiles, AutoGivesTheSameImage) {
    const Rendered chosen = renderWithTiles(rangedLights(), LightTiles::Auto, 256);
    const Rendered plain = renderWithTiles(rangedLights(), LightTiles::Off, 256);
    EXPECT_LE(difference(chosen.image, plain.image).most, 1);
}

TEST(LightTiles, ScoreOfListsFrameMatchesTheUntiled) {
    // The visibility pass after a lists frame draws untiled: every light's visibility.
    Scene s = rangedLights();
    s.options.width = s.options.height = 96;
    auto visibility = [&](LightTiles mode) {
        RenderOptions o = s.options;
        o.shading.lightTiles = mode;
        ShadowVisibility v;
        sharedRenderer().render(s, o, v);
        return v.visibility;
    };
    EXPECT_EQ(visibility(LightTiles::Lists), visibility(LightTiles::Off));
}

// A known layout for the lists: a 128 x 128 view down -z (90 degrees), two unshadowed point
// lights of range 1 on the left and the right at depth 10, a spot with a map above the
// centre pointing down, and a cascaded sun.
GpuLight recordOf(int type, glm::vec3 position, float range) {
    GpuLight r = gpu::emptyLightRecord();
    r.type = type;
    r.position = position;
    r.range = range;
    r.direction = {0.0f, -1.0f, 0.0f};
    r.cosOuter = type == gpu::kSpot ? std::cos(glm::radians(10.0f)) : -1.0f;
    return r;
}

TEST(LightTiles, ListsHoldEachTilesLights) {
    const std::vector<GpuLight> records = {recordOf(gpu::kPoint, {-5.0f, 0.0f, -10.0f}, 1.0f),
                                           recordOf(gpu::kPoint, {5.0f, 0.0f, -10.0f}, 1.0f),
                                           recordOf(gpu::kSpot, {0.0f, 5.0f, -10.0f}, 20.0f),
                                           recordOf(gpu::kDirectional, {0.0f, 0.0f, 0.0f}, -1.0f)};
    const glm::ivec4 ranges(2, 3, 3, 4);  // unshadowed, map, no cube, cascaded
    const glm::mat4 clipFromView = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f);
    render::TiledLights tiled;
    tiled.plan(records, ranges, glm::mat4(1.0f), clipFromView, 128, 128, 1000, LightTiles::Lists,
               nullptr);
    const render::LightLists& lists = tiled.lists();
    ASSERT_GT(lists.size, 0);
    EXPECT_EQ(lists.size & (lists.size - 1), 0) << "a power of two";
    EXPECT_EQ(lists.columns, (128 + lists.size - 1) / lists.size);
    EXPECT_EQ(lists.rows, lists.columns);
    ASSERT_EQ(lists.texels.size(), std::size_t(lists.columns * lists.rows));
    EXPECT_TRUE(tiled.tiles().empty());
    // The records of pixel (x, y)'s tile, each in its kind's range of the order.
    auto lightsAt = [&](int x, int y) {
        const glm::ivec4 t =
            lists.texels[std::size_t((y / lists.size) * lists.columns + x / lists.size)];
        const int ends[4] = {t.y, t.z, t.w, t.w + ranges.w - ranges.z};
        const int kindEnds[4] = {ranges.x, ranges.y, ranges.z, ranges.w};
        std::set<int> found;
        int start = t.x, kindStart = 0;
        for (int kind = 0; kind < 4; ++kind) {
            for (int k = start; k < ends[kind]; ++k) {
                const int record = tiled.order()[std::size_t(k)];
                EXPECT_GE(record, kindStart) << "record " << record << " in kind " << kind;
                EXPECT_LT(record, kindEnds[kind]) << "record " << record << " in kind " << kind;
                found.insert(record);
            }
            start = ends[kind];
            kindStart = kindEnds[kind];
        }
        return found;
    };
    // The point lights project to (32, 64) and (96, 64); the spot's pool lies below the centre.
    EXPECT_EQ(lightsAt(32, 64).count(0), 1u);
    EXPECT_EQ(lightsAt(32, 64).count(1), 0u);
    EXPECT_EQ(lightsAt(96, 64).count(1), 1u);
    EXPECT_EQ(lightsAt(96, 64).count(0), 0u);
    EXPECT_EQ(lightsAt(64, 40).count(2), 1u);
    // The top corners: the sun alone, from the same entries of the order.
    EXPECT_EQ(lightsAt(0, 127), std::set<int>{3});
    EXPECT_EQ(lightsAt(127, 127), std::set<int>{3});
    EXPECT_EQ(lists.texels.back(),
              lists.texels[std::size_t(lists.columns * lists.rows - lists.columns)]);
    // Every tile has the cascaded sun after its cubes.
    for (std::size_t t = 0; t < lists.texels.size(); ++t)
        EXPECT_EQ(tiled.order()[std::size_t(lists.texels[t].w)], 3) << "tile " << t;
}

}  // namespace
}  // namespace gnomon::test
