// The text forms of the render options (include/gnomon/OptionSchema.h): values as the CLI
// spells them, ranges in words, range checks, and the docs' tables.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <regex>

#include "gnomon/Error.h"
#include "gnomon/OptionSchema.h"

namespace gnomon {
namespace {

constexpr double kHuge = std::numeric_limits<double>::max();  // the schema's "no bound"

// Shortest text that reads back as the same float (the options are floats).
std::string number(double v) {
    char buf[32];
    if (v == std::floor(v) && std::abs(v) < 1e15) {
        std::snprintf(buf, sizeof buf, "%.0f", v);
        return buf;
    }
    for (int precision = 1; precision <= 9; ++precision) {
        std::snprintf(buf, sizeof buf, "%.*g", precision, v);
        if (float(std::strtod(buf, nullptr)) == float(v)) break;
    }
    return buf;
}

std::string joined(const std::vector<std::string>& v, const char* separator) {
    std::string out;
    for (const std::string& s : v)
        out += (out.empty() ? "" : separator) + s;
    return out;
}

}  // namespace

std::string formatOption(const OptionSpec& spec, const RenderOptions& o) {
    switch (spec.kind) {
        case OptionKind::Size:
            return std::to_string(o.width) + "x" + std::to_string(o.height);
        case OptionKind::Switch:
            return spec.get(o) != 0.0 ? "on" : "off";
        case OptionKind::Choice: {
            const auto i = std::size_t(spec.get(o));
            return i < spec.choices.size() ? spec.choices[i] : "?";
        }
        case OptionKind::Integer: {
            const long long v = (long long)spec.get(o);
            return v == 0 && *spec.zeroName ? spec.zeroName : std::to_string(v);
        }
        case OptionKind::Real:
            return number(spec.get(o));
    }
    return "?";
}

std::optional<std::string> parseOption(const OptionSpec& spec, const std::string& text,
                                       RenderOptions& o) {
    const std::string got = ", got '" + text + "'";
    switch (spec.kind) {
        case OptionKind::Size: {
            // Any digits parse (up to 9: no int overflow); the range check names the limits.
            static const std::regex kSize(R"((\d{1,9})x(\d{1,9}))");
            std::smatch m;
            if (!std::regex_match(text, m, kSize))
                return "expected WIDTHxHEIGHT such as 512x512" + got;
            o.width = std::stoi(m[1].str());
            o.height = std::stoi(m[2].str());
            return std::nullopt;
        }
        case OptionKind::Switch:
            if (text != "on" && text != "off") return "expected on or off" + got;
            spec.set(o, text == "on" ? 1.0 : 0.0);
            return std::nullopt;
        case OptionKind::Choice:
            for (std::size_t i = 0; i < spec.choices.size(); ++i) {
                if (text == spec.choices[i] ||
                    (*spec.formerOn && text == "on" && spec.choices[i] == spec.formerOn)) {
                    spec.set(o, double(i));
                    return std::nullopt;
                }
            }
            return "expected one of " + joined(spec.choices, ", ") + got;
        case OptionKind::Integer: {
            if (*spec.zeroName && text == spec.zeroName) {
                spec.set(o, 0.0);
                return std::nullopt;
            }
            static const std::regex kInteger(R"(-?\d{1,10})");
            const long long v = std::regex_match(text, kInteger) ? std::stoll(text) : 0;
            if (!std::regex_match(text, kInteger) || v < std::numeric_limits<int>::min() ||
                v > std::numeric_limits<int>::max())
                return std::string("expected ") +
                       (*spec.zeroName ? std::string(spec.zeroName) + " or " : "") + "an integer" +
                       got;
            spec.set(o, double(v));
            return std::nullopt;
        }
        case OptionKind::Real: {
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v))
                return "expected a number" + got;
            spec.set(o, v);
            return std::nullopt;
        }
    }
    return "cannot be set";
}

std::string optionRange(const OptionSpec& spec) {
    const std::string unit = *spec.unit ? std::string(" ") + spec.unit : "";
    switch (spec.kind) {
        case OptionKind::Size:
            return "WIDTHxHEIGHT, each 1..16384";
        case OptionKind::Switch:
            return "on or off";
        case OptionKind::Choice:
            return joined(spec.choices, ", ");
        case OptionKind::Integer: {
            std::string r = (spec.odd ? "odd " : "") + number(spec.min) +
                            (spec.max >= std::numeric_limits<int>::max() ? " or more"
                                                                         : ".." + number(spec.max));
            if (spec.zeroAllowed)
                r = (*spec.zeroName ? spec.zeroName : "0") + std::string(" or ") + r;
            return r + unit;
        }
        case OptionKind::Real:
            if (spec.min <= -kHuge) return *spec.unit ? spec.unit : "any number";
            return "[" + number(spec.min) + ", " + number(spec.max) +
                   (spec.maxExclusive ? ")" : "]") + unit;
    }
    return "";
}

std::string optionValueName(const OptionSpec& spec) {
    switch (spec.kind) {
        case OptionKind::Size:
            return "WxH";
        case OptionKind::Switch:
            return "on|off";
        case OptionKind::Choice:
            return joined(spec.choices, "|");
        case OptionKind::Integer:
            return *spec.zeroName ? std::string(spec.zeroName) + "|N" : "N";
        case OptionKind::Real:
            return "X";
    }
    return "";
}

