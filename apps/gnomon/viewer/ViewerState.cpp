#include "ViewerState.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "RenderOptionsCli.h"
#include "gnomon/Error.h"
#include "viewer_presets.h"  // kPresetsText: examples/presets.txt

namespace gnomon::view {
namespace {

[[noreturn]] void bad(const std::string& message) {
    throw Error(ErrorKind::InvalidInput, message);
}

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string w; in >> w;)
        out.push_back(w);
    return out;
}

std::vector<PresetEntry> buildPresets() {
    std::vector<PresetEntry> out;
    out.push_back({"default", "Start from", {"--preset", "default"}});
    out.push_back({"textbook", "Start from", {"--preset", "textbook"}});
    std::istringstream in(kPresetsText);
    std::string group = "Examples";
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("## ", 0) == 0) {
            group = line.substr(3);
            continue;
        }
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> w = words(line);
        if (w.empty()) continue;
        PresetEntry p;
        p.name = w.front();
        p.group = group;
        p.args.assign(w.begin() + 1, w.end());
        out.push_back(std::move(p));
    }
    return out;
}

float number(const Command& c, std::size_t i) {
    const std::string& s = c.args.at(i);
    try {
        std::size_t used = 0;
        const float v = std::stof(s, &used);
        if (used == s.size() && std::isfinite(v)) return v;
    } catch (const std::exception&) {
    }
    bad("line " + std::to_string(c.line) + ": " + c.verb + ": expected a number, got '" + s + "'");
}

int integer(const Command& c, std::size_t i) {
    const float v = number(c, i);
    if (v != std::floor(v)) {
        bad("line " + std::to_string(c.line) + ": " + c.verb + ": expected a whole number, got '" +
            c.args[i] + "'");
    }
    return int(v);
}

glm::vec3 vec3(const Command& c, std::size_t first) {
    return {number(c, first), number(c, first + 1), number(c, first + 2)};
}

bool onOff(const Command& c, std::size_t i) {
    const std::string& s = c.args.at(i);
    if (s == "on" || s == "true" || s == "1") return true;
    if (s == "off" || s == "false" || s == "0") return false;
    bad("line " + std::to_string(c.line) + ": " + c.verb + ": expected on or off, got '" + s + "'");
}

template <typename E>
E choice(const Command& c, std::size_t i, const std::map<std::string, E>& names) {
    const std::string& s = c.args.at(i);
    if (auto it = names.find(s); it != names.end()) return it->second;
    std::string known;
    for (const auto& [name, value] : names)
        known += (known.empty() ? "" : ", ") + name;
    bad("line " + std::to_string(c.line) + ": " + c.verb + ": expected one of " + known +
        ", got '" + s + "'");
}

// A value of an enum by its toString spelling (Scene.h).
template <typename E>
E named(const Command& c, std::size_t i) {
    std::map<std::string, E> names;
    for (int v = 0; std::string(toString(E(v))) != "?"; ++v)
        names.emplace(toString(E(v)), E(v));
    return choice(c, i, names);
}

void needArgs(const Command& c, std::size_t count) {
    if (c.args.size() != count) {
        bad("line " + std::to_string(c.line) + ": " + c.verb + " " +
            (c.args.empty() ? "" : c.args.front() + " ") + "takes " + std::to_string(count) +
            " argument(s) here, got " + std::to_string(c.args.size()));
    }
}

// Verbs and their argument counts (min, max; -1: any).
struct Arity {
    int min, max;
};
const std::map<std::string, Arity>& verbs() {
    static const std::map<std::string, Arity> v = {
        // State edits (applyCommand).
        {"set", {1, -1}},
        {"preset", {1, 1}},
        {"scene", {1, 1}},
        {"light", {2, 5}},
        {"camera", {2, 4}},
        {"orbit", {2, 2}},
        {"pan", {2, 2}},
        {"zoom", {1, 1}},
        {"drag-light", {2, 2}},
        {"select-light", {1, 1}},
        {"side", {1, 1}},
        {"frusta", {1, 1}},
        {"fit-view", {1, 1}},
        {"play", {0, 0}},
        {"pause", {0, 0}},
        {"speed", {1, 1}},
        // The viewer's own (Viewer.cpp).
        {"wait", {1, 1}},
        {"screenshot", {1, 1}},
        {"window-shot", {1, 1}},
        {"save", {1, 1}},
        {"load", {1, 1}},
        {"score", {0, 0}},
        {"wait-score", {0, 0}},
        {"expect-score", {3, 3}},
        {"tune", {0, 0}},
        {"wait-tune", {0, 0}},
        {"apply-tune", {0, 0}},
        {"key", {1, 1}},
        {"stats", {0, 0}},
        {"tab", {1, 1}},
        {"expect-fits", {0, 0}},
        {"measure", {1, 1}},
        {"quit", {0, 0}},
        {"repeat", {2, -1}},
    };
    return v;
}

