// RenderOptions::validate (include/gnomon/Options.h): the defaults are valid, each invalid
// field yields exactly one message that names the option as the CLI spells it, and every
// enum round-trips through toString/parse* while unknown strings are rejected.
#include <cmath>
#include <functional>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gnomon/Options.h"

namespace gnomon {
namespace {

TEST(Options, DefaultsAreValid) {
    EXPECT_TRUE(RenderOptions{}.validate().empty());
}

TEST(Options, DefaultsMatchTheDocumentedValues) {
    const RenderOptions o;
    EXPECT_EQ(o.width, 512);
    EXPECT_EQ(o.height, 512);
    EXPECT_EQ(o.lightOnly, -1);
    EXPECT_TRUE(o.shadow.enabled);
    EXPECT_EQ(o.shadow.outside, OutsidePolicy::Lit);
    EXPECT_EQ(o.shadow.filter, ShadowFilter::Pcf);
    EXPECT_EQ(o.shadow.pcfSize, 3);
    EXPECT_EQ(o.shadow.mapSize, 0);
    EXPECT_EQ(o.shadow.cull, CullMode::Back);
    EXPECT_EQ(o.shadow.cascades, 0);  // auto
    EXPECT_EQ(o.shadow.fitTo, FitTo::ViewDepth);
    EXPECT_EQ(o.shading.shadowedRule, ShadowedRule::AmbientOnly);
    EXPECT_FLOAT_EQ(o.shading.shadowFactor, 0.7f);  // the WebGL book's factor
}

struct InvalidCase {
    const char* label;
    std::function<void(RenderOptions&)> spoil;
    const char* mustMention;  // the option's CLI name
};

void PrintTo(const InvalidCase& c, std::ostream* os) {
    *os << c.label;
}

class InvalidOption : public testing::TestWithParam<InvalidCase> {};

TEST_P(InvalidOption, YieldsOneMessageNamingTheOption) {
    RenderOptions o;
    GetParam().spoil(o);
    const std::vector<std::string> problems = o.validate();
    ASSERT_EQ(problems.size(), 1u) << GetParam().label;
    EXPECT_NE(problems[0].find(GetParam().mustMention), std::string::npos)
        << "message: " << problems[0];
}

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

INSTANTIATE_TEST_SUITE_P(
    Fields, InvalidOption,
    testing::Values(
        InvalidCase{"width=0", [](RenderOptions& o) { o.width = 0; }, "size"},
        InvalidCase{"height=16385", [](RenderOptions& o) { o.height = 16385; }, "size"},
        InvalidCase{"time=NaN",
                    [](RenderOptions& o) { o.time = std::numeric_limits<double>::quiet_NaN(); },
                    "time"},
        InvalidCase{"light-only=-2", [](RenderOptions& o) { o.lightOnly = -2; }, "light-only"},
        InvalidCase{"bias-constant=NaN", [](RenderOptions& o) { o.shadow.biasConstant = kNaN; },
                    "bias-constant"},
        InvalidCase{"bias-constant=1", [](RenderOptions& o) { o.shadow.biasConstant = 1.0f; },
                    "bias-constant"},
        InvalidCase{"bias-slope=-1", [](RenderOptions& o) { o.shadow.biasSlope = -1.0f; },
                    "bias-slope"},
        InvalidCase{"bias-units=inf", [](RenderOptions& o) { o.shadow.biasUnits = kInf; },
                    "bias-units"},
        InvalidCase{"normal-offset=NaN", [](RenderOptions& o) { o.shadow.normalOffset = kNaN; },
                    "normal-offset"},
        InvalidCase{"pcf-size=4-even", [](RenderOptions& o) { o.shadow.pcfSize = 4; }, "pcf-size"},
        InvalidCase{"pcf-size=11", [](RenderOptions& o) { o.shadow.pcfSize = 11; }, "pcf-size"},
        InvalidCase{"map-size=8", [](RenderOptions& o) { o.shadow.mapSize = 8; }, "map-size"},
        InvalidCase{"cascades=5", [](RenderOptions& o) { o.shadow.cascades = 5; }, "cascades"},
        InvalidCase{"cascades=-1", [](RenderOptions& o) { o.shadow.cascades = -1; }, "cascades"},
        InvalidCase{"map-size=-1", [](RenderOptions& o) { o.shadow.mapSize = -1; }, "map-size"},
        InvalidCase{"map-size=32", [](RenderOptions& o) { o.shadow.mapSize = 32; }, "map-size"},
        InvalidCase{"map-size=16384", [](RenderOptions& o) { o.shadow.mapSize = 16384; },
                    "map-size"},
        InvalidCase{"light-radius=-1", [](RenderOptions& o) { o.shadow.lightRadius = -1.0f; },
                    "light-radius"},
        InvalidCase{"light-radius=NaN", [](RenderOptions& o) { o.shadow.lightRadius = kNaN; },
                    "light-radius"},
        InvalidCase{"light-angle=30", [](RenderOptions& o) { o.shadow.lightAngle = 30.0f; },
                    "light-angle"},
        InvalidCase{"shadow-factor=2", [](RenderOptions& o) { o.shading.shadowFactor = 2.0f; },
                    "shadow-factor"},
        InvalidCase{"shadow-factor=NaN", [](RenderOptions& o) { o.shading.shadowFactor = kNaN; },
                    "shadow-factor"}));

TEST(Options, MessagesQuoteTheBadValue) {
    RenderOptions o;
    o.shadow.pcfSize = 4;
    o.shadow.mapSize = 8;
    const auto problems = o.validate();
    ASSERT_EQ(problems.size(), 2u);  // in the schema's order: map size, then the filter's
    EXPECT_NE(problems[0].find("map-size must be 0 or in 64..8192, got 8"), std::string::npos)
        << problems[0];
    EXPECT_NE(problems[1].find("pcf-size must be odd and in 1..9 texels, got 4"), std::string::npos)
        << problems[1];
    o = RenderOptions{};
    o.width = 0;
    ASSERT_EQ(o.validate().size(), 1u);
    EXPECT_NE(o.validate()[0].find("0x512"), std::string::npos) << o.validate()[0];
}

TEST(Options, EveryProblemIsReported) {
    RenderOptions o;
    o.width = 0;
    o.shadow.biasConstant = kNaN;
    o.shadow.pcfSize = 4;
    o.shadow.mapSize = 8;
    o.shading.shadowFactor = 2.0f;
    EXPECT_EQ(o.validate().size(), 5u);
}

TEST(Options, BoundaryValuesAreValid) {
    RenderOptions o;
    o.width = 1;
    o.height = 16384;
    o.lightOnly = 0;
    o.shadow.biasConstant = 0.0f;
    o.shadow.pcfSize = 9;
    o.shadow.mapSize = 64;
    o.shading.shadowFactor = 1.0f;
    EXPECT_TRUE(o.validate().empty());
    o.shadow.pcfSize = 1;
    o.shadow.mapSize = 8192;
    o.shading.shadowFactor = 0.0f;
    EXPECT_TRUE(o.validate().empty());
}

// Every enum value: toString then parse gives it back, and the names are the CLI's.
TEST(Options, ShadowedRuleRoundTrip) {
    for (ShadowedRule v : {ShadowedRule::AmbientOnly, ShadowedRule::Factor})
        EXPECT_EQ(parseShadowedRule(toString(v)), v) << toString(v);
    EXPECT_STREQ(toString(ShadowedRule::AmbientOnly), "ambient");
    EXPECT_STREQ(toString(ShadowedRule::Factor), "factor");
}

TEST(Options, OutsidePolicyRoundTrip) {
    for (OutsidePolicy v : {OutsidePolicy::Lit, OutsidePolicy::Clamp})
        EXPECT_EQ(parseOutsidePolicy(toString(v)), v) << toString(v);
    EXPECT_STREQ(toString(OutsidePolicy::Lit), "lit");
    EXPECT_STREQ(toString(OutsidePolicy::Clamp), "clamp");
}

TEST(Options, CullModeRoundTrip) {
    for (CullMode v : {CullMode::Back, CullMode::Front, CullMode::None})
        EXPECT_EQ(parseCullMode(toString(v)), v) << toString(v);
    EXPECT_STREQ(toString(CullMode::Front), "front");
}

TEST(Options, ShadowFilterRoundTrip) {
    for (ShadowFilter v : {ShadowFilter::None, ShadowFilter::Hw2x2, ShadowFilter::Pcf})
        EXPECT_EQ(parseShadowFilter(toString(v)), v) << toString(v);
    EXPECT_STREQ(toString(ShadowFilter::Hw2x2), "hw2x2");
}

TEST(Options, UnknownStringsAreRejected) {
    for (const char* s : {"", "Ambient", "ambient ", "shadow", "?"})
        EXPECT_FALSE(parseShadowedRule(s).has_value()) << "'" << s << "'";
    for (const char* s : {"", "LIT", "wrap", "?"})
        EXPECT_FALSE(parseOutsidePolicy(s).has_value()) << "'" << s << "'";
    for (const char* s : {"", "Back", "both", "?"})
        EXPECT_FALSE(parseCullMode(s).has_value()) << "'" << s << "'";
    for (const char* s : {"", "PCF", "hw", "pcf3", "?"})
        EXPECT_FALSE(parseShadowFilter(s).has_value()) << "'" << s << "'";
}

}  // namespace
}  // namespace gnomon
