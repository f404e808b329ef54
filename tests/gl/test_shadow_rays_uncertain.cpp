// --shadow-rays uncertain: the map answers where it is sure, a ray where it is not. Scored
// against the ray-traced reference it must come close to tracing every lookup while tracing a
// small share of them, fix a coarse map's edges, leave the penumbra filters' look alone, and
// --debug-view rays must show where it traced.
#include <gtest/gtest.h>

#include <cstdio>

#include "GlTest.h"
#include "RayTest.h"
#include "gl/Caps.h"

namespace gnomon::test {
namespace {

RenderOptions uncertain(const Scene& s, int size) {
    return withRays(s, size, ShadowRayMode::Uncertain);
}

// The bound for rays where the map is unsure: the share for `uncertain`, plus one pair.
void expectWithinBound(const ScoreResult& r) {
    expectWrongAtMost(r, 0.0002, 1.0);
}

TEST(ShadowRaysUncertain, AgreesWithTheReferenceTracingFew) {
    for (const char* name :
         {"book-triangle", "tutorial-room", "tutorial-spot", "tutorial-point", "mixed-lights"}) {
        SCOPED_TRACE(name);
        const Scene s = builtinScene(name);
        const ScoreResult r = score(sharedRenderer(), s, uncertain(s, 128));
        std::printf("%-16s misclassified %.4f %%, traced %.2f %% of %ld pairs\n", name,
                    100.0 * r.overall.misclassified, 100.0 * r.overall.traced, r.overall.pixels);
        ASSERT_GT(r.overall.pixels, 1000);
        expectWithinBound(r);
        EXPECT_GT(r.overall.traced, 0.0);   // every one of these has shadow edges
        EXPECT_LT(r.overall.traced, 0.25);  // and is mostly sure
    }
}

// With every lookup traced, each pair is the ray's.
TEST(ShadowRaysUncertain, AllTracesEveryPair) {
    const Scene s = builtinScene("tutorial-spot");
    RenderOptions o = uncertain(s, 64);
    o.shadow.shadowRays = ShadowRayMode::All;
    const ScoreResult r = score(sharedRenderer(), s, o);
    EXPECT_EQ(r.overall.traced, 1.0);
    o.shadow.shadowRays = ShadowRayMode::Off;
    EXPECT_EQ(score(sharedRenderer(), s, o).overall.traced, 0.0);
}

// A 64-texel map under the default 3 x 3 PCF puts tutorial-room's shadow edges texels off;
// its footprints there hold lit and shadowed texels, and the rays decide them.
TEST(ShadowRaysUncertain, FixACoarseMapsEdges) {
    const Scene s = builtinScene("tutorial-room");
    RenderOptions map = s.options;
    map.width = map.height = 128;
    map.shadow.mapSize = 64;
    map.shadow.shadowRays = ShadowRayMode::Off;
    RenderOptions rays = map;
    rays.shadow.shadowRays = ShadowRayMode::Uncertain;
    const ScoreResult m = score(sharedRenderer(), s, map);
    const ScoreResult r = score(sharedRenderer(), s, rays);
    std::printf("map %.4f %%, uncertain %.4f %% (traced %.2f %%)\n",
                100.0 * m.overall.misclassified, 100.0 * r.overall.misclassified,
                100.0 * r.overall.traced);
    EXPECT_GT(m.overall.misclassified, 0.001);
    expectWithinBound(r);
    EXPECT_LT(r.overall.traced, 0.5);
}

// Pixels whose colour differs between `a` and `b`; `opaque`: whether every alpha of `a` is 1.
long differing(const Image& a, const Image& b, bool& opaque) {
    long n = 0;
    opaque = true;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const std::uint8_t *p = a.at(x, y), *q = b.at(x, y);
            n += p[0] != q[0] || p[1] != q[1] || p[2] != q[2];
            opaque = opaque && p[3] == 255;
        }
    }
    return n;
}