std::string checkOption(const OptionSpec& spec, const RenderOptions& o) {
    switch (spec.kind) {
        case OptionKind::Size:
            if (o.width >= 1 && o.width <= 16384 && o.height >= 1 && o.height <= 16384) return "";
            return "size " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                   " is outside 1x1..16384x16384";
        case OptionKind::Switch:
            return "";
        case OptionKind::Choice:
            return std::size_t(spec.get(o)) < spec.choices.size()
                       ? ""
                       : std::string(spec.name) + " has no such value";
        case OptionKind::Integer: {
            const double v = spec.get(o);
            const bool inRange = v >= spec.min && v <= spec.max && (!spec.odd || int(v) % 2 != 0);
            if (inRange || (spec.zeroAllowed && v == 0.0)) return "";
            const std::string zero = !spec.zeroAllowed ? ""
                                     : *spec.zeroName  ? std::string(spec.zeroName) + " (0) or "
                                                       : "0 or ";
            const std::string range = spec.max >= std::numeric_limits<int>::max()
                                          ? number(spec.min) + " or more"
                                          : "in " + number(spec.min) + ".." + number(spec.max);
            return std::string(spec.name) + " must be " + zero + (spec.odd ? "odd and " : "") +
                   range + (*spec.unit ? " " : "") + spec.unit + ", got " +
                   std::to_string((long long)v);
        }
        case OptionKind::Real: {
            const double v = spec.get(o);
            const bool inRange = std::isfinite(v) && v >= spec.min &&
                                 (spec.maxExclusive ? v < spec.max : v <= spec.max);
            if (inRange) return "";
            return std::string(spec.name) + " must be " +
                   (spec.min <= -kHuge ? std::string("a finite number")
                                       : "in " + optionRange(spec)) +
                   ", got " + number(v);
        }
    }
    return "";
}

std::vector<std::string> applyOptionTexts(const std::map<std::string, std::string>& given,
                                          RenderOptions& o) {
    for (const OptionSpec& spec : optionSchema()) {
        const auto text = given.find(spec.name);
        if (text == given.end()) continue;
        if (auto why = parseOption(spec, text->second, o))
            throw Error(ErrorKind::InvalidInput, "--" + std::string(spec.name) + ": " + *why);
    }
    if (auto problems = o.validate(); !problems.empty())
        throw Error(ErrorKind::InvalidInput, joined(problems, "; "));
    std::vector<std::string> warnings;
    for (const OptionSpec& spec : optionSchema()) {
        if (spec.matters && given.count(spec.name) && !spec.matters(o)) {
            warnings.push_back("--" + std::string(spec.name) +
                               " does nothing here: it applies only with " + spec.onlyWith);
        }
    }
    return warnings;
}

namespace {

std::string escapeBars(const std::string& s) {
    std::string out;
    for (char c : s)
        out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

std::string defaultText(const OptionSpec& spec) {
    return *spec.defaultNote ? spec.defaultNote : formatOption(spec, RenderOptions{});
}

// The default as a scene file writes it.
std::string jsonDefault(const OptionSpec& spec) {
    const std::string v = formatOption(spec, RenderOptions{});
    switch (spec.kind) {
        case OptionKind::Switch:
            return v == "on" ? "`true`" : "`false`";
        case OptionKind::Size:
            return "`\"" + v + "\"`";
        case OptionKind::Integer:
            return *spec.zeroName && v == spec.zeroName ? "`\"" + v + "\"`" : "`" + v + "`";
        default:
            return "`" + v + "`";
    }
}

std::string jsonType(const OptionSpec& spec) {
    switch (spec.kind) {
        case OptionKind::Switch:
            return "bool";
        case OptionKind::Size:
            return "`\"WIDTHxHEIGHT\"`, each 1..16384 (or `width` and `height`)";
        case OptionKind::Integer:
            return (*spec.zeroName ? "`\"" + std::string(spec.zeroName) + "\"` or "
                                   : std::string()) +
                   "integer " +
                   (*spec.zeroName ? number(spec.min) + ".." + number(spec.max)
                                   : optionRange(spec));
        case OptionKind::Real:
            return spec.min <= -kHuge ? optionRange(spec) : "number " + optionRange(spec);
        case OptionKind::Choice: {
            std::string out;
            for (const std::string& c : spec.choices)
                out += (out.empty() ? "`" : ", `") + c + "`";
            if (*spec.formerOn)
                out += " (or `true`: " + std::string(spec.formerOn) + ", `false`: off)";
            return out;
        }
    }
    return "";
}

}  // namespace

std::string optionTableMarkdown(OptionTable table) {
    std::string out = table == OptionTable::Flags
                          ? "| group | flag | meaning | default |\n|---|---|---|---|\n"
                          : "| key | type | default | |\n|---|---|---|---|\n";
    for (const OptionSpec& spec : optionSchema()) {
        if (table == OptionTable::Flags) {
            const bool ranged = spec.kind == OptionKind::Integer || spec.kind == OptionKind::Real;
            out += "| " + std::string(toString(spec.group)) + " | `--" + spec.name + " " +
                   escapeBars(optionValueName(spec)) + "` | " + spec.doc +
                   (ranged ? " (" + optionRange(spec) + ")" : std::string()) + " | " +
                   defaultText(spec) + " |\n";
        } else {
            out += "| `" + std::string(spec.name) + "` | " + jsonType(spec) + " | " +
                   jsonDefault(spec) + " | " + spec.doc + " |\n";
        }
    }
    return out;
}

}  // namespace gnomon
