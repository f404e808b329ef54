// The render options as data: one entry per option (its name, group, one-line doc, unit,
// range or choices, when it has an effect, and how to read and write it in a RenderOptions).
// The CLI's flags and their help, the scene files' "options" keys (read and written),
// RenderOptions::validate(), the viewer's controls and the docs' option tables are all made
// from this one list, so they cannot disagree: adding an option is one entry here plus the
// code that uses it (docs/extending.md).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "gnomon/Options.h"

namespace gnomon {

// The help's sections, in help order (also the viewer's headers and the docs tables' first
// column).
enum class OptionGroup { Output, ShadowMaps, Tolerances, Filtering, Cascades, Shading };
// The group's title: "Output", "Shadow maps", ...
const char* toString(OptionGroup g);
// Whether the group's options tune the shadow technique, so that without a rule of their own
// they have an effect only with shadows on.
bool isTechniqueGroup(OptionGroup g);

enum class OptionKind {
    Switch,   // on|off (scene files: true or false)
    Integer,  // a whole number in [min, max] (0 may be allowed apart, and named)
    Real,     // a finite number in [min, max] (or [min, max) with maxExclusive)
    Choice,   // one of `choices` (an enum, in its order)
    Size,     // WIDTHxHEIGHT, each 1..16384
};

struct OptionSpec {
    const char* name = "";  // CLI flag without "--", scene-file key, viewer label
    OptionGroup group = OptionGroup::Output;
    const char* doc = "";   // one line: what it does (range and default are added from below)
    const char* unit = "";  // for messages and help ("" when none): "texels", "degrees", ...
    OptionKind kind = OptionKind::Switch;
    double min = 0.0, max = 0.0;
    bool maxExclusive = false;
    bool zeroAllowed = false;               // Integer: 0 is valid outside [min, max]
    const char* zeroName = "";              // Integer: how 0 is spelled ("auto"); "" = "0"
    bool odd = false;                       // Integer: odd values only
    std::vector<std::string> choices = {};  // Choice
    // Choice that was once a Switch: the choice `on` (scene files: true) still names; `off`
    // (false) is a choice of its own. "" for the others.
    const char* formerOn = "";
    const char* defaultNote = "";  // instead of the library default in help ("the scene's")
    // The value as a number: Switch 0/1, Choice its index. Null for Size, whose value is
    // two numbers (width and height: formatOption and parseOption handle it).
    double (*get)(const RenderOptions&) = nullptr;
    void (*set)(RenderOptions&, double) = nullptr;
    // Where the value lives in `o` (for Size, the width): names an option in code the
    // compiler checks, see optionAt().
    const void* (*field)(const RenderOptions& o) = nullptr;
    // Whether the option has an effect with the other options `o` holds (null: always), and
    // the condition in the CLI's words ("--filter pcf or poisson"): the CLI warns about a flag
    // that would do nothing, the viewer dims its control. See optionSchema() for the default.
    bool (*matters)(const RenderOptions& o) = nullptr;
    const char* onlyWith = "";
    // In a technique group, has an effect with shadows off too (--shadows itself).
    bool mattersWithoutShadows = false;
};

// Every render option, in help order. An option of a technique group with no rule of its own
// has the rule "--shadows on".
const std::vector<OptionSpec>& optionSchema();
// The entry named `name` (without "--"), or null.
const OptionSpec* findOption(const std::string& name);
// The entry whose value lives at `field`, a member of `o`: optionAt(o, &o.shadow.mapSize).
// Code that needs one particular option names it this way, so a typo does not compile;
// throws std::logic_error for a member no entry holds. (A struct's address is its first
// member's: &o.shadow names "shadows".)
const OptionSpec& optionAt(const RenderOptions& o, const void* field);

// The value of `spec` in `o` as the CLI spells it: "on", "0.00005", "pcf", "auto", "512x512".
std::string formatOption(const OptionSpec& spec, const RenderOptions& o);
// Sets `spec` in `o` from its CLI spelling; on bad text, returns why ("expected one of
// none, pcf, got 'blurry'") and leaves `o` as it was. Ranges are validate()'s.
std::optional<std::string> parseOption(const OptionSpec& spec, const std::string& text,
                                       RenderOptions& o);
// What `spec` accepts, in words for help and messages: "0..100 texels", "[0, 1)",
// "none|pcf|...", "auto or 1..4", "odd 1..9", "WIDTHxHEIGHT".
std::string optionRange(const OptionSpec& spec);
// The value name in help: N, X, WxH, on|off, or the choices joined by |.
std::string optionValueName(const OptionSpec& spec);
// "" when `spec`'s value in `o` is within its range, else one sentence naming the option.
std::string checkOption(const OptionSpec& spec, const RenderOptions& o);
// Sets the options `given` names (schema name -> CLI spelling) over `o`, in schema order,
// then validate()s them all: what the CLI's flags and the web page's address do. Throws
// gnomon::Error (InvalidInput) in the CLI's words: "--map-size: ..." for text parseOption
// refuses, validate()'s sentences joined by "; " for values out of range. Returns one
// warning per given option the others make pointless ("--pcf-size does nothing here: it
// applies only with ..."). Names outside the schema are the caller's to refuse.
std::vector<std::string> applyOptionTexts(const std::map<std::string, std::string>& given,
                                          RenderOptions& o);

// The docs' option tables, made from the schema (README.md and docs/scene-file.md hold
// them between <!-- options:... --> markers; a test keeps them equal to these).
enum class OptionTable {
    Flags,      // | group | flag | meaning (range) | default |
    SceneFile,  // | key | type | default | meaning |
};
std::string optionTableMarkdown(OptionTable table);

}  // namespace gnomon
