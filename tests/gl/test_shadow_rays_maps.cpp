// --shadow-rays all answers every lookup with a ray, so the frame draws no shadow map: it
// counts no shadow, moment or transmittance pass, and paints what a renderer whose maps an
// earlier `off` frame drew paints. Back under `off`, maps kept from before serve only where
// nothing they were drawn from changed, moments are made again, and the pictures are those of
// a renderer that never traced. What shows the maps (--debug-view shadow-map, the viewer's
// panel, read-backs) still has them.
#include <gtest/gtest.h>

#include <string>

#include "GlTest.h"
#include "RayTest.h"

namespace gnomon::test {
namespace {

ContextOptions testContext() {
    ContextOptions c;
    c.gles = testsGles();
    return c;
}

struct Case {
    const char* scene;
    ShadowFilter filter = ShadowFilter::Pcf;
    PointMaps pointMaps = PointMaps::Faces;
};

// Spot, directional, point lights with faces and with cubes, cascades, moments.
const Case kCases[] = {{"tutorial-room"},
                       {"tutorial-room", ShadowFilter::Evsm2},
                       {"tutorial-spot"},
                       {"tutorial-point"},
                       {"tutorial-point", ShadowFilter::Pcf, PointMaps::Cube},
                       {"mixed-lights"}};

RenderOptions optionsOf(const Scene& s, const Case& c, ShadowRayMode mode) {
    RenderOptions o = withRays(s, 64, mode);
    o.shadow.filter = c.filter;
    o.shadow.pointMaps = c.pointMaps;
    return o;
}

std::string nameOf(const Case& c) {
    return std::string(c.scene) + " " + toString(c.filter) + " " + toString(c.pointMaps);
}

void expectNoMapDrawn(const FrameStats& f) {
    EXPECT_EQ(f.shadowPasses, 0);
    EXPECT_EQ(f.shadowMaps, 0);
    EXPECT_EQ(f.shadowTriangles, 0u);
    EXPECT_EQ(f.momentPasses, 0);
    EXPECT_EQ(f.transmittancePasses, 0);
}

// A renderer that only ever traces draws no map, and paints what one whose maps an `off`
// frame drew just before paints.
TEST(ShadowRaysMaps, AllDrawsNoMapAndPaintsTheSame) {
    Renderer traced(testContext());
    Renderer& switched = sharedRenderer();
    for (const Case& c : kCases) {
        SCOPED_TRACE(nameOf(c));
        const Scene s = builtinScene(c.scene);
        const Image fresh = traced.render(s, optionsOf(s, c, ShadowRayMode::All));
        expectNoMapDrawn(traced.lastFrameStats());
        EXPECT_EQ(traced.lastFrameStats().shadowMapBytes, 0u) << "nothing drawn, nothing held";
        (void)switched.render(s, optionsOf(s, c, ShadowRayMode::Off));
        ASSERT_GT(switched.lastFrameStats().shadowMaps, 0);
        const Image afterMaps = switched.render(s, optionsOf(s, c, ShadowRayMode::All));
        expectNoMapDrawn(switched.lastFrameStats());
        EXPECT_EQ(fresh.pixels, afterMaps.pixels);
    }
}

// all -> off -> all: `off` draws again what changed while maps were left out (and the
// moments, which `all` let go) and paints what a renderer that never traced paints; `all`
// again paints as before.
TEST(ShadowRaysMaps, BackToOffDrawsWhatItNeeds) {
    Renderer mapped(testContext());  // only ever `off`
    Renderer traced(testContext());  // only ever `all`
    Renderer& switched = sharedRenderer();
    for (const Case& c : kCases) {
        SCOPED_TRACE(nameOf(c));
        const Scene s = builtinScene(c.scene);
        const RenderOptions off = optionsOf(s, c, ShadowRayMode::Off);
        const RenderOptions all = optionsOf(s, c, ShadowRayMode::All);
        (void)switched.render(s, off);
        (void)switched.render(s, all);
        const Image back = switched.render(s, off);
        EXPECT_EQ(switched.lastFrameStats().shadowPasses, 0) << "nothing changed: kept";
        if (c.filter == ShadowFilter::Evsm2) {
            EXPECT_GT(switched.lastFrameStats().momentPasses, 0) << "made again";
        }
        EXPECT_EQ(back.pixels, mapped.render(s, off).pixels);
        EXPECT_EQ(switched.render(s, all).pixels, traced.render(s, all).pixels);
    }
    // The book's triangle, a caster, turns while maps are left out: its map is drawn again.
    const Scene book = builtinScene("book-triangle");
    RenderOptions off = withRays(book, 64, ShadowRayMode::Off);
    RenderOptions all = withRays(book, 64, ShadowRayMode::All);
    (void)switched.render(book, off);
    all.time = off.time = 0.5;
    (void)switched.render(book, all);
    const Image back = switched.render(book, off);
    EXPECT_EQ(switched.lastFrameStats().shadowPasses, 1);
    EXPECT_EQ(back.pixels, mapped.render(book, off).pixels);
}

// The shadow-map debug view draws the maps it shows, as under `off`.
TEST(ShadowRaysMaps, DebugViewStillShowsTheMaps) {
    Renderer traced(testContext());
    Renderer mapped(testContext());
    for (const char* name : {"tutorial-room", "tutorial-point", "mixed-lights"}) {
        SCOPED_TRACE(name);
        const Scene s = builtinScene(name);
        RenderOptions all = withRays(s, 96, ShadowRayMode::All);
        all.debugView = DebugView::ShadowMap;
        RenderOptions off = all;
        off.shadow.shadowRays = ShadowRayMode::Off;
        const Image view = traced.render(s, all);
        EXPECT_GT(traced.lastFrameStats().shadowPasses, 0);
        EXPECT_EQ(view.pixels, mapped.render(s, off).pixels);
    }
}

// The viewer's panel draws the maps the frame left out, from its plan: a frame under `off`
// then keeps them and paints as a renderer that never traced.
TEST(ShadowRaysMaps, PanelDrawsTheMapsLeftOut) {
    Renderer traced(testContext());
    Renderer mapped(testContext());
    const Scene s = builtinScene("tutorial-room");
    RenderOptions all = withRays(s, 64, ShadowRayMode::All);
    all.shadow.filter = ShadowFilter::Evsm2;
    RenderOptions off = all;
    off.shadow.shadowRays = ShadowRayMode::Off;
    (void)traced.render(s, all);
    EXPECT_TRUE(traced.drawShadowMapPanel(0, 64, 64));
    expectNoMapDrawn(traced.lastFrameStats());  // the frame's counts stay the frame's
    const Image back = traced.render(s, off);
    EXPECT_EQ(traced.lastFrameStats().shadowPasses, 0) << "the panel drew them";
    EXPECT_GT(traced.lastFrameStats().momentPasses, 0);
    EXPECT_EQ(back.pixels, mapped.render(s, off).pixels);
}

// Read-backs (gnomon render --shadow-maps) get the maps an `off` frame draws.
TEST(ShadowRaysMaps, ReadBackDrawsTheMapsLeftOut) {
    GNOMON_NEEDS_DEPTH_READBACK();
    Renderer traced(testContext());
    Renderer mapped(testContext());
    for (const char* name : {"tutorial-room", "tutorial-point", "mixed-lights"}) {
        SCOPED_TRACE(name);
        const Scene s = builtinScene(name);
        const RenderOptions all = withRays(s, 64, ShadowRayMode::All);
        (void)traced.render(s, all);
        const std::vector<ShadowMapImage> left = traced.shadowMaps();
        (void)mapped.render(s, withRays(s, 64, ShadowRayMode::Off));
        const std::vector<ShadowMapImage> drawn = mapped.shadowMaps();
        ASSERT_EQ(left.size(), drawn.size());
        ASSERT_FALSE(left.empty());
        for (std::size_t i = 0; i < left.size(); ++i) {
            EXPECT_EQ(left[i].light, drawn[i].light);
            EXPECT_EQ(left[i].depth.pixels, drawn[i].depth.pixels);
        }
    }
}

}  // namespace
}  // namespace gnomon::test
