// Every render option as a flag of `gnomon render` (apps/gnomon/RenderCommand.cpp), made from
// the schema so that a new option is covered without a test naming it: each option's flag,
// given a value other than the scene's (OptionValues.h), sets that option and nothing else,
// and all of them given together set them all.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>

#include "OptionValues.h"
#include "RenderOptionsCli.h"

namespace gnomon::test {
namespace {

// What `gnomon render --scene SCENE ARGS` renders `scene` with.
RenderOptions parsed(const std::vector<std::string>& args, const Scene& scene) {
    CLI::App app{"render"};
    cli::RenderFlags flags;
    flags.add(app);
    std::vector<std::string> reversed(args.rbegin(), args.rend());
    app.parse(reversed);
    return flags.resolve(scene);
}

TEST(RenderFlags, EveryOptionsFlagSetsThatOptionOnly) {
    const Scene scene = builtinScene("tutorial-room");
    const RenderOptions base = parsed({}, scene);  // the scene's own options
    std::size_t covered = 0;
    for (const OptionSpec& spec : optionSchema()) {
        const std::string flag = "--" + std::string(spec.name), value = otherValue(spec, base);
        SCOPED_TRACE(flag + " " + value);
        RenderOptions expected = base;
        ASSERT_EQ(parseOption(spec, value, expected), std::nullopt);
        const RenderOptions o = parsed({flag, value}, scene);
        EXPECT_FALSE(sameOption(spec, o, base)) << "the flag changed nothing";
        EXPECT_TRUE(o == expected) << "the flag changed another option";
        covered += !sameOption(spec, o, base);
    }
    EXPECT_EQ(covered, optionSchema().size());
}

TEST(RenderFlags, EveryFlagAtOnce) {
    const Scene scene = builtinScene("tutorial-room");
    const RenderOptions base = parsed({}, scene);
    std::vector<std::string> args;
    RenderOptions expected = base;
    for (const OptionSpec& spec : optionSchema()) {
        const std::string value = otherValue(spec, base);
        args.insert(args.end(), {"--" + std::string(spec.name), value});
        ASSERT_EQ(parseOption(spec, value, expected), std::nullopt) << spec.name;
    }
    ASSERT_TRUE(expected.validate().empty());
    const RenderOptions o = parsed(args, scene);
    for (const OptionSpec& spec : optionSchema()) {
        EXPECT_TRUE(sameOption(spec, o, expected)) << spec.name;
        EXPECT_FALSE(sameOption(spec, o, base)) << spec.name;
    }
}

}  // namespace
}  // namespace gnomon::test
