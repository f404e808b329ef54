// The option schema itself (include/gnomon/OptionSchema.h): every entry is complete and
// reaches its own member of RenderOptions and no other, code can name an entry by its member,
// and the rules for when an option has an effect come with their words.
#include <set>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "OptionValues.h"
#include "gnomon/OptionSchema.h"

namespace gnomon::test {
namespace {

TEST(OptionSchema, EveryEntryIsCompleteWithAUniqueNameAndMember) {
    const RenderOptions o;
    std::set<std::string> names;
    std::set<const void*> fields;
    for (const OptionSpec& spec : optionSchema()) {
        SCOPED_TRACE(spec.name);
        EXPECT_TRUE(names.insert(spec.name).second) << "a second entry of that name";
        ASSERT_NE(spec.field, nullptr);
        EXPECT_TRUE(fields.insert(spec.field(o)).second) << "a second entry of that member";
        EXPECT_NE(*spec.doc, '\0');
        // A size is two numbers, read and written as text; every other kind is one number.
        EXPECT_EQ(spec.get == nullptr, spec.kind == OptionKind::Size);
        EXPECT_EQ(spec.set == nullptr, spec.kind == OptionKind::Size);
        EXPECT_EQ(spec.choices.empty(), spec.kind != OptionKind::Choice);
    }
}

// Setting an option changes its own member and leaves every other option as it was: a copied
// accessor that writes a neighbour's member fails here.
TEST(OptionSchema, EachOptionSetsItsOwnMemberOnly) {
    const RenderOptions defaults;
    for (const OptionSpec& spec : optionSchema()) {
        SCOPED_TRACE(spec.name);
        RenderOptions o = defaults;
        const std::string value = otherValue(spec, defaults);
        ASSERT_EQ(parseOption(spec, value, o), std::nullopt) << value;
        EXPECT_TRUE(o.validate().empty()) << value;
        EXPECT_FALSE(sameOption(spec, o, defaults)) << value << " is the default";
        EXPECT_EQ(formatOption(spec, o), value);
        for (const OptionSpec& other : optionSchema()) {
            if (&other != &spec) {
                EXPECT_TRUE(sameOption(other, o, defaults)) << other.name;
            }
        }
    }
}

TEST(OptionSchema, OptionAtNamesAnEntryByItsMember) {
    const RenderOptions o;
    for (const OptionSpec& spec : optionSchema())
        EXPECT_EQ(&optionAt(o, spec.field(o)), &spec) << spec.name;
    EXPECT_STREQ(optionAt(o, &o.shadow.pcfSize).name, "pcf-size");
    EXPECT_STREQ(optionAt(o, &o.width).name, "size");
    EXPECT_THROW(optionAt(o, &o.height), std::logic_error);  // the size is held by its width
}

// A rule comes with its condition in words (what the CLI's warning and the viewer's tooltip
// say), and an option of the shadow technique without a rule of its own needs shadows on.
TEST(OptionSchema, RulesComeWithTheirConditionAndTechniqueOptionsNeedShadows) {
    RenderOptions off;
    off.shadow.enabled = false;
    int shadowsRule = 0;
    for (const OptionSpec& spec : optionSchema()) {
        SCOPED_TRACE(spec.name);
        EXPECT_EQ(spec.matters == nullptr, *spec.onlyWith == '\0');
        if (isTechniqueGroup(spec.group) && !spec.mattersWithoutShadows) {
            EXPECT_NE(spec.matters, nullptr) << "a technique option that always matters";
        }
        if (std::string(spec.onlyWith) == "--shadows on") {
            ++shadowsRule;
            EXPECT_TRUE(spec.matters(RenderOptions{}));
            EXPECT_FALSE(spec.matters(off));
        }
    }
    EXPECT_GT(shadowsRule, 0);
    // The switch itself has an effect either way.
    const RenderOptions o;
    EXPECT_EQ(optionAt(o, &o.shadow.enabled).matters, nullptr);
}

TEST(OptionSchema, AChoiceThatWasASwitchTakesOnAsBefore) {
    RenderOptions o;
    const OptionSpec& tiles = optionAt(o, &o.shading.lightTiles);
    EXPECT_EQ(parseOption(tiles, "off", o), std::nullopt);
    EXPECT_EQ(o.shading.lightTiles, LightTiles::Off);
    EXPECT_EQ(parseOption(tiles, "on", o), std::nullopt);
    EXPECT_EQ(o.shading.lightTiles, LightTiles::Auto);
    EXPECT_EQ(formatOption(tiles, o), "auto");
    EXPECT_EQ(parseOption(tiles, "lists", o), std::nullopt);
    EXPECT_EQ(o.shading.lightTiles, LightTiles::Lists);
    // Other choices take no "on".
    EXPECT_NE(parseOption(optionAt(o, &o.shadow.filter), "on", o), std::nullopt);
}

TEST(OptionSchema, GroupsAreTheHelpSectionsInOrder) {
    int last = -1;
    for (const OptionSpec& spec : optionSchema()) {
        EXPECT_GE(int(spec.group), last) << spec.name << ": a group's entries stay together";
        last = int(spec.group);
        EXPECT_STRNE(toString(spec.group), "?");
    }
    EXPECT_STREQ(toString(OptionGroup::ShadowMaps), "Shadow maps");
    EXPECT_FALSE(isTechniqueGroup(OptionGroup::Output));
    EXPECT_TRUE(isTechniqueGroup(OptionGroup::Filtering));
}

}  // namespace
}  // namespace gnomon::test