glm::vec3 rotateAbout(const glm::vec3& v, const glm::vec3& axis, float degrees) {
    return glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(degrees), axis) *
                     glm::vec4(v, 0.0f));
}

void checkCommand(const Command& c, const std::string& path) {
    const int lineNumber = c.line;
    const auto it = verbs().find(c.verb);
    if (it == verbs().end()) {
        std::string known;
        for (const auto& [verb, arity] : verbs())
            known += (known.empty() ? "" : ", ") + verb;
        bad(path + ":" + std::to_string(lineNumber) + ": unknown command '" + c.verb +
            "' (known: " + known + ")");
    }
    const int n = int(c.args.size());
    if (n < it->second.min || (it->second.max >= 0 && n > it->second.max)) {
        bad(path + ":" + std::to_string(lineNumber) + ": " + c.verb + " takes " +
            (it->second.min == it->second.max
                 ? std::to_string(it->second.min)
                 : std::to_string(it->second.min) + ".." +
                       (it->second.max < 0 ? std::string("any") : std::to_string(it->second.max))) +
            " argument(s), got " + std::to_string(n));
    }
}

}  // namespace

const std::vector<PresetEntry>& presets() {
    static const std::vector<PresetEntry> all = buildPresets();
    return all;
}

const PresetEntry* findPreset(const std::string& name) {
    for (const PresetEntry& p : presets()) {
        if (p.name == name) return &p;
    }
    return nullptr;
}

void load(State& state, const std::string& source, bool ground, UpAxis up) {
    Scene scene = loadScene(source, up);
    if (ground) addGround(scene);
    show(state, std::move(scene), source, ground, up);
}

void show(State& state, Scene scene, const std::string& source, bool ground, UpAxis up) {
    const int width = state.options.width, height = state.options.height;
    state.scene = std::move(scene);
    state.source = source;
    state.ground = ground;
    state.up = up;
    state.options = state.scene.options;
    if (!state.fitView) {
        state.options.width = width;
        state.options.height = height;
    }
    state.selectedLight = 0;
    for (std::size_t i = 0; i < state.scene.lights.size(); ++i) {
        if (state.scene.lights[i].castsShadows && state.scene.lights[i].enabled) {
            state.selectedLight = int(i);
            break;
        }
    }
    ++state.revision;
}

void applyFlags(State& state, const std::vector<std::string>& args) {
    CLI::App app{"gnomon view flags"};
    cli::RenderFlags flags;
    std::string scene;
    app.add_option("--scene", scene, "scene to load");
    flags.add(app);
    std::vector<std::string> reversed(args.rbegin(), args.rend());
    try {
        app.parse(reversed);
    } catch (const CLI::ParseError& e) {
        std::string all;
        for (const std::string& a : args)
            all += (all.empty() ? "" : " ") + a;
        bad("flags '" + all + "': " + e.what());
    }
    // A new scene loads with the --up given (default y); --up alone reloads the source.
    const bool upGiven = app.count("--up") > 0;
    const UpAxis up = upGiven || !scene.empty() ? flags.upAxis() : state.up;
    if (!scene.empty() || (flags.ground && !state.ground) || up != state.up) {
        load(state, scene.empty() ? state.source : scene, flags.ground || state.ground, up);
    }
    flags.placeCameraAndSun(state.scene);
    RenderOptions options = state.options;
    if (app.count("--preset") > 0) {
        const std::optional<gnomon::Preset> p = parsePreset(flags.preset);
        if (!p) bad("--preset: expected one of default, textbook, got '" + flags.preset + "'");
        options = presetOptions(state.scene, *p);
        options.width = state.options.width;
        options.height = state.options.height;
    }
    flags.apply(options);  // validates
    if (flags.given(optionAt(options, &options.width))) state.fitView = false;
    state.options = options;
    ++state.revision;
}

void applyPreset(State& state, const PresetEntry& preset) {
    // An example names its scene: it starts from that scene's authored options.
    applyFlags(state, preset.args);
}

