// Tile culling for the main pass (shadow/LightTiles.h): it may keep a light that cannot
// reach a tile, never drop one that can.
#include <random>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "shadow/LightTiles.h"

using namespace gnomon::shadow;

namespace {
const glm::mat4 kClipFromView = glm::perspective(glm::radians(60.0f), 1.0f, 0.5f, 40.0f);
const glm::mat4 kViewFromClip = glm::inverse(kClipFromView);

// A spot 6 above a floor at y = -2, pointing down, 30 degrees wide, in view space.
LightReach downSpot(glm::vec3 apex, float degrees = 30.0f) {
    LightReach l;
    l.shape = LightReach::Shape::Cone;
    l.position = apex;
    l.direction = {0.0f, -1.0f, 0.0f};
    l.cosOuter = std::cos(glm::radians(degrees));
    return l;
}

// Does the light lit any point of the tile's volume (dense samples of it)?
bool litSomewhere(const LightReach& l, const std::array<glm::vec3, 8>& c) {
    for (int i = 0; i <= 12; ++i) {
        for (int j = 0; j <= 12; ++j) {
            for (int k = 0; k <= 24; ++k) {
                const float x = i / 12.0f, y = j / 12.0f, z = k / 24.0f;
                auto lerp = [](glm::vec3 a, glm::vec3 b, float t) { return a + (b - a) * t; };
                const glm::vec3 nearP = lerp(lerp(c[0], c[1], x), lerp(c[2], c[3], x), y);
                const glm::vec3 farP = lerp(lerp(c[4], c[5], x), lerp(c[6], c[7], x), y);
                const glm::vec3 p = lerp(nearP, farP, z);
                const glm::vec3 d = p - l.position;
                const float dist = glm::length(d);
                if (l.range > 0.0f && dist >= l.range) continue;
                if (l.shape == LightReach::Shape::Cone &&
                    glm::dot(d / dist, glm::normalize(l.direction)) <= l.cosOuter) {
                    continue;
                }
                return true;
            }
        }
    }
    return false;
}
}  // namespace

TEST(LightTiles, SpotBelowTheViewMissesTheTopTiles) {
    const LightReach spot = downSpot({0.0f, -1.0f, -10.0f}, 20.0f);
    const auto top = tileCorners(kViewFromClip, 512, 512, 0, 448, 512, 512);
    const auto centre = tileCorners(kViewFromClip, 512, 512, 224, 192, 288, 256);
    EXPECT_FALSE(mayReach(spot, top));
    EXPECT_TRUE(mayReach(spot, centre));
}

TEST(LightTiles, RangedPointLightReachesOnlyNearbyTiles) {
    LightReach point;
    point.shape = LightReach::Shape::Sphere;
    point.position = {0.0f, 0.0f, -10.0f};
    point.range = 2.0f;
    EXPECT_TRUE(mayReach(point, tileCorners(kViewFromClip, 512, 512, 192, 192, 320, 320)));
    EXPECT_FALSE(mayReach(point, tileCorners(kViewFromClip, 512, 512, 0, 0, 64, 64)));
    point.range = 0.0f;  // unbounded: a sphere without range reaches everywhere
    EXPECT_TRUE(mayReach(point, tileCorners(kViewFromClip, 512, 512, 0, 0, 64, 64)));
}

TEST(LightTiles, NeverDropsALightThatReachesTheTile) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int dropped = 0, kept = 0;
    for (int trial = 0; trial < 300; ++trial) {
        LightReach l = downSpot({6.0f * u(rng), 4.0f * u(rng), -12.0f + 8.0f * u(rng)},
                                10.0f + 35.0f * (u(rng) + 1.0f));
        l.direction = glm::vec3(u(rng), u(rng), u(rng));
        if (glm::length(l.direction) < 0.1f) continue;
        l.range = trial % 3 == 0 ? 4.0f + 4.0f * (u(rng) + 1.0f) : 0.0f;
        const int x = int(256 + 250 * u(rng)), y = int(256 + 250 * u(rng));
        const float nearest = 0.5f + 0.25f * (u(rng) + 1.0f);
        const auto c = tileCorners(kViewFromClip, 512, 512, x, y, x + 64, y + 64, nearest,
                                   std::min(1.0f, nearest + 0.05f));
        const bool may = mayReach(l, c);
        if (!may) {
            ++dropped;
            EXPECT_FALSE(litSomewhere(l, c)) << "trial " << trial;
        } else {
            ++kept;
        }
    }
    // The test means something only if both outcomes occur often.
    EXPECT_GT(dropped, 50);
    EXPECT_GT(kept, 50);
}

TEST(LightTiles, DepthCellsBoundTheTilesAndEmptyTilesGetNoLight) {
    // 128 x 128 target, 4 x 4 cells of 32 pixels: only the bottom-left cell drew anything,
    // a surface near the near plane.
    SampleGrid grid{{128, 128}, 32, {4, 4}};
    std::vector<glm::vec2> ranges(16, glm::vec2(1.0f));
    ranges[0] = {0.2f, 0.25f};
    const DepthCells cells{&ranges, grid};
    LightReach everywhere;
    LightReach farPoint;
    farPoint.shape = LightReach::Shape::Sphere;
    farPoint.position = {-10.0f, -10.0f, -35.0f};  // far behind what was drawn there
    farPoint.range = 5.0f;
    TileReach withDepth, without;
    cullTiles({everywhere, farPoint}, kViewFromClip, 128, 128, 64, &cells, withDepth);
    cullTiles({everywhere, farPoint}, kViewFromClip, 128, 128, 64, nullptr, without);
    ASSERT_EQ(withDepth.columns, 2);
    ASSERT_EQ(withDepth.rows, 2);
    EXPECT_EQ(withDepth.reaches[0], 1);  // tile 0 drew something: the sun reaches it
    EXPECT_EQ(withDepth.reaches[1], 0);  // but not the far point light
    EXPECT_EQ(without.reaches[1], 1);    // which the whole depth range would keep
    for (int tile = 1; tile < 4; ++tile) {
        EXPECT_EQ(withDepth.reaches[std::size_t(tile) * 2], 0) << "empty tile " << tile;
    }
}

