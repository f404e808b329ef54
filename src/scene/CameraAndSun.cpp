// The camera and sun edits of the CLI's flags and the web page's address (gnomon/Scene.h):
// one parser and one set of messages for both.
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "gnomon/Error.h"
#include "gnomon/Scene.h"

namespace gnomon {
namespace {

[[noreturn]] void bad(const std::string& flag, const std::string& message) {
    throw Error(ErrorKind::InvalidInput, flag + ": " + message);
}

std::optional<glm::vec3> vec3Of(const std::string& text) {
    const auto v = parseNumberList(text, 3);
    if (!v) return std::nullopt;
    return glm::vec3((*v)[0], (*v)[1], (*v)[2]);
}

}  // namespace

std::optional<std::vector<float>> parseNumberList(const std::string& text, std::size_t count) {
    std::vector<float> out;
    std::size_t at = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t end = i + 1 < count ? text.find(',', at) : text.size();
        if (end == std::string::npos) return std::nullopt;
        const std::string part = text.substr(at, end - at);
        char* stop = nullptr;
        const float v = std::strtof(part.c_str(), &stop);
        if (part.empty() || stop != part.c_str() + part.size() || !std::isfinite(v))
            return std::nullopt;
        out.push_back(v);
        at = end + 1;
    }
    return out;
}

void placeCameraAndSun(Scene& scene, const CameraAndSun& edits) {
    Camera& c = scene.camera;
    if (edits.eye) {
        const auto v = vec3Of(*edits.eye);
        if (!v) bad("--camera-eye", "expected X,Y,Z such as 4,3,6, got '" + *edits.eye + "'");
        c.eye = *v;
    }
    if (edits.target) {
        const auto v = vec3Of(*edits.target);
        if (!v) bad("--camera-target", "expected X,Y,Z such as 0,1,0, got '" + *edits.target + "'");
        c.centre = *v;
    }
    if (edits.fovDegrees) {
        const float fov = *edits.fovDegrees;
        if (!(fov >= 1.0f && fov <= 179.0f)) {
            char typed[32];  // as typed, not std::to_string's six decimals
            std::snprintf(typed, sizeof typed, "%g", double(fov));
            bad("--camera-fov", std::string("must be in 1..179 degrees, got ") + typed);
        }
        c.fovyDegrees = fov;
    }
    if (edits.eye || edits.target) {
        if (!(glm::length(c.centre - c.eye) > 0.0f))
            bad("--camera-eye", "the eye and the target are the same point");
        // A camera placed by flags keeps no near and far planes from the one it replaced (a
        // framing camera's, sized for a view from outside, would cut away a model seen from
        // within).
        fitCameraDepth(scene, c);
    }
    // Eye and target given, the framing camera a loader added is replaced: its warning would
    // only mislead.
    if (edits.eye && edits.target) {
        std::erase_if(scene.warnings, [](const std::string& w) {
            return w.ends_with("no camera: one framing the scene was added");
        });
    }
    if (edits.sun) {
        const auto v = parseNumberList(*edits.sun, 2);
        if (!v || !((*v)[1] > 0.0f && (*v)[1] <= 90.0f))
            bad("--sun", "expected AZIMUTH,ELEVATION in degrees, elevation in (0, 90], got '" +
                             *edits.sun + "'");
        Light l;
        l.name = "sun (--sun)";
        l.type = LightType::Directional;
        l.direction = sunDirection((*v)[0], (*v)[1]);
        scene.lights = {l};
        // The model's added sun is gone with the rest: its warning would only mislead.
        std::erase_if(scene.warnings,
                      [](const std::string& w) { return w.ends_with(kDefaultSunWarning); });
    }
}

}  // namespace gnomon
