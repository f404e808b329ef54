// The one list of render options (include/gnomon/OptionSchema.h); their text forms and the
// docs' tables are in OptionText.cpp.
#include "gnomon/OptionSchema.h"

#include <limits>

namespace gnomon {
namespace {

// The names of an enum's values in its order, as toString spells them.
template <typename E>
std::vector<std::string> namesOf() {
    std::vector<std::string> out;
    for (int i = 0; i < 64; ++i) {
        const std::string name = toString(E(i));
        if (name == "?") break;
        out.push_back(name);
    }
    return out;
}

// Accessors for a member reached by `FIELD` (an expression of `o`), as numbers.
#define NUMBER(FIELD, TYPE)                                 \
    [](const RenderOptions& o) { return double(o.FIELD); }, \
        [](RenderOptions& o, double v) { o.FIELD = static_cast<TYPE>(v); }
#define ENUM(FIELD, TYPE)                                        \
    [](const RenderOptions& o) { return double(int(o.FIELD)); }, \
        [](RenderOptions& o, double v) { o.FIELD = TYPE(int(v)); }

constexpr double kHuge = std::numeric_limits<double>::max();  // "no bound"

// What the frame is and how it is written.
void addOutput(std::vector<OptionSpec>& s) {
    using K = OptionKind;
    auto add = [&](OptionSpec spec) { s.push_back(std::move(spec)); };
    add({"size",
         "Output",
         "output size in pixels",
         "",
         K::Size,
         1,
         16384,
         false,
         false,
         "",
         false,
         {},
         "the scene's, usually 512x512",
         nullptr,
         nullptr});
    add({"time",
         "Output",
         "seconds of animation to pose (the book triangle turns 40 deg/s)",
         "seconds",
         K::Real,
         -kHuge,
         kHuge,
         false,
         false,
         "",
         false,
         {},
         "",
         NUMBER(time, double)});
    add({"light-only",
         "Output",
         "render with only light N on (-1: the scene's switches)",
         "",
         K::Integer,
         -1,
         std::numeric_limits<int>::max(),
         false,
         false,
         "",
         false,
         {},
         "",
         NUMBER(lightOnly, int)});
    add({"output-encoding", "Output",
         "image colours as computed (the textbooks) or sRGB-encoded for display (glTF viewers)", "",
         K::Choice, 0, 0, false, false, "", false, namesOf<OutputEncoding>(),
         "the scene's: built-in scenes linear, model files srgb",
         ENUM(shading.output, OutputEncoding)});
    add({"debug-view", "Output",
         "tint by cascade, show one light's maps (--light-only's, else the first shadowed "
         "light's), or draw the shadow cameras' volumes",
         "", K::Choice, 0, 0, false, false, "", false, namesOf<DebugView>(), "",
         ENUM(debugView, DebugView)});
}

// Whether and how maps are made.
void addShadowMaps(std::vector<OptionSpec>& s) {
    using K = OptionKind;
    auto add = [&](OptionSpec spec) { s.push_back(std::move(spec)); };
    add({"shadows",
         "Shadow maps",
         "off disables every shadow test, lighting unchanged",
         "",
         K::Switch,
         0,
         1,
         false,
         false,
         "",
         false,
         {},
         "",
         NUMBER(shadow.enabled, bool)});
    add({"map-size",
         "Shadow maps",
         "shadow map texels per side for every light",
         "",
         K::Integer,
         64,
         8192,
         false,
         true,
         "",
         false,
         {},
         "0: each light's own",
         NUMBER(shadow.mapSize, int)});
    add({"depth-format", "Shadow maps",
         "shadow map storage (point-light cubes use depth32f for colour formats)", "", K::Choice, 0,
         0, false, false, "", false, namesOf<DepthFormat>(), "",
         ENUM(shadow.depthFormat, DepthFormat)});
    add({"fit-to", "Shadow maps",
         "what fitted lights' maps cover: the points a coarse depth pre-pass of the view sees (a "
         "point light whose points fit a cube face's angle gets one frustum over them), or the "
         "visible receivers' boxes",
         "", K::Choice, 0, 0, false, false, "", false, namesOf<FitTo>(), "",
         ENUM(shadow.fitTo, FitTo)});
    add({"outside", "Shadow maps",
         "lookups outside a light's map: lit, or clamp (shows the textbooks' error)", "", K::Choice,
         0, 0, false, false, "", false, namesOf<OutsidePolicy>(), "",
         ENUM(shadow.outside, OutsidePolicy)});
    add({"blend-shadows", "Shadow maps",
         "shadows of alpha-blended materials: full, none, or covering alpha of the map's texels",
         "", K::Choice, 0, 0, false, false, "", false, namesOf<BlendShadows>(), "",
         ENUM(shadow.blendShadows, BlendShadows)});
}

// What keeps lit surfaces from shadowing themselves.
void addTolerances(std::vector<OptionSpec>& s) {
    using K = OptionKind;
    auto add = [&](OptionSpec spec) { s.push_back(std::move(spec)); };
    add({"bias-constant",
         "Tolerances",
         "tolerance added to the stored depth",
         "stored-depth units",
         K::Real,
         0,
         1,
         true,
         false,
         "",
         false,
         {},
         "",
         NUMBER(shadow.biasConstant, float)});
    add({"bias-depth-aware",
         "Tolerances",
         "plus this many steps of the stored depth's spacing for the map's format, growing with "
         "depth for float storage",
         "steps",
         K::Real,
         0,
         1000,
         false,
         false,
         "",
         false,
         {},
         "",
         NUMBER(shadow.biasDepthAware, float)});
    add({"bias-slope",
         "Tolerances",
         "polygon-offset factor in the depth pass",
         "",
         K::Real,
         0,
         100,
         false,
         false,
         "",
         false,
         {},
         "",
         NUMBER(shadow.biasSlope, float)});
    add({"bias-units",
         "Tolerances",
         "polygon-offset units in the depth pass",
         "",
         K::Real,
         0,
         1e6,
         false,
         false,
         "",
         false,
         {},
         "",
         NUMBER(shadow.biasUnits, float)});
    add({"receiver-plane",
         "Tolerances",
         "compare each tap against the receiver's plane at the texel it reads (off: one "
         "reference depth per lookup)",
         "",
         K::Switch,
         0,
         1,
         false,
         false,
         "",
         false,
         {},
         "",
         NUMBER(shadow.receiverPlane, bool)});
    add({"normal-offset",
         "Tolerances",
         "lookup shift along the normal, in texels x the filter's reach x sin(light angle)",
         "texels",
         K::Real,
         0,
         100,
         false,
         false,
         "",
         false,
         {},
         "",
         NUMBER(shadow.normalOffset, float)});
    add({"cull", "Tolerances",
         "faces culled in the depth pass (only closed meshes of single-sided materials)", "",
         K::Choice, 0, 0, false, false, "", false, namesOf<CullMode>(), "",
         ENUM(shadow.cull, CullMode)});
}

// How a lookup reads the map.
void addFiltering(std::vector<OptionSpec>& s) {
    using K = OptionKind;
    auto add = [&](OptionSpec spec) { s.push_back(std::move(spec)); };
    add({"filter", "Filtering", "shadow map lookup filter", "", K::Choice, 0, 0, false, false, "",
         false, namesOf<ShadowFilter>(), "", ENUM(shadow.filter, ShadowFilter)});
    add({"pcf-size",
         "Filtering",
         "kernel width for pcf and poisson",
         "texels",
         K::Integer,
         1,
         9,
         false,
         false,
         "",
         true,
         {},
         "",
         NUMBER(shadow.pcfSize, int)});
    add({"light-radius",
         "Filtering",
         "pcss: emitter radius of spot, point and area lights",
         "world units",
         K::Real,
         0,
         1e4,
         false,
         false,
         "",
         false,
         {},
         "",
         NUMBER(shadow.lightRadius, float)});
    add({"light-angle",
         "Filtering",
         "pcss: angular radius of directional lights",
         "degrees",
         K::Real,
         0,
         20,
         false,
         false,
         "",
         false,
         {},
         "",
         NUMBER(shadow.lightAngle, float)});
    add({"map-filter", "Filtering",
         "filtering of the stored depth before a comparison by hand (colour formats, and "
         "--filter none)",
         "", K::Choice, 0, 0, false, false, "", false, namesOf<MapFilter>(), "",
         ENUM(shadow.mapFilter, MapFilter)});
}

// Directional lights split along the view.
void addCascades(std::vector<OptionSpec>& s) {
    using K = OptionKind;
    auto add = [&](OptionSpec spec) { s.push_back(std::move(spec)); };
    add({"cascades",
         "Cascades",
         "fitted directional lights: cascaded maps along the view; auto: one per factor of 8 "
         "in the depth the view sees",
         "",
         K::Integer,
         1,
         4,
         false,
         true,
         "auto",
         false,
         {},
         "",
         NUMBER(shadow.cascades, int)});
    add({"cascade-lambda",
         "Cascades",
         "cascade splits: 0 uniform .. 1 logarithmic",
         "",
         K::Real,
         0,
         1,
         false,
         false,
         "",
         false,
         {},
         "",
         NUMBER(shadow.cascadeLambda, float)});
    add({"cascade-blend",
         "Cascades",
         "fraction of each cascade blended into the next",
         "",
         K::Real,
         0,
         0.5,
         false,
         false,
         "",
         false,
         {},
         "",
         NUMBER(shadow.cascadeBlend, float)});
}

// What a shadow does to the colour.
void addShading(std::vector<OptionSpec>& s) {
    using K = OptionKind;
    auto add = [&](OptionSpec spec) { s.push_back(std::move(spec)); };
    add({"shadowed", "Shading",
         "a shadowed fragment keeps ambient only, or is multiplied by --shadow-factor", "",
         K::Choice, 0, 0, false, false, "", false, namesOf<ShadowedRule>(), "the scene's; ambient",
         ENUM(shading.shadowedRule, ShadowedRule)});
    add({"shadow-factor",
         "Shading",
         "colour multiplier in shadow for --shadowed factor",
         "",
         K::Real,
         0,
         1,
         false,
         false,
         "",
         false,
         {},
         "",
         NUMBER(shading.shadowFactor, float)});
}

// When options have an effect: those of the shadow technique only with shadows on, and a
// few only with the filter, rule or cascades they tune.
void addConditions(std::vector<OptionSpec>& s) {
    struct Condition {
        const char* name;
        bool (*matters)(const RenderOptions&);
        const char* onlyWith;
    };
    static const Condition kConditions[] = {
        {"light-radius",
         [](const RenderOptions& o) { return o.shadow.filter == ShadowFilter::Pcss; },
         "--filter pcss"},
        {"light-angle",
         [](const RenderOptions& o) { return o.shadow.filter == ShadowFilter::Pcss; },
         "--filter pcss"},
        {"pcf-size",
         [](const RenderOptions& o) {
             return o.shadow.filter == ShadowFilter::Pcf ||
                    o.shadow.filter == ShadowFilter::Poisson;
         },
         "--filter pcf or poisson"},
        {"map-filter",
         [](const RenderOptions& o) {
             return o.shadow.filter == ShadowFilter::None || isColourFormat(o.shadow.depthFormat);
         },
         "--filter none or a colour --depth-format (r8, rgba8-packed-*)"},
        {"cascade-lambda", [](const RenderOptions& o) { return o.shadow.cascades != 1; },
         "more than one cascade (--cascades auto or 2..4)"},
        {"cascade-blend", [](const RenderOptions& o) { return o.shadow.cascades != 1; },
         "more than one cascade (--cascades auto or 2..4)"},
        {"shadow-factor",
         [](const RenderOptions& o) { return o.shading.shadowedRule == ShadowedRule::Factor; },
         "--shadowed factor"},
    };
    for (OptionSpec& spec : s) {
        const std::string group = spec.group;
        const bool technique = group == "Tolerances" || group == "Filtering" ||
                               group == "Cascades" ||
                               (group == "Shadow maps" && std::string(spec.name) != "shadows");
        for (const Condition& c : kConditions) {
            if (std::string(spec.name) == c.name) {
                spec.matters = c.matters;
                spec.onlyWith = c.onlyWith;
            }
        }
        if (technique && !spec.matters) {
            spec.matters = [](const RenderOptions& o) { return o.shadow.enabled; };
            spec.onlyWith = "--shadows on";
        }
    }
}

std::vector<OptionSpec> makeSchema() {
    std::vector<OptionSpec> s;
    addOutput(s);
    addShadowMaps(s);
    addTolerances(s);
    addFiltering(s);
    addCascades(s);
    addShading(s);
    addConditions(s);
    return s;
}

#undef NUMBER
#undef ENUM

}  // namespace

const std::vector<OptionSpec>& optionSchema() {
    static const std::vector<OptionSpec> schema = makeSchema();
    return schema;
}

const OptionSpec* findOption(const std::string& name) {
    for (const OptionSpec& spec : optionSchema()) {
        if (name == spec.name) return &spec;
    }
    return nullptr;
}

}  // namespace gnomon
