// Golden images of every built-in scene at 256x256 (tests/golden/README.md says how they
// were made and how to regenerate them). Rendering on llvmpipe is deterministic, but other
// Mesa versions and GPUs round differently, so each comparison has stated tolerances.
#include <gtest/gtest.h>

#include <filesystem>

#include "GlTest.h"
#include "GoldenTolerance.h"

namespace gnomon::test {
namespace {

class Golden : public testing::TestWithParam<std::string> {};

TEST_P(Golden, MatchesWithinTolerance) {
    const std::string name = GetParam();
    const std::string golden = goldenDir() + "/" + name + ".png";
    ASSERT_TRUE(std::filesystem::exists(golden))
        << golden << " is missing; run scripts/update-goldens.sh";
    const Scene scene = builtinScene(name);
    RenderOptions o = scene.options;
    o.width = o.height = 256;
    const Image actual = sharedRenderer().render(scene, o);
    const Image expected = readPng(golden);
    const ImageDiff d = compareImages(actual, expected, kChannelThreshold);
    const bool ok = d.failingFraction <= kMaxFailingFraction && d.meanAbsDiff <= kMaxMeanDiff;
    if (!ok) {
        writePng(outputDir() + "/" + name + ".actual.png", actual);
        writePng(outputDir() + "/" + name + ".diff.png", d.diff);
    }
    EXPECT_TRUE(ok) << name << ": max channel diff " << d.maxChannelDiff << ", "
                    << d.failingFraction * 100.0 << "% pixels over " << kChannelThreshold
                    << " (allowed " << kMaxFailingFraction * 100.0 << "%), mean " << d.meanAbsDiff
                    << " (allowed " << kMaxMeanDiff << "); actual and diff written to "
                    << outputDir();
}

std::vector<std::string> names() {
    std::vector<std::string> out;
    for (const SceneInfo& s : builtinScenes())
        out.push_back(s.name);
    return out;
}

INSTANTIATE_TEST_SUITE_P(Builtin, Golden, testing::ValuesIn(names()), [](const auto& info) {
    std::string n = info.param;
    for (char& c : n)
        c = c == '-' ? '_' : c;
    return n;
});

// The comparison itself must catch a real change: a render without shadows fails it.
TEST(GoldenTolerance, MissingShadowIsCaught) {
    const Scene scene = builtinScene("tutorial-room");
    RenderOptions o = scene.options;
    o.width = o.height = 256;
    o.shadow.enabled = false;
    const Image plain = sharedRenderer().render(scene, o);
    const ImageDiff d =
        compareImages(plain, readPng(goldenDir() + "/tutorial-room.png"), kChannelThreshold);
    EXPECT_TRUE(d.failingFraction > kMaxFailingFraction || d.meanAbsDiff > kMaxMeanDiff)
        << "tolerances too loose: " << d.failingFraction << " / " << d.meanAbsDiff;
}

}  // namespace
}  // namespace gnomon::test
