// The address's scene edits (PageEdits.h): each key and light field as a pair of functions,
// its text in a scene and that text read back, so the writer and the reader cannot disagree.
#include "PageEdits.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <regex>
#include <tuple>

#include "core/FloatText.h"
#include "gnomon/Error.h"

namespace gnomon::web {
namespace {

[[noreturn]] void refuse(const std::string& message) {
    throw Error(ErrorKind::InvalidInput, message);
}

std::string listText(std::initializer_list<float> values) {
    std::string out;
    for (const float v : values)
        out += (out.empty() ? "" : ",") + numberText(v);
    return out;
}

std::string vecText(const glm::vec3& v) {
    return listText({v.x, v.y, v.z});
}

using Numbers = std::vector<float>;

// `n` numbers; none when the text is not n numbers or `valid` refuses them.
std::optional<Numbers> numbers(const std::string& text, std::size_t n,
                               bool (*valid)(const Numbers&) = nullptr) {
    auto got = parseNumberList(text, n);
    if (got && valid && !valid(*got)) return std::nullopt;
    return got;
}

bool readVec(const std::string& text, glm::vec3& v, bool (*valid)(const Numbers&) = nullptr) {
    const auto got = numbers(text, 3, valid);
    if (got) v = glm::vec3((*got)[0], (*got)[1], (*got)[2]);
    return bool(got);
}

bool readNumber(const std::string& text, float& v, bool (*valid)(const Numbers&) = nullptr) {
    const auto got = numbers(text, 1, valid);
    if (got) v = got->front();
    return bool(got);
}

// Four numbers into an orthographic volume's sides (the view camera's or a light's).
template <typename C>
bool readBox(const std::string& text, C& c) {
    const auto got = numbers(text, 4);
    if (got)
        std::tie(c.left, c.right, c.bottom, c.top) =
            std::tie((*got)[0], (*got)[1], (*got)[2], (*got)[3]);
    return bool(got);
}

// Two numbers, 0 < near < far, into a camera's planes.
template <typename C>
bool readDepth(const std::string& text, C& c) {
    const auto got = numbers(text, 2, [](const Numbers& v) { return v[0] > 0.0f && v[1] > v[0]; });
    if (got) std::tie(c.near, c.far) = std::tie((*got)[0], (*got)[1]);
    return bool(got);
}

bool allAtLeastZero(const Numbers& v) {
    return std::all_of(v.begin(), v.end(), [](float x) { return x >= 0.0f; });
}

bool readSwitch(const std::string& text, bool& v) {
    if (text != "on" && text != "off") return false;
    v = text == "on";
    return true;
}

// One of an enum's values by its name (toString), the enum running from 0 to `count`.
template <typename E>
bool readChoice(const std::string& text, E& v, int count) {
    for (int i = 0; i < count; ++i) {
        if (text == toString(E(i))) {
            v = E(i);
            return true;
        }
    }
    return false;
}

// Short names for the tables' lambdas, which capture nothing: the tables hold plain function
// pointers.
using L = const Light&;
using S = const std::string&;

}  // namespace

std::string numberText(float v) {
    std::string out = shortestText(v);
    const std::size_t plus = out.find("e+");  // "1e+06" reads back as "1e06"; '+' needs escaping
    if (plus != std::string::npos) out.erase(plus + 1, 1);
    return out;
}

std::string encodedValue(const std::string& text) {
    static const std::string kLiteral = "-._~,:;/";
    std::string out;
    for (const char c : text) {
        if (std::isalnum((unsigned char)c) || kLiteral.find(c) != std::string::npos) {
            out += c;
        } else {
            char escape[4];
            std::snprintf(escape, sizeof escape, "%%%02X", (unsigned)(unsigned char)c);
            out += escape;
        }
    }
    return out;
}

const std::vector<SceneKey>& sceneKeys() {
    static const std::vector<SceneKey> keys = {
        {"camera-projection", "perspective or orthographic",
         [](const Scene& s) -> std::string { return toString(s.camera.projection); },
         [](S t, Scene& s) { return readChoice(t, s.camera.projection, 2); }},
        {"camera-box", "LEFT,RIGHT,BOTTOM,TOP such as -5,5,-5,5",
         [](const Scene& s) {
             const Camera& c = s.camera;
             return listText({c.left, c.right, c.bottom, c.top});
         },
         [](S t, Scene& s) { return readBox(t, s.camera); }},
        {"camera-depth", "NEAR,FAR with 0 < near < far, such as 0.1,100",
         [](const Scene& s) {
             return listText({s.camera.near, s.camera.far});
         },
         [](S t, Scene& s) { return readDepth(t, s.camera); }},
        {"ambient", "R,G,B, each 0 or more, such as 0.1,0.1,0.1",
         [](const Scene& s) { return vecText(s.ambient); },
         [](S t, Scene& s) { return readVec(t, s.ambient, allAtLeastZero); }},
    };
    return keys;
}

const std::vector<LightField>& lightFields() {
    static const std::vector<LightField> fields = {
        {"on", "on or off", [](L l) -> std::string { return l.enabled ? "on" : "off"; },
         [](S t, Light& l) { return readSwitch(t, l.enabled); }},
        {"shadows", "on or off", [](L l) -> std::string { return l.castsShadows ? "on" : "off"; },
         [](S t, Light& l) { return readSwitch(t, l.castsShadows); }},
        {"type", "one of directional, spot, point, area",
         [](L l) -> std::string { return toString(l.type); },
         [](S t, Light& l) { return readChoice(t, l.type, 4); }},
        {"pos", "X,Y,Z such as 1,4,2", [](L l) { return vecText(l.position); },
         [](S t, Light& l) { return readVec(t, l.position); }},
        {"dir", "X,Y,Z, not all 0, such as 0,-1,0", [](L l) { return vecText(l.direction); },
         [](S t, Light& l) {
             return readVec(t, l.direction, [](const Numbers& v) {
                 return std::any_of(v.begin(), v.end(), [](float x) { return x != 0.0f; });
             });
         }},
        {"colour", "R,G,B, each 0 or more, such as 1,0.9,0.8",
         [](L l) { return vecText(l.colour); },
         [](S t, Light& l) { return readVec(t, l.colour, allAtLeastZero); }},
        {"int", "a number, 0 or more", [](L l) { return numberText(l.intensity); },
         [](S t, Light& l) { return readNumber(t, l.intensity, allAtLeastZero); }},
        {"att", "CONSTANT,LINEAR,QUADRATIC, each 0 or more and not all 0, such as 1,0,0.1",
         [](L l) {
             const Attenuation& a = l.attenuation;
             return listText({a.constant, a.linear, a.quadratic});
         },
         [](S t, Light& l) {
             const auto v = numbers(t, 3, [](const Numbers& a) {
                 return allAtLeastZero(a) && a[0] + a[1] + a[2] > 0.0f;
             });
             if (v) l.attenuation = {(*v)[0], (*v)[1], (*v)[2]};
             return bool(v);
         }},
        {"range", "a distance, 0 or more (0: unlimited)", [](L l) { return numberText(l.range); },
         [](S t, Light& l) { return readNumber(t, l.range, allAtLeastZero); }},
        {"cone", "INNER,OUTER degrees with 0 <= inner <= outer < 90, such as 20,30",
         [](L l) {
             return listText({l.innerConeDegrees, l.outerConeDegrees});
         },
         [](S t, Light& l) {
             const auto v = numbers(t, 2, [](const Numbers& c) {
                 return c[0] >= 0.0f && c[0] <= c[1] && c[1] > 0.0f && c[1] < 90.0f;
             });
             if (v) std::tie(l.innerConeDegrees, l.outerConeDegrees) = std::tie((*v)[0], (*v)[1]);
             return bool(v);
         }},
        {"map", "0 (the light's default) or 64..8192 texels",
         [](L l) { return std::to_string(l.shadowMapSize); },
         [](S t, Light& l) {
             static const std::regex kSize(R"(0|[1-9]\d{0,3})");
             if (!std::regex_match(t, kSize)) return false;
             const int v = std::stoi(t);
             if (v != 0 && (v < 64 || v > 8192)) return false;
             l.shadowMapSize = v;
             return true;
         }},
        {"cam", "one of fit, manual, course",
         [](L l) -> std::string { return toString(l.shadowCamera.policy); },
         [](S t, Light& l) { return readChoice(t, l.shadowCamera.policy, 3); }},
        {"proj", "perspective or orthographic",
         [](L l) -> std::string { return toString(l.shadowCamera.projection); },
         [](S t, Light& l) { return readChoice(t, l.shadowCamera.projection, 2); }},
        {"target", "X,Y,Z such as 0,0,0", [](L l) { return vecText(l.shadowCamera.target); },
         [](S t, Light& l) { return readVec(t, l.shadowCamera.target); }},
        {"fov", "degrees, more than 0 and less than 180",
         [](L l) { return numberText(l.shadowCamera.fovyDegrees); },
         [](S t, Light& l) {
             return readNumber(t, l.shadowCamera.fovyDegrees,
                               [](const Numbers& v) { return v[0] > 0.0f && v[0] < 180.0f; });
         }},
        {"box", "LEFT,RIGHT,BOTTOM,TOP such as -5,5,-5,5",
         [](L l) {
             const ShadowCamera& c = l.shadowCamera;
             return listText({c.left, c.right, c.bottom, c.top});
         },
         [](S t, Light& l) { return readBox(t, l.shadowCamera); }},
        {"depth", "NEAR,FAR with 0 < near < far, such as 0.5,50",
         [](L l) {
             return listText({l.shadowCamera.near, l.shadowCamera.far});
         },
         [](S t, Light& l) { return readDepth(t, l.shadowCamera); }},
    };
    return fields;
}

int lightKeyIndex(const std::string& key) {
    static const std::regex kLight(R"(light(0|[1-9]\d{0,5}))");
    std::smatch m;
    return std::regex_match(key, m, kLight) ? std::stoi(m[1].str()) : -1;
}

std::map<std::string, std::string> parseLightFields(const std::string& key,
                                                    const std::string& value) {
    std::vector<std::string> names;
    for (const LightField& f : lightFields())
        names.push_back(f.name);
    std::map<std::string, std::string> out;
    std::size_t at = 0;
    while (at <= value.size()) {
        std::size_t end = value.find(';', at);
        if (end == std::string::npos) end = value.size();
        const std::string part = value.substr(at, end - at);
        at = end + 1;
        if (part.empty()) continue;
        const std::size_t colon = part.find(':');
        if (colon == std::string::npos) {
            refuse(key + ": expected FIELD:VALUE;... such as pos:1,4,2;int:3, got '" + part + "'");
        }
        const std::string name = part.substr(0, colon);
        if (std::find(names.begin(), names.end(), name) == names.end()) {
            const std::string nearest = nearestName(name, names);
            refuse(key + ": unknown field '" + name + "'" +
                   (nearest.empty() ? "" : "; did you mean " + nearest + "?"));
        }
        if (!out.emplace(name, part.substr(colon + 1)).second)
            refuse(key + ": gives '" + name + "' twice");
    }
    if (out.empty()) refuse(key + ": expected FIELD:VALUE;... such as pos:1,4,2;int:3");
    return out;
}

void applySceneEdits(const PageRequest& request, Scene& scene) {
    const auto given = [&](const char* key) -> std::optional<std::string> {
        const auto it = request.edits.find(key);
        if (it == request.edits.end()) return std::nullopt;
        return it->second;
    };
    CameraAndSun cli;  // what the CLI's flags of the same names do, in its words
    cli.eye = given("camera-eye");
    cli.target = given("camera-target");
    cli.sun = given("sun");
    if (const auto fov = given("camera-fov")) {
        const auto v = parseNumberList(*fov, 1);
        if (!v) refuse("--camera-fov: expected a number, got '" + *fov + "'");
        cli.fovDegrees = v->front();
    }
    placeCameraAndSun(scene, cli);
    for (const SceneKey& k : sceneKeys()) {
        const auto text = given(k.name);
        if (text && !k.parse(*text, scene))
            refuse(std::string(k.name) + ": expected " + k.expected + ", got '" + *text + "'");
    }
    const std::size_t count = scene.lights.size();
    for (const auto& [index, fields] : request.lights) {
        const std::string key = "light" + std::to_string(index);
        if (std::size_t(index) >= count) {
            refuse(key + ": the scene has " +
                   (count == 0   ? std::string("no lights")
                    : count == 1 ? std::string("1 light (light0)")
                                 : std::to_string(count) + " lights (light0..light" +
                                       std::to_string(count - 1) + ")"));
        }
        Light& light = scene.lights[std::size_t(index)];
        for (const LightField& f : lightFields()) {
            const auto text = fields.find(f.name);
            if (text != fields.end() && !f.parse(text->second, light)) {
                refuse(key + ": " + f.name + ": expected " + f.expected + ", got '" + text->second +
                       "'");
            }
        }
    }
    // What no field can check alone: a spot turned by `type` with no direction, a shadow
    // camera looking at its own light.
    for (const std::string& problem : scene.validateLightsAndCamera()) {
        for (const auto& [index, fields] : request.lights) {
            if (problem.find("lights[" + std::to_string(index) + "]") != std::string::npos)
                refuse("light" + std::to_string(index) + ": " + problem);
        }
    }
}

}  // namespace gnomon::web
