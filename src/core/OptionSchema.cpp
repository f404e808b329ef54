// The one list of render options (include/gnomon/OptionSchema.h): the frame's options here,
// the shadow technique's in ShadowOptionSchema.cpp; their text forms and the docs' tables
// are in OptionText.cpp.
#include <stdexcept>

#include "core/OptionSchemaEntries.h"

namespace gnomon {
namespace {

using namespace schema;

// The rules for when an option has an effect (OptionSpec::matters), with their words.
bool shadowsOn(const RenderOptions& o) {
    return o.shadow.enabled;
}
// Every debug view but the tints, which need cascades or shadow rays to tint.
bool debugViewShows(const RenderOptions& o) {
    if (o.debugView == DebugView::Rays) return tracesShadowRays(o.shadow);
    return o.debugView != DebugView::Cascades || o.shadow.cascades != 1;
}
bool factorRule(const RenderOptions& o) {
    return o.shading.shadowedRule == ShadowedRule::Factor;
}

// What the frame is and how it is written.
void addOutput(std::vector<OptionSpec>& s) {
    using K = OptionKind;
    using G = OptionGroup;
    auto add = [&](OptionSpec spec) { s.push_back(std::move(spec)); };
    add({.name = "size",
         .group = G::Output,
         .doc = "output size in pixels",
         .kind = K::Size,
         .min = 1,
         .max = 16384,
         .defaultNote = "the scene's, usually 512x512",
         .field = [](const RenderOptions& o) -> const void* { return &o.width; }});
    add({.name = "time",
         .group = G::Output,
         .doc = "seconds of animation to pose (book-triangle turns 40 deg/s)",
         .unit = "seconds",
         .kind = K::Real,
         .min = -kHuge,
         .max = kHuge,
         NUMBER(time, double)});
    add({.name = "light-only",
         .group = G::Output,
         .doc = "render with only light N on (-1: the scene's switches)",
         .kind = K::Integer,
         .min = -1,
         .max = std::numeric_limits<int>::max(),
         NUMBER(lightOnly, int)});
    add({.name = "output-encoding",
         .group = G::Output,
         .doc =
             "image colours as computed (the textbooks) or sRGB-encoded for display (glTF viewers)",
         .kind = K::Choice,
         .choices = namesOf<OutputEncoding>(),
         .defaultNote = "the scene's: built-in scenes linear, model files srgb",
         ENUM(shading.output, OutputEncoding)});
    add({.name = "dither",
         .group = G::Output,
         .doc = "ordered dithering of the 8-bit colours by under half a step, so smooth "
                "gradients do not band (off: plain rounding)",
         .kind = K::Switch,
         .max = 1,
         NUMBER(shading.dither, bool)});
    add({.name = "debug-view",
         .group = G::Output,
         .doc = "tint by cascade, show one light's maps (--light-only's, else the first shadowed "
                "light's), draw the shadow cameras' volumes, or tint where shadow rays decided",
         .kind = K::Choice,
         .choices = namesOf<DebugView>(),
         ENUM(debugView, DebugView),
         .matters = debugViewShows,
         .onlyWith = "--cascades auto or 2..4 (for the cascades tint), --shadow-rays all "
                     "or uncertain (for the rays tint)"});
}

// What a shadow does to the colour.
void addShading(std::vector<OptionSpec>& s) {
    using K = OptionKind;
    using G = OptionGroup;
    auto add = [&](OptionSpec spec) { s.push_back(std::move(spec)); };
    add({.name = "shadowed",
         .group = G::Shading,
         .doc = "a shadowed fragment keeps ambient only, or is multiplied by --shadow-factor",
         .kind = K::Choice,
         .choices = namesOf<ShadowedRule>(),
         .defaultNote = "the scene's; ambient",
         ENUM(shading.shadowedRule, ShadowedRule)});
    add({.name = "shadow-factor",
         .group = G::Shading,
         .doc = "colour multiplier in shadow for --shadowed factor",
         .kind = K::Real,
         .max = 1,
         NUMBER(shading.shadowFactor, float),
         .matters = factorRule,
         .onlyWith = "--shadowed factor"});
    add({.name = "light-tiles",
         .group = G::Shading,
         .doc = "leave out of each screen tile the lights that cannot reach it: lists (one draw, "
                "each pixel reads its tile's lights from a texture), draws (one draw per tile), "
                "auto (a cost model picks either or neither; on: the same), or off (every light "
                "on every pixel); the same image",
         .kind = K::Choice,
         .choices = namesOf<LightTiles>(),
         .formerOn = "auto",
         ENUM(shading.lightTiles, LightTiles)});
    add({.name = "depth-prepass",
         .group = G::Shading,
         .doc = "start the main pass from the view's depth pass where one is drawn for the "
                "view anyway, so each pixel is shaded once (the same image; off: surfaces "
                "later covered by nearer ones are shaded too)",
         .kind = K::Switch,
         .max = 1,
         NUMBER(shading.depthPrepass, bool)});
}

// Options of the technique groups without a rule of their own have an effect only with
// shadows on.
void addShadowsRule(std::vector<OptionSpec>& s) {
    for (OptionSpec& spec : s) {
        if (isTechniqueGroup(spec.group) && !spec.matters && !spec.mattersWithoutShadows) {
            spec.matters = shadowsOn;
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
    addShadowsRule(s);
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

const OptionSpec& optionAt(const RenderOptions& o, const void* field) {
    for (const OptionSpec& spec : optionSchema()) {
        if (spec.field(o) == field) return spec;
    }
    throw std::logic_error("optionAt: no render option holds that member of RenderOptions");
}

const char* toString(OptionGroup g) {
    switch (g) {
        case OptionGroup::Output:
            return "Output";
        case OptionGroup::ShadowMaps:
            return "Shadow maps";
        case OptionGroup::Tolerances:
            return "Tolerances";
        case OptionGroup::Filtering:
            return "Filtering";
        case OptionGroup::Cascades:
            return "Cascades";
        case OptionGroup::Shading:
            return "Shading";
    }
    return "?";
}

bool isTechniqueGroup(OptionGroup g) {
    switch (g) {
        case OptionGroup::ShadowMaps:
        case OptionGroup::Tolerances:
        case OptionGroup::Filtering:
        case OptionGroup::Cascades:
            return true;
        case OptionGroup::Output:
        case OptionGroup::Shading:
            return false;
    }
    return false;
}

}  // namespace gnomon
