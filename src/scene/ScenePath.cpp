#include "gnomon/ScenePath.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "gnomon/Error.h"
#include "scene/SceneFileJson.h"
#include "scene/SceneFileRead.h"

namespace gnomon {

namespace {

constexpr int kMaxFrames = 10000;

void checkFrames(int frames, bool zeroAllowed) {
    if ((frames == 0 && zeroAllowed) || (frames >= 2 && frames <= kMaxFrames)) return;
    throw Error(ErrorKind::InvalidInput, "a path needs 2.." + std::to_string(kMaxFrames) +
                                             " frames, got " + std::to_string(frames));
}

// `v` turned by `degrees` about `axis` (through the origin).
glm::vec3 turned(const glm::vec3& v, const glm::vec3& axis, float degrees) {
    return glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::normalize(axis)) *
                     glm::vec4(v, 0.0f));
}

ScenePath readPathFile(const std::string& path, const Scene& scene, int frames) {
    using namespace scenefile;
    const Reader r(path);
    const Parsed parsed = parseJson(readFileText(path, "path file"), r);
    const Fields root(r, parsed.doc, "", {"gnomon-path", "cameras"});
    if (!parsed.doc.contains("gnomon-path"))
        r.fail("", "missing required key \"gnomon-path\" (the format version, 1)");
    if (r.integer(parsed.doc["gnomon-path"], "gnomon-path", 0, 1000000) != 1)
        r.fail("gnomon-path", "this gnomon reads path format version 1");
    if (!parsed.doc.contains("cameras")) r.fail("", "missing required key \"cameras\"");
    const Json& cameras = r.array(parsed.doc["cameras"], "cameras", 2, std::size_t(kMaxFrames));
    ScenePath out;
    out.name = path;
    const std::size_t count =
        frames > 0 ? std::min(cameras.size(), std::size_t(frames)) : cameras.size();
    if (frames > 0 && std::size_t(frames) > cameras.size()) {
        r.fail("cameras", "the file has " + std::to_string(cameras.size()) +
                              " cameras, fewer than the " + std::to_string(frames) +
                              " frames asked for");
    }
    for (std::size_t i = 0; i < count; ++i) {
        // Each camera starts from the scene's, so a file may give only eye and centre.
        const Camera full = readCamera(r, cameras[i], element("cameras", i), scene.camera);
        if (glm::length(full.centre - full.eye) <= 0.0f)
            r.fail(element("cameras", i), "the eye and the centre are the same point");
        out.cameras.push_back(full);
    }
    return out;
}

}  // namespace

ScenePath makeScenePath(const std::string& spec, const Scene& scene, int frames) {
    const bool builtin = spec == "orbit" || spec == "dolly" || spec == "sun" || spec == "still";
    if (!builtin) {
        if (spec.find_first_of("./") == std::string::npos) {
            throw Error(ErrorKind::InvalidInput, "unknown path '" + spec +
                                                     "': expected orbit, dolly, sun, still or a "
                                                     "path file (.json)");
        }
        checkFrames(frames, true);
        return readPathFile(spec, scene, frames);
    }
    checkFrames(frames, false);
    ScenePath out;
    out.name = spec;
    const Camera& start = scene.camera;
    const glm::vec3 offset = start.eye - start.centre;
    for (int i = 0; i < frames; ++i) {
        Camera c = start;
        if (spec == "orbit") {
            c.eye = start.centre + turned(offset, start.up, 0.5f * float(i));
        } else if (spec == "dolly") {
            c.eye = start.centre + offset * (1.0f - 0.005f * float(i));
        }
        out.cameras.push_back(c);
        if (spec != "sun") continue;
        std::vector<glm::vec3> directions;
        for (const Light& l : scene.lights) {
            const bool parallel = l.type == LightType::Directional || l.type == LightType::Area;
            directions.push_back(
                parallel ? turned(l.direction, glm::vec3(0, 1, 0), 0.25f * float(i)) : l.direction);
        }
        out.lightDirections.push_back(std::move(directions));
    }
    return out;
}

void applyPathFrame(const ScenePath& path, int frame, Scene& scene) {
    if (frame < 0 || frame >= path.frames())
        throw Error(ErrorKind::InvalidInput,
                    "path frame " + std::to_string(frame) + " of " + std::to_string(path.frames()));
    scene.camera = path.cameras[std::size_t(frame)];
    if (path.lightDirections.empty()) return;
    const std::vector<glm::vec3>& d = path.lightDirections[std::size_t(frame)];
    for (std::size_t l = 0; l < scene.lights.size() && l < d.size(); ++l)
        scene.lights[l].direction = d[l];
}

}  // namespace gnomon