RenderOptions mainViewOptions(const State& state, int width, int height) {
    RenderOptions o = state.options;
    if (state.fitView) {
        o.width = std::clamp(width, 1, 16384);
        o.height = std::clamp(height, 1, 16384);
    }
    if (state.frusta) o.debugView = DebugView::LightFrusta;
    return o;
}

void orbit(Camera& camera, float yawDegrees, float pitchDegrees) {
    const glm::vec3 up = glm::normalize(camera.up);
    glm::vec3 offset = camera.eye - camera.centre;
    offset = rotateAbout(offset, up, -yawDegrees);
    const glm::vec3 right = glm::cross(-offset, up);
    if (glm::length(right) > 0.0f) {
        // Keep 2 degrees short of either pole so the up vector stays meaningful.
        const float angle = glm::degrees(std::acos(
            std::clamp(glm::dot(glm::normalize(offset), up), -1.0f, 1.0f)));  // 0 at the pole
        const float pitch = std::clamp(-pitchDegrees, 2.0f - angle, 178.0f - angle);
        offset = rotateAbout(offset, glm::normalize(right), -pitch);
    }
    camera.eye = camera.centre + offset;
}

void pan(Camera& camera, float dx, float dy) {
    const glm::vec3 forward = camera.centre - camera.eye;
    const float distance = glm::length(forward);
    if (distance <= 0.0f) return;
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 up = glm::normalize(glm::cross(right, forward));
    const float height = camera.projection == Projection::Perspective
                             ? 2.0f * distance * std::tan(glm::radians(camera.fovyDegrees) * 0.5f)
                             : camera.top - camera.bottom;
    const glm::vec3 move = (-dx * right + dy * up) * height;
    camera.eye += move;
    camera.centre += move;
}

void zoom(Camera& camera, float factor) {
    if (!(factor > 0.0f) || !std::isfinite(factor)) return;
    if (camera.projection == Projection::Orthographic) {
        camera.left *= factor;
        camera.right *= factor;
        camera.bottom *= factor;
        camera.top *= factor;
        return;
    }
    const glm::vec3 offset = camera.eye - camera.centre;
    const float distance = glm::length(offset);
    const float next = std::max(distance * factor, camera.near * 1.01f);
    if (distance > 0.0f) camera.eye = camera.centre + offset * (next / distance);
}

void orbitLight(Light& light, const glm::vec3& pivot, const glm::vec3& viewRight, float yawDegrees,
                float pitchDegrees) {
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    const glm::vec3 axis =
        glm::length(viewRight) > 0.0f ? glm::normalize(viewRight) : glm::vec3(1, 0, 0);
    auto turn = [&](glm::vec3 v) {
        v = rotateAbout(v, up, yawDegrees);
        return rotateAbout(v, axis, pitchDegrees);
    };
    light.direction = turn(light.direction);
    if (light.type != LightType::Directional) light.position = pivot + turn(light.position - pivot);
}

std::vector<Command> parseScript(const std::string& text, const std::string& path) {
    std::vector<Command> out;
    std::istringstream in(text);
    int lineNumber = 0;
    for (std::string line; std::getline(in, line);) {
        ++lineNumber;
        if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        std::vector<std::string> w = words(line);
        if (w.empty()) continue;
        Command c;
        c.line = lineNumber;
        c.verb = w.front();
        c.args.assign(w.begin() + 1, w.end());
        checkCommand(c, path);
        if (c.verb == "repeat") {
            const Command inner = repeatedCommand(c);
            if (inner.verb == "repeat" || inner.verb == "wait" || inner.verb == "wait-score" ||
                inner.verb == "wait-tune" || inner.verb == "quit") {
                bad(path + ":" + std::to_string(lineNumber) + ": repeat cannot repeat " +
                    inner.verb);
            }
            checkCommand(inner, path);
        }
        out.push_back(std::move(c));
    }
    return out;
}

Command repeatedCommand(const Command& c) {
    const std::string& n = c.args.at(0);
    if (n.empty() || n.size() > 6 || n.find_first_not_of("0123456789") != std::string::npos) {
        bad("line " + std::to_string(c.line) + ": repeat: expected a frame count, got '" + n + "'");
    }
    Command inner;
    inner.line = c.line;
    inner.verb = c.args.at(1);
    inner.args.assign(c.args.begin() + 2, c.args.end());
    return inner;
}

