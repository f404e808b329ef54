// The render options as data: one entry per option (its name, group, one-line doc, unit,
// range or choices, and how to read and write it in a RenderOptions). The CLI's flags and
// their help, the scene files' "options" keys (read and written), RenderOptions::validate()
// and the docs' option tables are all made from this one list, so they cannot disagree:
// adding an option is one entry here plus the code that uses it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "gnomon/Options.h"

namespace gnomon {

enum class OptionKind {
    Switch,   // on|off (scene files: true or false)
    Integer,  // a whole number in [min, max] (0 may be allowed apart, and named)
    Real,     // a finite number in [min, max] (or [min, max) with maxExclusive)
    Choice,   // one of `choices` (an enum, in its order)
    Size,     // WIDTHxHEIGHT, each 1..16384
};

struct OptionSpec {
    const char* name = "";   // CLI flag without "--", scene-file key, viewer label
    const char* group = "";  // help section: "Output", "Shadow maps", "Tolerances", ...
    const char* doc = "";    // one line: what it does (range and default are added from below)
    const char* unit = "";   // for messages and help ("" when none): "texels", "degrees", ...
    OptionKind kind = OptionKind::Switch;
    double min = 0.0, max = 0.0;
    bool maxExclusive = false;
    bool zeroAllowed = false;               // Integer: 0 is valid outside [min, max]
    const char* zeroName = "";              // Integer: how 0 is spelled ("auto"); "" = "0"
    bool odd = false;                       // Integer: odd values only
    std::vector<std::string> choices = {};  // Choice
    const char* defaultNote = "";  // instead of the library default in help ("the scene's")
    // The value as a number: Switch 0/1, Choice its index, Size the width.
    double (*get)(const RenderOptions&) = nullptr;
    void (*set)(RenderOptions&, double) = nullptr;
    // Whether the option has an effect with the other options `o` holds (null: always), and
    // when it does, in the CLI's words ("--filter pcss"): what warns about a flag that would
    // do nothing.
    bool (*matters)(const RenderOptions& o) = nullptr;
    const char* onlyWith = "";
};

// Every render option, in help order.
const std::vector<OptionSpec>& optionSchema();
// The entry named `name` (without "--"), or null.
const OptionSpec* findOption(const std::string& name);

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

// The docs' option tables, made from the schema (README.md and docs/scene-file.md hold
// them between <!-- options:... --> markers; a test keeps them equal to these).
enum class OptionTable {
    Flags,      // | group | flag | meaning (range) | default |
    SceneFile,  // | key | type | default | meaning |
};
std::string optionTableMarkdown(OptionTable table);

}  // namespace gnomon