// The picture is the rays' where the map is unsure: the pixels marked in the first draw are
// drawn again with their rays (render/RayMarks.h), and none is left marked. A 64-texel map
// with one comparison, against every lookup traced: the map alone differs along every edge,
// `uncertain` where it misclassifies at most.
TEST(ShadowRaysUncertain, PaintsTheRaysWhereTheMapIsUnsure) {
    for (const char* name : {"tutorial-room", "tutorial-point"}) {
        SCOPED_TRACE(name);
        const Scene s = builtinScene(name);
        RenderOptions o = uncertain(s, 128);
        o.shadow.mapSize = 64;
        o.shadow.filter = ShadowFilter::None;
        Renderer& renderer = sharedRenderer();
        const Image rays = renderer.render(s, o);
        const ScoreResult r = score(renderer, s, o);
        o.shadow.shadowRays = ShadowRayMode::All;
        const Image all = renderer.render(s, o);
        o.shadow.shadowRays = ShadowRayMode::Off;
        const Image map = renderer.render(s, o);
        bool opaque = false, mapOpaque = false;
        const long wrong = differing(rays, all, opaque), mapWrong = differing(map, all, mapOpaque);
        std::printf("differ from all: map %ld pixels, uncertain %ld (%.0f pairs misclassified)\n",
                    mapWrong, wrong, wrongPairs(r));
        EXPECT_GT(mapWrong, 20);
        EXPECT_LE(double(wrong), wrongPairs(r) + 2.0);
        EXPECT_TRUE(opaque);
    }
}

// The rays run in a pass of their own when a frame marks many pixels and in the second draw
// when it marks few (RayMarks::compacts): the same picture either way. A new output size
// starts with the pass (no count yet); tutorial-room marks too few of its pixels for the pass
// (RayMarks' kCompactShare), so on OpenGL 4.5, which counts them, its next frame traces in
// the second draw.
TEST(ShadowRaysUncertain, EitherWayTheRaysRunPaintsTheSame) {
    const Scene s = builtinScene("tutorial-room");
    const RenderOptions o = uncertain(s, 500);
    Renderer& renderer = sharedRenderer();
    const Image pass = renderer.render(s, o);
    EXPECT_EQ(renderer.lastFrameStats().shadowRayPasses, 1);
    const Image second = renderer.render(s, o);
    EXPECT_EQ(renderer.lastFrameStats().shadowRayPasses,
              gl::activeCaps().api == gl::Api::Gl45 ? 0 : 1);
    bool opaque = false;
    EXPECT_EQ(differing(pass, second, opaque), 0);
    EXPECT_TRUE(opaque);
}

// Where `uncertain` traces, its ray starts as `all`'s does (on OpenGL 4.5 on the triangle the
// first draw drew, written into the pixel's job), so every pixel it traced is `all`'s pixel.
// From an interpolated start, a pixel of tutorial-point at a silhouette differed.
TEST(ShadowRaysUncertain, TracedPixelsAreAllsPixels) {
    for (const char* name : {"tutorial-point", "mixed-lights"}) {
        SCOPED_TRACE(name);
        const Scene s = builtinScene(name);
        RenderOptions o = uncertain(s, 256);
        Renderer& renderer = sharedRenderer();
        const Image rays = renderer.render(s, o);
        o.debugView = DebugView::Rays;
        const Image tinted = renderer.render(s, o);
        o.debugView = DebugView::None;
        o.shadow.shadowRays = ShadowRayMode::All;
        const Image all = renderer.render(s, o);
        long traced = 0, differ = 0;
        for (int y = 0; y < rays.height; ++y) {
            for (int x = 0; x < rays.width; ++x) {
                const std::uint8_t *p = rays.at(x, y), *t = tinted.at(x, y), *a = all.at(x, y);
                if (p[0] == t[0] && p[1] == t[1] && p[2] == t[2]) continue;
                ++traced;
                differ += p[0] != a[0] || p[1] != a[1] || p[2] != a[2];
            }
        }
        std::printf("traced %ld pixels, %ld unlike all's\n", traced, differ);
        EXPECT_GT(traced, 100);
        EXPECT_EQ(differ, 0);
    }
}