TEST(LightTiles, TilingPaysOnlyForWhatItSkips) {
    LightReach everywhere;
    everywhere.shadowed = true;
    TileReach tiles;
    cullTiles({everywhere}, kViewFromClip, 512, 512, 64, nullptr, tiles);
    const TilingGain none = tilingGainMs(tiles, {everywhere}, 1000, 8);
    EXPECT_LE(none.draws, 0.0);  // nothing skipped
    EXPECT_LE(none.lists, 0.0);

    LightReach spot = downSpot({0.0f, -1.0f, -10.0f}, 20.0f);
    spot.shadowed = true;
    const std::vector<LightReach> lights(12, spot);
    cullTiles(lights, kViewFromClip, 512, 512, 64, nullptr, tiles);
    const TilingGain few = tilingGainMs(tiles, lights, 100, 8);
    EXPECT_GT(few.draws, 0.0);
    EXPECT_GT(few.lists, 0.0);
    // The same skipping does not pay for drawing a million triangles again per tile; lists
    // draw them once.
    const TilingGain many = tilingGainMs(tiles, lights, 1000000, 8);
    EXPECT_LT(many.draws, 0.0);
    EXPECT_DOUBLE_EQ(many.lists, few.lists);
}

TEST(LightTiles, EmptyTilesCostNothingEitherWay) {
    // Nothing drawn anywhere: no light is looked up whether tiled or not.
    const std::vector<glm::vec2> ranges(4, glm::vec2(1.0f));
    const DepthCells cells{&ranges, SampleGrid{{128, 128}, 64, {2, 2}}};
    LightReach spot = downSpot({0.0f, -1.0f, -10.0f}, 20.0f);
    spot.shadowed = true;
    const std::vector<LightReach> lights(12, spot);
    TileReach tiles;
    cullTiles(lights, kViewFromClip, 128, 128, 64, &cells, tiles);
    EXPECT_EQ(tiles.drawn, std::vector<std::int32_t>(4, 0));
    EXPECT_DOUBLE_EQ(tilingGainMs(tiles, lights, 0, 8).lists, 0.0);
}

TEST(LightTiles, CoarserGridsAreTheUnionOfTheirFinerTiles) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<LightReach> lights;
    for (int i = 0; i < 24; ++i) {
        LightReach l = downSpot({6.0f * u(rng), 4.0f * u(rng), -12.0f + 8.0f * u(rng)}, 25.0f);
        if (i % 2) {
            l.shape = LightReach::Shape::Sphere;
            l.range = 2.0f;
        }
        lights.push_back(l);
    }
    // 200 x 120 pixels: 16-pixel tiles, 4 x 4 of them to a coarse one, the last column and
    // row of both narrower.
    const std::vector<glm::vec2> depths(50 * 30, glm::vec2(0.3f, 0.9f));
    std::vector<glm::vec2> cells = depths;
    for (int cx = 0; cx < 100; ++cx)
        cells[std::size_t(28 * 50 + cx)] = glm::vec2(1.0f);  // nothing drawn in the top 8 rows
    const DepthCells depth{&cells, SampleGrid{{200, 120}, 4, {50, 30}}};
    TileReach fine, coarse;
    cullTiles(lights, kViewFromClip, 200, 120, 16, &depth, fine);
    coarsenTiles(fine, 4, 200, 120, lights.size(), coarse);
    ASSERT_EQ(coarse.size, 64);
    ASSERT_EQ(coarse.columns, 4);
    ASSERT_EQ(coarse.rows, 2);
    int reached = 0;
    for (int r = 0; r < coarse.rows; ++r) {
        for (int c = 0; c < coarse.columns; ++c) {
            for (std::size_t l = 0; l < lights.size(); ++l) {
                std::uint8_t any = 0;
                for (int fr = r * 4; fr < std::min(fine.rows, r * 4 + 4); ++fr)
                    for (int fc = c * 4; fc < std::min(fine.columns, c * 4 + 4); ++fc)
                        any |=
                            fine.reaches[std::size_t(fr * fine.columns + fc) * lights.size() + l];
                const std::size_t at = std::size_t(r * coarse.columns + c) * lights.size() + l;
                EXPECT_EQ(coarse.reaches[at], any) << "tile " << c << ", " << r << " light " << l;
                reached += any;
            }
            // Drawn where its fine tiles are: all but the top row of fine tiles.
            const int w = std::min(200, (c + 1) * 64) - c * 64;
            const int h = r == 0 ? 64 : 112 - 64;
            EXPECT_EQ(coarse.drawn[std::size_t(r * coarse.columns + c)], w * h);
        }
    }
    EXPECT_GT(reached, 0);
    EXPECT_EQ(fine.drawn[std::size_t(7 * fine.columns)], 0);  // the top row of 16-pixel tiles
}