bool applyCommand(State& state, const Command& c) {
    const std::string at = "line " + std::to_string(c.line) + ": ";
    Camera& cam = state.scene.camera;
    if (c.verb == "set") {
        applyFlags(state, c.args);
    } else if (c.verb == "preset") {
        const PresetEntry* p = findPreset(c.args[0]);
        if (!p) bad(at + "preset: no preset named '" + c.args[0] + "'");
        applyPreset(state, *p);
    } else if (c.verb == "scene") {
        applyFlags(state, {"--scene", c.args[0]});
    } else if (c.verb == "light") {
        const int index = integer(c, 0);
        if (index < 0 || index >= int(state.scene.lights.size())) {
            bad(at + "light " + c.args[0] + ": scene '" + state.scene.name + "' has " +
                std::to_string(state.scene.lights.size()) + " light(s)");
        }
        Light& l = state.scene.lights[std::size_t(index)];
        const std::string& key = c.args[1];
        Command rest{c.line, "light " + c.args[0] + " " + key, {c.args.begin() + 2, c.args.end()}};
        if (key == "on") {
            needArgs(rest, 1);
            l.enabled = onOff(rest, 0);
        } else if (key == "shadows") {
            needArgs(rest, 1);
            l.castsShadows = onOff(rest, 0);
        } else if (key == "type") {
            needArgs(rest, 1);
            l.type = named<LightType>(rest, 0);
        } else if (key == "position" || key == "direction" || key == "colour") {
            needArgs(rest, 3);
            (key == "position"    ? l.position
             : key == "direction" ? l.direction
                                  : l.colour) = vec3(rest, 0);
        } else if (key == "intensity") {
            needArgs(rest, 1);
            l.intensity = number(rest, 0);
        } else if (key == "map-size") {
            needArgs(rest, 1);
            l.shadowMapSize = integer(rest, 0);
        } else if (key == "policy") {
            needArgs(rest, 1);
            l.shadowCamera.policy = named<ShadowCameraPolicy>(rest, 0);
        } else {
            bad(at + "light: unknown property '" + key +
                "' (known: on, shadows, type, position, direction, colour, intensity, map-size, "
                "policy)");
        }
        ++state.revision;
    } else if (c.verb == "camera") {
        const std::string& key = c.args[0];
        Command rest{c.line, "camera " + key, {c.args.begin() + 1, c.args.end()}};
        if (key == "eye" || key == "centre") {
            needArgs(rest, 3);
            (key == "eye" ? cam.eye : cam.centre) = vec3(rest, 0);
        } else if (key == "fovy") {
            needArgs(rest, 1);
            cam.fovyDegrees = number(rest, 0);
        } else {
            bad(at + "camera: unknown property '" + key + "' (known: eye, centre, fovy)");
        }
        ++state.revision;
    } else if (c.verb == "orbit") {
        orbit(cam, number(c, 0), number(c, 1));
        ++state.revision;
    } else if (c.verb == "pan") {
        pan(cam, number(c, 0), number(c, 1));
        ++state.revision;
    } else if (c.verb == "zoom") {
        zoom(cam, number(c, 0));
        ++state.revision;
    } else if (c.verb == "drag-light") {
        if (state.selectedLight < 0 || state.selectedLight >= int(state.scene.lights.size())) {
            bad(at + "drag-light: no light selected");
        }
        const glm::vec3 right = glm::cross(cam.centre - cam.eye, cam.up);
        orbitLight(state.scene.lights[std::size_t(state.selectedLight)], cam.centre, right,
                   number(c, 0), number(c, 1));
        ++state.revision;
    } else if (c.verb == "select-light") {
        const int index = integer(c, 0);
        if (index < 0 || index >= int(state.scene.lights.size())) {
            bad(at + "select-light " + c.args[0] + ": scene '" + state.scene.name + "' has " +
                std::to_string(state.scene.lights.size()) + " light(s)");
        }
        state.selectedLight = index;
    } else if (c.verb == "side") {
        state.side =
            choice<SideView>(c, 0, {{"shadow-map", SideView::ShadowMap}, {"none", SideView::None}});
    } else if (c.verb == "frusta") {
        state.frusta = onOff(c, 0);
        ++state.viewRevision;
    } else if (c.verb == "fit-view") {
        state.fitView = onOff(c, 0);
        ++state.revision;
    } else if (c.verb == "play" || c.verb == "pause") {
        state.playing = c.verb == "play";
    } else if (c.verb == "speed") {
        state.speed = number(c, 0);
    } else {
        return false;
    }
    return true;
}

}  // namespace gnomon::view
