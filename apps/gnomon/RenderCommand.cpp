
#include "RenderOptionsCli.h"
#include "gnomon/Error.h"
#include "gnomon/OptionSchema.h"

namespace gnomon::cli {
namespace {

const RenderOptions kDefaults;

[[noreturn]] void bad(const std::string& flag, const std::string& message) {
    throw Error(ErrorKind::InvalidInput, flag + ": " + message);
}

template <typename E>
E parseEnum(const std::string& flag, const std::string& value,
            std::optional<E> (*parse)(const std::string&), const char* choices) {
    if (auto v = parse(value)) return *v;
    bad(flag, "expected one of " + std::string(choices) + ", got '" + value + "'");
}

}  // namespace

void RenderFlags::add(CLI::App& a) {
    app = &a;
    a.add_option("--preset", preset,
                 "where options start: default, or textbook = the textbook's own numbers for the "
                 "scene (constant tolerance, its depth storage; acne included); flags given "
                 "override it (default: default)")
        ->type_name("default|textbook")
        ->group("Output");
    a.add_flag("--ground", ground,
               "add a grey ground under the scene (receives shadows, casts none), for models "
               "without a floor")
        ->group("Output");
    for (const OptionSpec& spec : optionSchema()) {
        const std::string defaultText =
            *spec.defaultNote ? spec.defaultNote : formatOption(spec, kDefaults);
        const std::string range = spec.kind == OptionKind::Choice ||
                                          spec.kind == OptionKind::Switch ||
                                          spec.kind == OptionKind::Size
                                      ? ""
                                      : optionRange(spec) + "; ";
        a.add_option("--" + std::string(spec.name), values[spec.name],
                     std::string(spec.doc) + " (" + range + "default " + defaultText + ")")
            ->type_name(optionValueName(spec))
            ->group(spec.group);
    }
}

RenderOptions RenderFlags::resolve(const Scene& scene) const {
    Preset p = Preset::Default;
    if (app->count("--preset") > 0)
        p = parseEnum("--preset", preset, parsePreset, "default, textbook");
    RenderOptions o = presetOptions(scene, p);
    apply(o);
    return o;
}

void RenderFlags::apply(RenderOptions& o) const {
    for (const OptionSpec& spec : optionSchema()) {
        const std::string flag = "--" + std::string(spec.name);
        if (app->count(flag) == 0) continue;
        if (auto why = parseOption(spec, values.at(spec.name), o)) bad(flag, *why);
    }
    if (auto problems = o.validate(); !problems.empty()) {
        std::string all;
        for (const auto& p : problems)
            all += (all.empty() ? "" : "; ") + p;
        throw Error(ErrorKind::InvalidInput, all);
    }
    // A flag given that the other options make pointless: said once, not silently ignored.
    for (const OptionSpec& spec : optionSchema()) {
        if (spec.matters && app->count("--" + std::string(spec.name)) > 0 && !spec.matters(o)) {
            std::fprintf(stderr,
                         "gnomon: warning: --%s does nothing here: it applies only with %s\n",
                         spec.name, spec.onlyWith);
        }
    }
}

}  // namespace gnomon::cli
