// Each value of every render option renders (issue 3's "each option value renders"): on
// mixed-lights, which has every light type, every value gives a picture that has shadows
// (differs from the shadows-off render) and is not blank. The values come from the schema:
// every choice of every choice option, both states of every switch, and each choice of
// depth-format crossed with each of map-filter (the lookups they select together); then
// the numeric options at the ends of their ranges where a picture changes there.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

#include "GlTest.h"
#include "gnomon/OptionSchema.h"

namespace gnomon::test {
namespace {

struct OptionCase {
    std::string name;
    std::function<void(RenderOptions&)> set;
};

void PrintTo(const OptionCase& c, std::ostream* os) {
    *os << c.name;
}

// Values of the schema this test leaves out, and why.
struct LeftOut {
    const OptionSpec* spec;
    const char* value;
    const char* why;
};
std::vector<LeftOut> leftOut() {
    const RenderOptions o;
    return {
        {&optionAt(o, &o.shadow.enabled), "off", "the render every case is compared against"},
        {&optionAt(o, &o.debugView), "shadow-map",
         "draws the maps instead of the scene (test_debug_views.cpp)"},
    };
}

std::vector<OptionCase> everyValue() {
    std::vector<OptionCase> cases;
    auto add = [&](std::string name, std::function<void(RenderOptions&)> set) {
        for (char& ch : name)
            ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
        cases.push_back({name, std::move(set)});
    };
    auto values = [](const OptionSpec& spec) {
        return spec.kind == OptionKind::Switch ? std::vector<std::string>{"on", "off"}
                                               : spec.choices;
    };
    auto setter = [](const OptionSpec* spec, std::string value) {
        return [spec, value](RenderOptions& o) { ASSERT_FALSE(parseOption(*spec, value, o)); };
    };
    const std::vector<LeftOut> out = leftOut();
    for (const OptionSpec& spec : optionSchema()) {
        if (spec.kind != OptionKind::Switch && spec.kind != OptionKind::Choice) continue;
        for (const std::string& v : values(spec)) {
            const bool skip = std::any_of(out.begin(), out.end(), [&](const LeftOut& l) {
                return l.spec == &spec && l.value == v;
            });
            if (!skip) add(std::string(spec.name) + "_" + v, setter(&spec, v));
        }
    }
    const RenderOptions d;
    const OptionSpec& format = optionAt(d, &d.shadow.depthFormat);
    const OptionSpec& lookup = optionAt(d, &d.shadow.mapFilter);
    for (const std::string& f : format.choices) {
        for (const std::string& m : lookup.choices) {
            add("format_" + f + "_" + m, [&format, &lookup, f, m](RenderOptions& o) {
                ASSERT_FALSE(parseOption(format, f, o));
                ASSERT_FALSE(parseOption(lookup, m, o));
            });
        }
    }
    for (int n : {1, 9})
        add("pcf_size_" + std::to_string(n), [n](RenderOptions& o) { o.shadow.pcfSize = n; });
    for (int n = 1; n <= 4; ++n)
        add("cascades_" + std::to_string(n), [n](RenderOptions& o) { o.shadow.cascades = n; });
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

// What the cases leave out are values the options have.
TEST(EveryOption, LeftOutValuesExist) {
    for (const LeftOut& l : leftOut()) {
        RenderOptions o;
        EXPECT_FALSE(parseOption(*l.spec, l.value, o)) << l.spec->name << " " << l.value;
    }
}

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
