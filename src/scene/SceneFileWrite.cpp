// Writing scene files: the JSON of lights, camera and options, refused when not finite, and
// printed with arrays of numbers and short objects on one line so the file reads well.
#include "scene/SceneFileWrite.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/FloatText.h"
#include "gnomon/Error.h"
#include "gnomon/Image.h"
#include "gnomon/OptionSchema.h"
#include "scene/SceneFileJson.h"

namespace gnomon::scenefile {
namespace {

// The shortest decimal that reads back as the same float (0.1f is written 0.1, not
// 0.10000000149011612).
OJson number(float v) {
    if (!std::isfinite(v)) return OJson(double(v));  // refused by checkFinite
    return OJson(std::strtod(shortestText(v).c_str(), nullptr));
}

OJson vec(const glm::vec3& v) {
    return OJson::array({number(v.x), number(v.y), number(v.z)});
}

void projectionJson(OJson& j, Projection projection, float fovy, float aspect, float near,
                    float far, float left, float right, float bottom, float top) {
    j["projection"] = nameOf(kProjections, projection);
    j["fovy"] = number(fovy);
    j["aspect"] = number(aspect);
    j["near"] = number(near);
    j["far"] = number(far);
    j["left"] = number(left);
    j["right"] = number(right);
    j["bottom"] = number(bottom);
    j["top"] = number(top);
}

OJson lightJson(const Light& l) {
    OJson j;
    j["name"] = l.name;
    j["type"] = nameOf(kLightTypes, l.type);
    j["enabled"] = l.enabled;
    j["position"] = vec(l.position);
    j["direction"] = vec(l.direction);
    j["colour"] = vec(l.colour);
    j["intensity"] = number(l.intensity);
    j["attenuation"] = OJson::array({number(l.attenuation.constant), number(l.attenuation.linear),
                                     number(l.attenuation.quadratic)});
    j["inner-cone"] = number(l.innerConeDegrees);
    j["range"] = number(l.range);
    j["outer-cone"] = number(l.outerConeDegrees);
    j["casts-shadows"] = l.castsShadows;
    if (l.shadowMapSize > 0) j["shadow-map-size"] = l.shadowMapSize;  // else its default
    const ShadowCamera& c = l.shadowCamera;
    OJson s;
    s["policy"] = nameOf(kPolicies, c.policy);
    s["target"] = vec(c.target);
    s["up"] = vec(c.up);
    projectionJson(s, c.projection, c.fovyDegrees, c.aspect, c.near, c.far, c.left, c.right,
                   c.bottom, c.top);
    j["shadow-camera"] = s;
    return j;
}

OJson cameraJson(const Camera& c) {
    OJson j;
    j["eye"] = vec(c.eye);
    j["centre"] = vec(c.centre);
    j["up"] = vec(c.up);
    projectionJson(j, c.projection, c.fovyDegrees, c.aspect, c.near, c.far, c.left, c.right,
                   c.bottom, c.top);
    return j;
}

// Every option of the schema, as readOption reads it back.
OJson optionsJson(const RenderOptions& o) {
    OJson j;
    for (const OptionSpec& spec : optionSchema()) {
        switch (spec.kind) {
            case OptionKind::Switch:
                j[spec.name] = spec.get(o) != 0.0;
                break;
            case OptionKind::Real: {
                // Floats as their shortest text; a double (time) as it is.
                const double v = spec.get(o);
                j[spec.name] = double(float(v)) == v ? number(float(v)) : OJson(v);
                break;
            }
            case OptionKind::Integer:
                if (spec.get(o) == 0.0 && *spec.zeroName) {
                    j[spec.name] = spec.zeroName;
                } else {
                    j[spec.name] = (long long)spec.get(o);
                }
                break;
            case OptionKind::Choice:
            case OptionKind::Size:
                j[spec.name] = formatOption(spec, o);
                break;
        }
    }
    return j;
}

void checkFinite(const OJson& j, const std::string& path, const std::string& file) {
    if (j.is_number_float() && !std::isfinite(j.get<double>())) {
        throw Error(ErrorKind::InvalidInput,
                    "cannot save '" + file + "': " + path + " is not a finite number");
    }
    if (j.is_object()) {
        for (auto it = j.begin(); it != j.end(); ++it)
            checkFinite(it.value(), member(path, it.key()), file);
    } else if (j.is_array()) {
        for (std::size_t i = 0; i < j.size(); ++i)
            checkFinite(j[i], element(path, i), file);
    }
}

// An object of scalars on one line, if that is short: {"scene": "x", "lights": false}.
std::string oneLine(const OJson& j) {
    std::string out = "{";
    for (auto it = j.begin(); it != j.end(); ++it) {
        if (it.value().is_structured()) return "";
        out += (out.size() > 1 ? ", " : "") + OJson(it.key()).dump() + ": " + it.value().dump();
    }
    return out.size() < 72 ? out + "}" : "";
}

// Indented JSON with arrays of numbers and short objects on one line.
void writePretty(std::string& out, const OJson& j, int indent) {
    const std::string pad(std::size_t(indent), ' '), inner(std::size_t(indent) + 2, ' ');
    if (j.is_object() && !j.empty()) {
        if (const std::string line = oneLine(j); !line.empty()) {
            out += line;
            return;
        }
        out += "{\n";
        std::size_t n = 0;
        for (auto it = j.begin(); it != j.end(); ++it) {
            out += inner + OJson(it.key()).dump() + ": ";
            writePretty(out, it.value(), indent + 2);
            out += ++n < j.size() ? ",\n" : "\n";
        }
        out += pad + "}";
    } else if (j.is_array() && !j.empty()) {
        const bool flat = std::all_of(
            j.begin(), j.end(), [](const OJson& e) { return !e.is_object() && !e.is_array(); });
        if (flat) {
            out += "[";
            for (std::size_t i = 0; i < j.size(); ++i)
                out += (i ? ", " : "") + j[i].dump();
            out += "]";
            return;
        }
        out += "[\n";
        for (std::size_t i = 0; i < j.size(); ++i) {
            out += inner;
            writePretty(out, j[i], indent + 2);
            out += i + 1 < j.size() ? ",\n" : "\n";
        }
        out += pad + "]";
    } else {
        out += j.dump();
    }
}

}  // namespace

void writeSceneFile(const std::string& path, const std::string& include, const Scene& scene,
                    const RenderOptions& options, bool ground, UpAxis up) {
    OJson doc;
    doc["gnomon-scene"] = kVersion;
    doc["name"] = scene.name;
    doc["description"] = scene.description;
    OJson included{{"scene", include}, {"lights", false}, {"camera", false}};
    if (up != UpAxis::Y) included["up"] = toString(up);
    doc["include"] = OJson::array({included});
    doc["lights"] = OJson::array();
    for (const Light& l : scene.lights)
        doc["lights"].push_back(lightJson(l));
    doc["camera"] = cameraJson(scene.camera);
    doc["ambient"] = vec(scene.ambient);
    if (ground) doc["ground"] = true;
    doc["options"] = optionsJson(options);
    checkFinite(doc, "", path);
    std::string text;
    writePretty(text, doc, 0);
    text += "\n";
    writeTextFile(path, text);
}

}  // namespace gnomon::scenefile
