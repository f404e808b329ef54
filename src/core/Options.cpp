// Option names as the CLI spells them, and validation with one sentence per problem.
#include <cmath>
#include <string>

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
const std::pair<const char*, ShadowFilter> kFilters[] = {{"none", ShadowFilter::None},
                                                         {"hw2x2", ShadowFilter::Hw2x2},
                                                         {"pcf", ShadowFilter::Pcf},
                                                         {"poisson", ShadowFilter::Poisson},
                                                         {"pcss", ShadowFilter::Pcss}};

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
                                                         {"light-frusta", DebugView::LightFrusta}};

const std::pair<const char*, BlendShadows> kBlendShadows[] = {{"opaque", BlendShadows::Opaque},
                                                              {"none", BlendShadows::None},
                                                              {"dithered", BlendShadows::Dithered}};

const std::pair<const char*, FitTo> kFitTo[] = {{"view-depth", FitTo::ViewDepth},
                                                {"boxes", FitTo::Boxes}};

const std::pair<const char*, OutputEncoding> kOutputs[] = {{"linear", OutputEncoding::Linear},
                                                           {"srgb", OutputEncoding::Srgb}};

bool finite(float v) {
    return std::isfinite(v);
}

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
const char* toString(FitTo v) {
    return nameOf(v, kFitTo);
}
std::optional<FitTo> parseFitTo(const std::string& s) {
    return lookup(s, kFitTo);
}
const char* toString(OutputEncoding v) {
    return nameOf(v, kOutputs);
}
std::optional<OutputEncoding> parseOutputEncoding(const std::string& s) {
    return lookup(s, kOutputs);
}
bool isColourFormat(DepthFormat v) {
    return v == DepthFormat::R8 || v == DepthFormat::Rgba8Packed256 ||
           v == DepthFormat::Rgba8Packed255;
}

std::vector<std::string> RenderOptions::validate() const {
    std::vector<std::string> problems;
    auto need = [&](bool ok, const std::string& what) {
        if (!ok) problems.push_back(what);
    };
    need(width >= 1 && width <= 16384 && height >= 1 && height <= 16384,
         "size " + std::to_string(width) + "x" + std::to_string(height) +
             " is outside 1x1..16384x16384");
    need(std::isfinite(time), "time must be a finite number of seconds");
    need(lightOnly >= -1, "light-only must be a light index >= 0 (or -1 for all)");
    const ShadowOptions& s = shadow;
    need(finite(s.biasConstant) && s.biasConstant >= 0.0f && s.biasConstant < 1.0f,
         "bias-constant must be in [0, 1) (stored-depth units), got " +
             std::to_string(s.biasConstant));
    need(finite(s.biasDepthAware) && s.biasDepthAware >= 0.0f && s.biasDepthAware <= 1000.0f,
         "bias-depth-aware must be in [0, 1000] steps, got " + std::to_string(s.biasDepthAware));
    need(s.cascades >= 0 && s.cascades <= 4,
         "cascades must be auto (0) or in 1..4, got " + std::to_string(s.cascades));
    need(finite(s.cascadeLambda) && s.cascadeLambda >= 0.0f && s.cascadeLambda <= 1.0f,
         "cascade-lambda must be in [0, 1], got " + std::to_string(s.cascadeLambda));
    need(finite(s.cascadeBlend) && s.cascadeBlend >= 0.0f && s.cascadeBlend <= 0.5f,
         "cascade-blend must be in [0, 0.5], got " + std::to_string(s.cascadeBlend));
    need(finite(s.biasSlope) && s.biasSlope >= 0.0f && s.biasSlope <= 100.0f,
         "bias-slope must be in [0, 100], got " + std::to_string(s.biasSlope));
    need(finite(s.biasUnits) && s.biasUnits >= 0.0f && s.biasUnits <= 1.0e6f,
         "bias-units must be in [0, 1e6], got " + std::to_string(s.biasUnits));
    need(finite(s.normalOffset) && s.normalOffset >= 0.0f && s.normalOffset <= 100.0f,
         "normal-offset must be in [0, 100] texels, got " + std::to_string(s.normalOffset));
    need(s.pcfSize >= 1 && s.pcfSize <= 9 && s.pcfSize % 2 == 1,
         "pcf-size must be odd and in 1..9, got " + std::to_string(s.pcfSize));
    need(s.mapSize == 0 || (s.mapSize >= 64 && s.mapSize <= 8192),
         "map-size must be 0 (each light's own) or in 64..8192, got " + std::to_string(s.mapSize));
    need(finite(s.lightRadius) && s.lightRadius >= 0.0f && s.lightRadius <= 1.0e4f,
         "light-radius must be in [0, 1e4] world units, got " + std::to_string(s.lightRadius));
    need(finite(s.lightAngle) && s.lightAngle >= 0.0f && s.lightAngle <= 20.0f,
         "light-angle must be in [0, 20] degrees, got " + std::to_string(s.lightAngle));
    need(finite(shading.shadowFactor) && shading.shadowFactor >= 0.0f &&
             shading.shadowFactor <= 1.0f,
         "shadow-factor must be in [0, 1], got " + std::to_string(shading.shadowFactor));
    return problems;
}

}  // namespace gnomon
