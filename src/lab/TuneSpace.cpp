// What gnomon tune searches: the settings and their values, a point of the search as
// settings, and the views moved half a pixel for the check of the best.
#include <algorithm>
#include <cmath>

#include "gnomon/Error.h"
#include "lab/TuneDetail.h"
#include "scene/CameraMath.h"
#include "scene/SceneUtil.h"

namespace gnomon::detail {

namespace {

bool hasFittedSun(const Scene& s) {
    for (const Light& l : s.lights) {
        if (l.type == LightType::Directional && l.castsShadows &&
            l.shadowCamera.policy == ShadowCameraPolicy::Fit) {
            return true;
        }
    }
    return false;
}

const std::vector<std::string> kMapSizes = {"512", "1024", "2048", "4096"};

// Triangles the shadow casters draw at full detail. From about this many, a shadow pass on
// llvmpipe costs more in triangles than in texels (docs/results/performance.md, "Triangles"),
// so stand-in casters (--caster-detail) free time a larger map can use; below it they save
// little and only add trials.
constexpr std::size_t kStandInTriangles = 20000;

// Lights whose map sizes are searched one by one: every shadowed light that is on (the
// scene's switches, or --light-only's) when there are two to kMaxSizedApart of them and the
// options leave each its own size (map-size 0) with shadows on, so a scene's sun can take the
// texels its spot does not need. Otherwise none: one map size is searched for all (with many
// lights, three more trials per light and sweep would swamp the search; mixed-lights has 16).
constexpr std::size_t kMaxSizedApart = 8;
std::vector<int> lightsSizedApart(const Scene& scene, const RenderOptions& o) {
    std::vector<int> lights;
    if (o.shadow.mapSize != 0 || !o.shadow.enabled) return lights;
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        if (lightIsOn(scene, o, i) && scene.lights[i].castsShadows) lights.push_back(int(i));
    if (lights.size() < 2 || lights.size() > kMaxSizedApart) lights.clear();
    return lights;
}

}  // namespace

Space searchSpace(const Scene& scene, const RenderOptions& o, search::Point& start) {
    Space result;
    result.sizedLights = lightsSizedApart(scene, o);
    for (const Light& l : scene.lights)
        result.ownSizes.push_back(shadowMapSizeOf(l));
    std::vector<search::Parameter>& space = result.parameters;
    // Each option by where it lives in RenderOptions (optionAt), so a wrong one fails to
    // compile; the values as the CLI spells them.
    std::vector<const OptionSpec*>& specs = result.specs;
    auto add = [&](const void* field, std::vector<std::string> values) {
        specs.push_back(&optionAt(o, field));
        space.push_back({specs.back()->name, std::move(values)});
    };
    const ShadowOptions& s = o.shadow;
    add(&s.filter, {"none", "pcf", "poisson", "pcss"});
    add(&s.pcfSize, {"1", "3", "5", "7"});
    if (result.sizedLights.empty()) add(&s.mapSize, kMapSizes);
    add(&s.receiverPlane, {"on", "off"});
    add(&s.normalOffset, {"0", "0.5", "1", "2"});
    add(&s.biasDepthAware, {"0.5", "1", "2", "4"});
    add(&s.biasSlope, {"0", "0.7", "1.5", "3"});
    add(&s.biasConstant, {"0", "0.00005", "0.0002"});
    if (hasFittedSun(scene)) add(&s.cascades, {"auto", "1", "2", "3", "4"});
    if (triangleCount(scene, /*castersOnly=*/true) >= kStandInTriangles)
        add(&s.casterDetail, {"1", "0.3", "0.1"});
    // Rays where the map is unsure: exact edges for a ray's cost per unsure pixel.
    add(&s.shadowRays, {"off", "uncertain"});
    start.clear();
    for (std::size_t i = 0; i < space.size(); ++i) {
        search::Parameter& p = space[i];
        const OptionSpec& spec = *specs[i];
        // The same value however it is spelled ("5e-05" and "0.00005").
        auto at = std::find_if(p.values.begin(), p.values.end(), [&](const std::string& v) {
            RenderOptions candidate = o;
            return !parseOption(spec, v, candidate) && spec.get(candidate) == spec.get(o);
        });
        if (at == p.values.end()) at = p.values.insert(p.values.begin(), formatOption(spec, o));
        start.push_back(int(at - p.values.begin()));
    }
    result.options = space.size();
    for (int light : result.sizedLights) {
        search::Parameter p{"light " + std::to_string(light) + " map-size", kMapSizes};
        const std::string own = std::to_string(result.ownSizes[std::size_t(light)]);
        auto at = std::find(p.values.begin(), p.values.end(), own);
        if (at == p.values.end()) at = p.values.insert(p.values.begin(), own);
        start.push_back(int(at - p.values.begin()));
        space.push_back(std::move(p));
    }
    return result;
}

Setting settingAt(const Space& space, const search::Point& point, const RenderOptions& start,
                  std::string& flags) {
    Setting s{start, space.ownSizes};
    flags.clear();
    auto add = [&](const std::string& text) { flags += (flags.empty() ? "" : " ") + text; };
    for (std::size_t i = 0; i < space.parameters.size(); ++i) {
        const search::Parameter& p = space.parameters[i];
        const std::string& value = p.values[std::size_t(point[i])];
        if (i >= space.options) {
            const auto light = std::size_t(space.sizedLights[i - space.options]);
            s.mapSizes[light] = std::stoi(value);
            if (s.mapSizes[light] != space.ownSizes[light]) add(p.name + " " + value);
            continue;
        }
        const OptionSpec& spec = *space.specs[i];
        if (const auto problem = parseOption(spec, value, s.options))
            throw Error(ErrorKind::InvalidInput, "tune: --" + p.name + ": " + *problem);
        if (spec.get(s.options) != spec.get(start)) add("--" + p.name + " " + value);
    }
    return s;
}

// `c` moved sideways, eye and target alike, by `dx` and `dy` pixels of an image `height`
// pixels high, measured at the target's distance: the picture moves by about that much there.
// Along the picture's own axes, as the renderer builds its view (gnomon::viewFromWorld, with
// its fallback where the camera looks along `up`).
Camera shiftedCamera(const Camera& c, int height, float dx, float dy) {
    const float distance = glm::length(c.centre - c.eye);
    if (!(distance > 0.0f) || height < 1) return c;
    const glm::mat4 worldFromView = glm::inverse(gnomon::viewFromWorld(c));
    const float viewHeight = c.projection == Projection::Perspective
                                 ? 2.0f * distance * std::tan(0.5f * glm::radians(c.fovyDegrees))
                                 : c.top - c.bottom;
    const glm::vec3 move = viewHeight / float(height) *
                           (dx * glm::vec3(worldFromView[0]) + dy * glm::vec3(worldFromView[1]));
    Camera moved = c;
    moved.eye += move;
    moved.centre += move;
    return moved;
}

}  // namespace gnomon::detail