// A main pass drawn a screen tile at a time marks, numbers and traces each tile's pixels in
// turn (only those: the others keep the answers of their own tile): the untiled picture.
TEST(ShadowRaysUncertain, ScreenTilesPaintTheSame) {
    const Scene s = builtinScene("mixed-lights");
    RenderOptions o = uncertain(s, 256);
    o.height = 251;  // a size of its own: every tile takes the rays' pass
    o.shading.lightTiles = LightTiles::Draws;
    Renderer& renderer = sharedRenderer();
    const Image tiled = renderer.render(s, o);
    EXPECT_GT(renderer.lastFrameStats().lightTiles, 1);
    EXPECT_EQ(renderer.lastFrameStats().shadowRayPasses, renderer.lastFrameStats().lightTiles);
    o.shading.lightTiles = LightTiles::Off;
    bool opaque = false;
    EXPECT_EQ(differing(tiled, renderer.render(s, o), opaque), 0);
    EXPECT_TRUE(opaque);
}

// PCSS and the moment filters keep their penumbra: no hierarchy, no ray, the same picture.
TEST(ShadowRaysUncertain, PenumbraFiltersKeepTheirLook) {
    const Scene s = builtinScene("tutorial-room");
    for (ShadowFilter f : {ShadowFilter::Pcss, ShadowFilter::Evsm2}) {
        SCOPED_TRACE(toString(f));
        RenderOptions off = s.options;
        off.width = off.height = 64;
        off.shadow.filter = f;
        RenderOptions rays = off;
        rays.shadow.shadowRays = ShadowRayMode::Uncertain;
        EXPECT_FALSE(tracesShadowRays(rays.shadow));
        Renderer& renderer = sharedRenderer();
        const Image a = renderer.render(s, off);
        const Image b = renderer.render(s, rays);
        EXPECT_EQ(renderer.lastFrameStats().shadowRayBuilds, 0);
        EXPECT_EQ(a.pixels, b.pixels);
    }
}

// --debug-view rays tints the pixels a ray decided, and only those: as many as the score
// counts traced where one light shadows (tutorial-room's sun), none without rays.
TEST(ShadowRaysUncertain, DebugViewShowsTheTracedPixels) {
    const Scene s = builtinScene("tutorial-room");
    RenderOptions o = uncertain(s, 96);
    Renderer& renderer = sharedRenderer();
    const ScoreResult r = score(renderer, s, o);
    const Image plain = renderer.render(s, o);
    o.debugView = DebugView::Rays;
    const Image tinted = renderer.render(s, o);
    ASSERT_EQ(plain.pixels.size(), tinted.pixels.size());
    long changed = 0;
    for (int y = 0; y < plain.height; ++y) {
        for (int x = 0; x < plain.width; ++x) {
            const std::uint8_t *a = plain.at(x, y), *b = tinted.at(x, y);
            changed += a[0] != b[0] || a[1] != b[1] || a[2] != b[2];
        }
    }
    const double traced = r.overall.traced * double(r.overall.pixels);
    std::printf("tinted %ld pixels, traced %.0f pairs\n", changed, traced);
    EXPECT_GT(changed, 0);
    EXPECT_NEAR(double(changed), traced, 0.1 * traced + 4.0);
    o.shadow.shadowRays = ShadowRayMode::Off;
    o.debugView = DebugView::None;
    const Image off = renderer.render(s, o);
    o.debugView = DebugView::Rays;
    EXPECT_EQ(renderer.render(s, o).pixels, off.pixels);
}

}  // namespace
}  // namespace gnomon::test
