// The main pass's variant table (render/MainVariant.h): over the option combinations and frame
// choices a renderer meets, distinct variants give distinct #defines and equal defines come
// from one key, so no program is built twice and no key serves the wrong program.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include "render/MainVariant.h"

namespace gnomon::render {
namespace {

std::string joined(const std::vector<std::string>& defines) {
    std::string s;
    for (const std::string& d : defines)
        s += d + "\n";
    return s;
}

// Every option combination below, on and off the floor, for casters and receivers only.
std::vector<MainVariant> optionVariants() {
    std::vector<MainVariant> out;
    const ShadowFilter filters[] = {ShadowFilter::None,    ShadowFilter::Hw2x2, ShadowFilter::Pcf,
                                    ShadowFilter::Poisson, ShadowFilter::Pcss,  ShadowFilter::Evsm2,
                                    ShadowFilter::Evsm4,   ShadowFilter::Msm};
    const DepthFormat formats[] = {
        DepthFormat::R8,      DepthFormat::Rgba8Packed256, DepthFormat::Rgba8Packed255,
        DepthFormat::Depth16, DepthFormat::Depth24,        DepthFormat::Depth32F};
    for (ShadowFilter filter : filters)
        for (int pcf : {1, 3, 9})
            for (DepthFormat format : formats)
                for (int flags = 0; flags < 64; ++flags) {
                    RenderOptions o;
                    o.shadow.filter = filter;
                    o.shadow.pcfSize = pcf;
                    o.shadow.depthFormat = format;
                    o.shadow.mapFilter = flags & 1 ? MapFilter::Nearest : MapFilter::Linear;
                    o.shadow.receiverPlane = flags & 2;
                    o.shadow.normalOffset = flags & 4 ? 1.0f : 0.0f;
                    o.shadow.outside = flags & 8 ? OutsidePolicy::Clamp : OutsidePolicy::Lit;
                    const bool floor = flags & 16, receiverOnly = flags & 32;
                    out.push_back(variantOf(o, floor, receiverOnly));
                }
    return out;
}

TEST(MainVariant, DistinctVariantsHaveDistinctDefines) {
    std::vector<MainVariant> variants = optionVariants();
    // The rest of the options and the frame's choices, each on its own and with unrolling.
    RenderOptions o;
    const auto add = [&](auto change) {
        for (bool floor : {false, true}) {
            MainVariant v = variantOf(o, floor, false);
            change(v);
            variants.push_back(v);
        }
    };
    o.shadow.enabled = false;
    add([](MainVariant&) {});
    o = {};
    o.shadow.casterDetail = 0.5f;
    add([](MainVariant&) {});
    o = {};
    o.debugView = DebugView::Cascades;
    add([](MainVariant&) {});
    o = {};
    o.shading.dither = true;
    for (OutputEncoding e : {OutputEncoding::Srgb, OutputEncoding::Linear}) {
        o.shading.output = e;
        add([](MainVariant&) {});
    }
    o = {};
    o.shading.shadowedRule = ShadowedRule::Factor;
    add([](MainVariant&) {});
    o = {};
    o.shadow.shadowRays = ShadowRayMode::All;
    add([](MainVariant&) {});
    add([](MainVariant& v) { v.hasCubes = v.hasCascades = v.visibilityPass = 1; });
    o = {};
    add([](MainVariant& v) { v.visibilityPass = 1; });
    add([](MainVariant& v) { v.material = 1; });
    add([](MainVariant& v) { v.contactShadows = 1; });
    add([](MainVariant& v) { v.coloured = 1; });
    add([](MainVariant& v) { v.hasCubes = 1; });
    add([](MainVariant& v) { v.hasCascades = 1; });
    add([](MainVariant& v) { v.pointFaces = 1; });
    add([](MainVariant& v) { v.constantFalloff = 1; });
    add([](MainVariant& v) { v.noSpecular = 1; });
    add([](MainVariant& v) { v.shadowRays = 1, v.rayCutouts = 1; });
    for (int kind = 0; kind <= 4; ++kind)
        add([&](MainVariant& v) { v.singleMapKind = MainVariant::Bits(kind); });
    for (int counts = 0; counts < 16 * 16; ++counts) {
        add([&](MainVariant& v) {
            v.unrolled = 1;
            v.unshadowedCount = MainVariant::Bits(counts % 4);
            v.mapCount = MainVariant::Bits(counts / 4 % 4);
            v.cubeCount = MainVariant::Bits(counts / 16 % 4);
            v.cascadedCount = MainVariant::Bits(counts / 64);
        });
    }

    std::map<std::uint64_t, std::string> byKey;
    std::map<std::string, std::uint64_t> byDefines;
    for (const MainVariant& v : variants) {
        const std::string d = joined(v.defines(256));
        const auto [k, newKey] = byKey.emplace(v.key(), d);
        EXPECT_EQ(k->second, d) << "one key, two define lists";
        const auto [e, newDefines] = byDefines.emplace(d, v.key());
        EXPECT_EQ(e->second, v.key()) << "two keys build the same program:\n" << d;
    }
    EXPECT_EQ(byKey.size(), byDefines.size());
    EXPECT_GT(byKey.size(), 1000u);  // the enumeration reached many programs
}

TEST(MainVariant, ChoicesOutsideTheLookupDoNotSplitPrograms) {
    // Kernel widths matter only to kernel filters; the map filter only to hand comparisons.
    RenderOptions a, b;
    a.shadow.filter = b.shadow.filter = ShadowFilter::Hw2x2;
    a.shadow.pcfSize = 3;
    b.shadow.pcfSize = 7;
    EXPECT_EQ(variantOf(a, false, false).key(), variantOf(b, false, false).key());
    a.shadow.filter = b.shadow.filter = ShadowFilter::Pcf;
    EXPECT_NE(variantOf(a, false, false).key(), variantOf(b, false, false).key());
}

}  // namespace
}  // namespace gnomon::render
