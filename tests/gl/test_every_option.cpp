// Each value of every render option renders (issue 3's "each option value renders"): on
// mixed-lights, which has every light type, every value gives a picture that has shadows
// (differs from the shadows-off render) and is not blank; the shadow-map view shows a map.
#include <gtest/gtest.h>

#include <functional>

#include "GlTest.h"

namespace gnomon::test {
namespace {

struct OptionCase {
    std::string name;
    std::function<void(RenderOptions&)> set;
};

void PrintTo(const OptionCase& c, std::ostream* os) {
    *os << c.name;
}

std::vector<OptionCase> everyValue() {
    std::vector<OptionCase> cases;
    auto add = [&](std::string name, std::function<void(RenderOptions&)> set) {
        for (char& ch : name)
            ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
        cases.push_back({name, std::move(set)});
    };
    for (OutsidePolicy v : {OutsidePolicy::Lit, OutsidePolicy::Clamp})
        add(std::string("outside_") + toString(v), [v](RenderOptions& o) { o.shadow.outside = v; });
    for (CullMode v : {CullMode::Back, CullMode::Front, CullMode::None})
        add(std::string("cull_") + toString(v), [v](RenderOptions& o) { o.shadow.cull = v; });
    for (ShadowFilter v :
         {ShadowFilter::None, ShadowFilter::Hw2x2, ShadowFilter::Pcf, ShadowFilter::Poisson,
          ShadowFilter::Pcss, ShadowFilter::Evsm2, ShadowFilter::Evsm4, ShadowFilter::Msm})
        add(std::string("filter_") + toString(v), [v](RenderOptions& o) { o.shadow.filter = v; });
    for (int n : {1, 9})
        add("pcf_size_" + std::to_string(n), [n](RenderOptions& o) { o.shadow.pcfSize = n; });
    for (DepthFormat v : {DepthFormat::R8, DepthFormat::Rgba8Packed256, DepthFormat::Rgba8Packed255,
                          DepthFormat::Depth16, DepthFormat::Depth24, DepthFormat::Depth32F}) {
        for (MapFilter m : {MapFilter::Nearest, MapFilter::Linear}) {
            add(std::string("format_") + toString(v) + "_" + toString(m), [v, m](RenderOptions& o) {
                o.shadow.depthFormat = v;
                o.shadow.mapFilter = m;
            });
        }
    }
    for (ShadowedRule v : {ShadowedRule::AmbientOnly, ShadowedRule::Factor})
        add(std::string("shadowed_") + toString(v),
            [v](RenderOptions& o) { o.shading.shadowedRule = v; });
    for (int n = 1; n <= 4; ++n)
        add("cascades_" + std::to_string(n), [n](RenderOptions& o) { o.shadow.cascades = n; });
    for (DebugView v : {DebugView::None, DebugView::Cascades, DebugView::LightFrusta})
        add(std::string("debug_view_") + toString(v), [v](RenderOptions& o) { o.debugView = v; });
    add("light_radius_0", [](RenderOptions& o) {
        o.shadow.filter = ShadowFilter::Pcss;
        o.shadow.lightRadius = 0.0f;
        o.shadow.lightAngle = 0.0f;
    });
    add("light_radius_large", [](RenderOptions& o) {
        o.shadow.filter = ShadowFilter::Pcss;
        o.shadow.lightRadius = 5.0f;
        o.shadow.lightAngle = 20.0f;
    });
    add("map_size_64", [](RenderOptions& o) { o.shadow.mapSize = 64; });
    add("no_biases", [](RenderOptions& o) {
        o.shadow.biasConstant = o.shadow.biasDepthAware = o.shadow.biasSlope = 0.0f;
        o.shadow.biasUnits = o.shadow.normalOffset = 0.0f;
    });
    return cases;
}

class EveryOption : public testing::TestWithParam<OptionCase> {};

TEST_P(EveryOption, RendersWithShadows) {
    const Scene s = builtinScene("mixed-lights");
    RenderOptions o = s.options;
    o.width = o.height = 128;
    o.shadow.mapSize = 256;
    GetParam().set(o);
    ASSERT_TRUE(o.validate().empty());
    const Image shadowed = sharedRenderer().render(s, o);
    RenderOptions off = o;
    off.shadow.enabled = false;
    const Image plain = sharedRenderer().render(s, off);
    long differ = 0, lit = 0;
    for (int y = 0; y < o.height; ++y) {
        for (int x = 0; x < o.width; ++x) {
            differ += luminance(shadowed.at(x, y)) < luminance(plain.at(x, y)) - 6;
            lit += luminance(shadowed.at(x, y)) > 60;
        }
    }
    EXPECT_GT(differ, 200) << "no shadows";
    EXPECT_GT(lit, 2000) << "hardly anything lit";
}

INSTANTIATE_TEST_SUITE_P(Values, EveryOption, testing::ValuesIn(everyValue()),
                         [](const auto& info) { return info.param.name; });

// The textbook preset of every built-in scene renders, with shadows.
TEST(EveryOption, TextbookPresetOfEveryScene) {
    for (const SceneInfo& info : builtinScenes()) {
        const Scene s = builtinScene(info.name);
        RenderOptions o = presetOptions(s, Preset::Textbook);
        o.width = o.height = 128;
        SCOPED_TRACE(info.name);
        const Image a = sharedRenderer().render(s, o);
        o.shadow.enabled = false;
        const Image b = sharedRenderer().render(s, o);
        EXPECT_NE(a.pixels, b.pixels) << "no shadow at all";
    }
}

}  // namespace
}  // namespace gnomon::test
