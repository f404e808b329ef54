#include <regex>

#include "RenderOptionsCli.h"
#include "gnomon/Error.h"

namespace gnomon::cli {
namespace {

const RenderOptions kDefaults;

template <typename T>
std::string str(T v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

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
    const ShadowOptions& s = kDefaults.shadow;
    a.add_option("--preset", preset,
                 "default|textbook: where options start; textbook = the textbook's own numbers "
                 "for the scene (constant tolerance, its depth storage; acne included); flags "
                 "given override it (default: default)");
    a.add_option("--size", size,
                 "output size WIDTHxHEIGHT (default: the scene's, usually 512x512)");
    a.add_option("--time", time,
                 "seconds of animation to pose (default 0: book triangle unrotated)");
    a.add_option("--light-only", lightOnly,
                 "render with only light N on (default: scene's switches)");
    a.add_option("--shadows", shadows,
                 "on|off: off disables every shadow test, lighting unchanged (default on)");
    a.add_option(
        "--outside", outside,
        "lit|clamp: lookups outside a light's map (default lit; clamp shows the textbooks' error)");
    a.add_option(
        "--map-size", mapSize,
        "shadow map texels per side for every light, 64..8192 (default 0: each light's own)");
    a.add_option(
        "--bias-constant", biasConstant,
        "tolerance added to the stored depth, [0,1) (default " + str(s.biasConstant) + ")");
    a.add_option("--bias-depth-aware", biasDepthAware,
                 "plus this many steps of the stored depth's spacing for the map's format, "
                 "growing with depth for float storage (default " +
                     str(s.biasDepthAware) + ")");
    a.add_option("--bias-slope", biasSlope,
                 "polygon-offset factor in the depth pass (default " + str(s.biasSlope) + ")");
    a.add_option("--bias-units", biasUnits,
                 "polygon-offset units in the depth pass (default " + str(s.biasUnits) + ")");
    a.add_option("--receiver-plane", receiverPlane,
                 "on|off: compare each tap against the receiver's plane at the texel it reads "
                 "(default on; off: one reference depth per lookup)");
    a.add_option("--normal-offset", normalOffset,
                 "lookup shift along the normal, in texels x the filter's reach x sin(light angle) "
                 "(default " +
                     str(s.normalOffset) + ")");
    a.add_option("--cull", cull,
                 "back|front|none: faces culled in the depth pass (default back; only closed "
                 "meshes of single-sided materials)");
    a.add_option("--filter", filter,
                 "none|hw2x2|pcf|poisson|pcss: shadow map lookup filter (default pcf)");
    a.add_option(
        "--pcf-size", pcfSize,
        "kernel width in texels for pcf and poisson, odd 1..9 (default " + str(s.pcfSize) + ")");
    a.add_option("--light-radius", lightRadius,
                 "pcss: emitter radius of spot, point and area lights, world units (default " +
                     str(s.lightRadius) + ")");
    a.add_option("--light-angle", lightAngle,
                 "pcss: angular radius of directional lights, degrees 0..20 (default " +
                     str(s.lightAngle) + ")");
    a.add_option("--cascades", cascades,
                 "fitted directional lights: auto|1..4 cascaded maps along the view; auto: one "
                 "per factor of 8 in the depth the view sees (default auto)");
    a.add_option("--fit-to", fitTo,
                 "view-depth|boxes: what fitted lights' maps cover: the points a coarse depth "
                 "pre-pass of the view sees (a point light whose points fit a cube face's "
                 "angle gets one frustum over them), or the visible receivers' boxes (default " +
                     std::string(toString(s.fitTo)) + ")");
    a.add_option(
        "--cascade-lambda", cascadeLambda,
        "cascade splits: 0 uniform .. 1 logarithmic (default " + str(s.cascadeLambda) + ")");
    a.add_option("--cascade-blend", cascadeBlend,
                 "fraction of each cascade blended into the next, 0..0.5 (default " +
                     str(s.cascadeBlend) + ")");
    a.add_option("--debug-view", debugView,
                 "none|cascades|shadow-map|light-frusta: tint by cascade, show one light's maps "
                 "(--light-only's, else the first shadowed light's), or draw the shadow cameras' "
                 "volumes (default none)");
    a.add_option("--depth-format", depthFormat,
                 "r8|rgba8-packed-256|rgba8-packed-255|depth16|depth24|depth32f: shadow map "
                 "storage (default depth32f; point-light cubes use depth32f for colour formats)");
    a.add_option("--map-filter", mapFilter,
                 "nearest|linear: filtering of the stored depth before a comparison by hand "
                 "(colour formats, and --filter none) (default nearest)");
    a.add_option("--blend-shadows", blendShadows,
                 "opaque|none|dithered: shadows of alpha-blended materials: full, none, or "
                 "covering alpha of the map's texels (default dithered)");
    a.add_flag("--ground", ground,
               "add a grey ground under the scene (receives shadows, casts none), for models "
               "without a floor");
    a.add_option("--output-encoding", outputEncoding,
                 "linear|srgb: image colours as computed (the textbooks) or sRGB-encoded for "
                 "display (glTF viewers) (default: scene's; built-in scenes linear, model files "
                 "srgb)");
    a.add_option("--shadowed", shadowed,
                 "ambient|factor: a shadowed fragment keeps ambient only, or is multiplied by "
                 "--shadow-factor (default: scene's; ambient)");
    a.add_option("--shadow-factor", shadowFactor,
                 "colour multiplier in shadow for --shadowed factor, 0..1 (default 0.7)");
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
    auto given = [&](const char* flag) { return app->count(flag) > 0; };
    if (given("--size")) {
        static const std::regex kSize(R"((\d{1,5})x(\d{1,5}))");
        std::smatch m;
        if (!std::regex_match(size, m, kSize)) {
            bad("--size", "expected WIDTHxHEIGHT such as 512x512, got '" + size + "'");
        }
        o.width = std::stoi(m[1].str());
        o.height = std::stoi(m[2].str());
    }
    if (given("--time")) o.time = time;
    if (given("--light-only")) o.lightOnly = lightOnly;
    if (given("--shadows")) {
        if (shadows != "on" && shadows != "off")
            bad("--shadows", "expected on or off, got '" + shadows + "'");
        o.shadow.enabled = shadows == "on";
    }
    if (given("--outside"))
        o.shadow.outside = parseEnum("--outside", outside, parseOutsidePolicy, "lit, clamp");
    if (given("--map-size")) o.shadow.mapSize = mapSize;
    if (given("--bias-constant")) o.shadow.biasConstant = biasConstant;
    if (given("--bias-depth-aware")) o.shadow.biasDepthAware = biasDepthAware;
    if (given("--bias-slope")) o.shadow.biasSlope = biasSlope;
    if (given("--bias-units")) o.shadow.biasUnits = biasUnits;
    if (given("--receiver-plane")) {
        if (receiverPlane != "on" && receiverPlane != "off")
            bad("--receiver-plane", "expected on or off, got '" + receiverPlane + "'");
        o.shadow.receiverPlane = receiverPlane == "on";
    }
    if (given("--normal-offset")) o.shadow.normalOffset = normalOffset;
    if (given("--cull"))
        o.shadow.cull = parseEnum("--cull", cull, parseCullMode, "back, front, none");
    if (given("--filter"))
        o.shadow.filter =
            parseEnum("--filter", filter, parseShadowFilter, "none, hw2x2, pcf, poisson, pcss");
    if (given("--pcf-size")) o.shadow.pcfSize = pcfSize;
    if (given("--light-radius")) o.shadow.lightRadius = lightRadius;
    if (given("--light-angle")) o.shadow.lightAngle = lightAngle;
    if (given("--cascades")) {
        if (cascades == "auto") {
            o.shadow.cascades = 0;
        } else if (cascades.size() == 1 && cascades[0] >= '1' && cascades[0] <= '4') {
            o.shadow.cascades = cascades[0] - '0';
        } else {
            bad("--cascades", "expected auto or 1..4, got '" + cascades + "'");
        }
    }
    if (given("--fit-to"))
        o.shadow.fitTo = parseEnum("--fit-to", fitTo, parseFitTo, "view-depth, boxes");
    if (given("--cascade-lambda")) o.shadow.cascadeLambda = cascadeLambda;
    if (given("--cascade-blend")) o.shadow.cascadeBlend = cascadeBlend;
    if (given("--debug-view")) {
        o.debugView = parseEnum("--debug-view", debugView, parseDebugView,
                                "none, cascades, shadow-map, light-frusta");
    }
    if (given("--depth-format")) {
        o.shadow.depthFormat =
            parseEnum("--depth-format", depthFormat, parseDepthFormat,
                      "r8, rgba8-packed-256, rgba8-packed-255, depth16, depth24, depth32f");
    }
    if (given("--map-filter")) {
        o.shadow.mapFilter =
            parseEnum("--map-filter", mapFilter, parseMapFilter, "nearest, linear");
    }
    if (given("--blend-shadows")) {
        o.shadow.blendShadows =
            parseEnum("--blend-shadows", blendShadows, parseBlendShadows, "opaque, none, dithered");
    }
    if (given("--output-encoding")) {
        o.shading.output =
            parseEnum("--output-encoding", outputEncoding, parseOutputEncoding, "linear, srgb");
    }
    if (given("--shadowed"))
        o.shading.shadowedRule =
            parseEnum("--shadowed", shadowed, parseShadowedRule, "ambient, factor");
    if (given("--shadow-factor")) o.shading.shadowFactor = shadowFactor;
    if (auto problems = o.validate(); !problems.empty()) {
        std::string all;
        for (const auto& p : problems)
            all += (all.empty() ? "" : "; ") + p;
        throw Error(ErrorKind::InvalidInput, all);
    }
}

}  // namespace gnomon::cli
