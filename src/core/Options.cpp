// Option names as the CLI spells them, and validation with one sentence per problem.
#include <cmath>
#include <string>

#include "gnomon/OptionSchema.h"
#include "gnomon/Options.h"

namespace gnomon {
namespace {

template <typename E, size_t N>
std::optional<E> lookup(const std::string& s, const std::pair<const char*, E> (&table)[N]) {
    for (const auto& [name, value] : table) {
        if (s == name) return value;
    }
    return std::nullopt;
}

template <typename E, size_t N>
const char* nameOf(E v, const std::pair<const char*, E> (&table)[N]) {
    for (const auto& [name, value] : table) {
        if (v == value) return name;
    }
    return "?";
}

const std::pair<const char*, ShadowedRule> kRules[] = {{"ambient", ShadowedRule::AmbientOnly},
                                                       {"factor", ShadowedRule::Factor}};
const std::pair<const char*, OutsidePolicy> kOutside[] = {{"lit", OutsidePolicy::Lit},
                                                          {"clamp", OutsidePolicy::Clamp}};
const std::pair<const char*, CullMode> kCull[] = {
    {"back", CullMode::Back}, {"front", CullMode::Front}, {"none", CullMode::None}};
const std::pair<const char*, ShadowFilter> kFilters[] = {
    {"none", ShadowFilter::None},   {"hw2x2", ShadowFilter::Hw2x2},
    {"pcf", ShadowFilter::Pcf},     {"poisson", ShadowFilter::Poisson},
    {"pcss", ShadowFilter::Pcss},   {"evsm2", ShadowFilter::Evsm2},
    {"evsm4", ShadowFilter::Evsm4}, {"msm", ShadowFilter::Msm}};

const std::pair<const char*, DepthFormat> kFormats[] = {
    {"r8", DepthFormat::R8},
    {"rgba8-packed-256", DepthFormat::Rgba8Packed256},
    {"rgba8-packed-255", DepthFormat::Rgba8Packed255},
    {"depth16", DepthFormat::Depth16},
    {"depth24", DepthFormat::Depth24},
    {"depth32f", DepthFormat::Depth32F}};
const std::pair<const char*, MapFilter> kMapFilters[] = {{"nearest", MapFilter::Nearest},
                                                         {"linear", MapFilter::Linear}};

const std::pair<const char*, Preset> kPresets[] = {{"default", Preset::Default},
                                                   {"textbook", Preset::Textbook}};

const std::pair<const char*, DebugView> kDebugViews[] = {{"none", DebugView::None},
                                                         {"cascades", DebugView::Cascades},
                                                         {"shadow-map", DebugView::ShadowMap},
                                                         {"light-frusta", DebugView::LightFrusta},
                                                         {"rays", DebugView::Rays}};

const std::pair<const char*, BlendShadows> kBlendShadows[] = {{"opaque", BlendShadows::Opaque},
                                                              {"none", BlendShadows::None},
                                                              {"dithered", BlendShadows::Dithered},
                                                              {"coloured", BlendShadows::Coloured}};

const std::pair<const char*, ShadowRayMode> kShadowRays[] = {
    {"off", ShadowRayMode::Off},
    {"all", ShadowRayMode::All},
    {"uncertain", ShadowRayMode::Uncertain}};

const std::pair<const char*, FitTo> kFitTo[] = {{"view-depth", FitTo::ViewDepth},
                                                {"boxes", FitTo::Boxes}};

const std::pair<const char*, PointMaps> kPointMaps[] = {{"faces", PointMaps::Faces},
                                                        {"cube", PointMaps::Cube}};

const std::pair<const char*, OutputEncoding> kOutputs[] = {{"linear", OutputEncoding::Linear},
                                                           {"srgb", OutputEncoding::Srgb}};

const std::pair<const char*, LightTiles> kLightTiles[] = {{"auto", LightTiles::Auto},
                                                          {"lists", LightTiles::Lists},
                                                          {"draws", LightTiles::Draws},
                                                          {"off", LightTiles::Off}};

}  // namespace

const char* toString(ShadowedRule v) {
    return nameOf(v, kRules);
}
const char* toString(OutsidePolicy v) {
    return nameOf(v, kOutside);
}
const char* toString(CullMode v) {
    return nameOf(v, kCull);
}
const char* toString(ShadowFilter v) {
    return nameOf(v, kFilters);
}
std::optional<ShadowedRule> parseShadowedRule(const std::string& s) {
    return lookup(s, kRules);
}
std::optional<OutsidePolicy> parseOutsidePolicy(const std::string& s) {
    return lookup(s, kOutside);
}
std::optional<CullMode> parseCullMode(const std::string& s) {
    return lookup(s, kCull);
}
std::optional<ShadowFilter> parseShadowFilter(const std::string& s) {
    return lookup(s, kFilters);
}
const char* toString(DepthFormat v) {
    return nameOf(v, kFormats);
}
const char* toString(MapFilter v) {
    return nameOf(v, kMapFilters);
}
std::optional<DepthFormat> parseDepthFormat(const std::string& s) {
    return lookup(s, kFormats);
}
std::optional<MapFilter> parseMapFilter(const std::string& s) {
    return lookup(s, kMapFilters);
}
const char* toString(Preset v) {
    return nameOf(v, kPresets);
}
std::optional<Preset> parsePreset(const std::string& s) {
    return lookup(s, kPresets);
}
const char* toString(DebugView v) {
    return nameOf(v, kDebugViews);
}
std::optional<DebugView> parseDebugView(const std::string& s) {
    return lookup(s, kDebugViews);
}
const char* toString(BlendShadows v) {
    return nameOf(v, kBlendShadows);
}
std::optional<BlendShadows> parseBlendShadows(const std::string& s) {
    return lookup(s, kBlendShadows);
}
const char* toString(ShadowRayMode v) {
    return nameOf(v, kShadowRays);
}
std::optional<ShadowRayMode> parseShadowRayMode(const std::string& s) {
    return lookup(s, kShadowRays);
}
const char* toString(FitTo v) {
    return nameOf(v, kFitTo);
}
std::optional<FitTo> parseFitTo(const std::string& s) {
    return lookup(s, kFitTo);
}
const char* toString(PointMaps v) {
    return nameOf(v, kPointMaps);
}
std::optional<PointMaps> parsePointMaps(const std::string& s) {
    return lookup(s, kPointMaps);
}
const char* toString(OutputEncoding v) {
    return nameOf(v, kOutputs);
}
const char* toString(LightTiles v) {
    return nameOf(v, kLightTiles);
}
std::optional<OutputEncoding> parseOutputEncoding(const std::string& s) {
    return lookup(s, kOutputs);
}
bool isColourFormat(DepthFormat v) {
    return v == DepthFormat::R8 || v == DepthFormat::Rgba8Packed256 ||
           v == DepthFormat::Rgba8Packed255;
}

std::vector<std::string> RenderOptions::validate() const {
    // Every range is the schema's (include/gnomon/OptionSchema.h).
    std::vector<std::string> problems;
    for (const OptionSpec& spec : optionSchema()) {
        if (std::string p = checkOption(spec, *this); !p.empty()) problems.push_back(std::move(p));
    }
    // Moments are made from a native depth map; an 8-bit encoded one holds too little.
    if (isMomentFilter(shadow.filter) && isColourFormat(shadow.depthFormat)) {
        problems.push_back(std::string("filter ") + toString(shadow.filter) +
                           " needs a native --depth-format (depth16, depth24 or depth32f), not " +
                           toString(shadow.depthFormat));
    }
    return problems;
}

}  // namespace gnomon
