// Reading the parts of a scene file: transforms, shapes, materials, lights, camera and render
// options. Each checks its keys, types and ranges, so a typo is an error with its JSON path.
#include "scene/SceneFileRead.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <regex>

#include <glm/gtc/matrix_transform.hpp>

#include "gnomon/OptionSchema.h"
#include "scene/MeshBuilder.h"

namespace gnomon::scenefile {
namespace {

// ---- Transforms: {"matrix": [16]} or {"translate", "rotate", "scale"} as T*R*S, or a list of
// those multiplied in order (the first outermost).

glm::mat4 readOneTransform(const Reader& r, const Json& j, const std::string& path) {
    const Fields f(r, j, path, {"matrix", "translate", "rotate", "scale"});
    if (const Json* m = f.find("matrix")) {
        if (f.has("translate") || f.has("rotate") || f.has("scale"))
            r.fail(path, "\"matrix\" cannot be combined with translate, rotate or scale");
        r.array(*m, f.at("matrix"), 16, 16);
        glm::mat4 out;
        for (int c = 0; c < 4; ++c)
            for (int k = 0; k < 4; ++k)
                out[c][k] = r.real((*m)[std::size_t(4 * c + k)],
                                   element(f.at("matrix"), std::size_t(4 * c + k)));
        return out;
    }
    glm::mat4 out(1.0f);
    if (const Json* t = f.find("translate"))
        out = glm::translate(out, r.vec3(*t, f.at("translate")));
    if (const Json* rot = f.find("rotate")) {
        const Fields rf(r, *rot, f.at("rotate"), {"axis", "degrees"});
        const glm::vec3 axis = r.vec3(rf.need("axis"), rf.at("axis"));
        const float degrees = r.real(rf.need("degrees"), rf.at("degrees"));
        if (!(glm::length(axis) > 0.0f)) r.fail(rf.at("axis"), "the rotation axis is zero");
        out = glm::rotate(out, glm::radians(degrees), glm::normalize(axis));
    }
    if (const Json* s = f.find("scale")) {
        const glm::vec3 scale =
            s->is_number() ? glm::vec3(r.real(*s, f.at("scale"))) : r.vec3(*s, f.at("scale"));
        if (scale.x == 0.0f || scale.y == 0.0f || scale.z == 0.0f)
            r.fail(f.at("scale"), "a scale of 0 flattens the geometry");
        out = glm::scale(out, scale);
    }
    return out;
}

// Directions are kept unit length when given so (the loader normalizes what is not).
glm::vec3 unitIfNot(const glm::vec3& d) {
    const float len = glm::length(d);
    return len > 0.0f && std::fabs(len - 1.0f) > 1e-6f ? d / len : d;
}

// Points as [[x, y, z], ...] or flat [x, y, z, x, y, z, ...].
std::vector<glm::vec3> readPoints(const Reader& r, const Json& j, const std::string& path) {
    r.array(j, path, 0, 3 * kMaxVertices);
    std::vector<glm::vec3> out;
    if (!j.empty() && j[0].is_array()) {
        if (j.size() > kMaxVertices)
            r.fail(path, "more than " + std::to_string(kMaxVertices) + " points");
        out.reserve(j.size());
        for (std::size_t i = 0; i < j.size(); ++i)
            out.push_back(r.vec3(j[i], element(path, i)));
    } else {
        if (j.size() % 3 != 0) {
            r.fail(path, "a flat list of points needs a multiple of 3 numbers, got " +
                             std::to_string(j.size()));
        }
        out.reserve(j.size() / 3);
        for (std::size_t i = 0; i < j.size(); i += 3)
            out.emplace_back(r.real(j[i], element(path, i)), r.real(j[i + 1], element(path, i + 1)),
                             r.real(j[i + 2], element(path, i + 2)));
    }
    return out;
}

// One colour for every vertex, or one per vertex.
std::vector<glm::vec3> readColours(const Reader& r, const Json& j, const std::string& path,
                                   std::size_t vertices, bool perVertexAllowed) {
    if (j.is_number() || (j.is_array() && !j.empty() && j[0].is_number()))
        return std::vector<glm::vec3>(vertices, r.colour(j, path));
    if (!perVertexAllowed) r.fail(path, "expected one colour [r, g, b] for every vertex");
    if (!j.is_array() || j.size() != vertices) {
        r.fail(path, "expected one colour [r, g, b] or a list of " + std::to_string(vertices) +
                         " (one per vertex), got " + preview(j));
    }
    std::vector<glm::vec3> out;
    for (std::size_t i = 0; i < j.size(); ++i)
        out.push_back(r.colour(j[i], element(path, i)));
    return out;
}

// Flat corners of a triangle or quad: the face's normal must exist.
void needArea(const Reader& r, const std::string& path, const std::vector<glm::vec3>& p) {
    const glm::vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    if (!(glm::length(n) > 0.0f) || !std::isfinite(glm::length(n)))
        r.fail(path, "the first three corners lie on a line (no face normal)");
}

void readProjectionNumbers(const Fields& f, Projection& projection, float& fovy, float& aspect,
                           float& near, float& far, float& left, float& right, float& bottom,
                           float& top) {
    f.get("projection", projection, kProjections);
    f.get("fovy", fovy, 1e-3f, 179.0f);
    f.get("aspect", aspect, 0.0f, 1e6f);
    f.get("near", near);
    f.get("far", far);
    f.get("left", left);
    f.get("right", right);
    f.get("bottom", bottom);
    f.get("top", top);
}

// The option keys: the schema's names, and "width" and "height" beside "size".
const std::vector<std::string>& optionKeys() {
    static const std::vector<std::string> k = [] {
        std::vector<std::string> keys;
        for (const OptionSpec& spec : optionSchema()) {
            keys.push_back(spec.name);
            if (spec.kind == OptionKind::Size) {
                keys.push_back("width");
                keys.push_back("height");
            }
        }
        return keys;
    }();
    return k;
}

}  // namespace

UpAxis readUpAxis(const Reader& r, const Json& j, const std::string& path) {
    const std::string text = r.string(j, path);
    const std::optional<UpAxis> up = parseUpAxis(text);
    if (!up) r.fail(path, "expected one of x, y, z, got \"" + text + "\"");
    return *up;
}

glm::mat4 readTransform(const Reader& r, const Json& j, const std::string& path) {
    if (!j.is_array()) return readOneTransform(r, j, path);
    r.array(j, path, 1, 64);
    glm::mat4 out(1.0f);
    for (std::size_t i = 0; i < j.size(); ++i)
        out = out * readOneTransform(r, j[i], element(path, i));
    return out;
}

glm::vec3 transformPoint(const glm::mat4& m, const glm::vec3& p) {
    return glm::vec3(m * glm::vec4(p, 1.0f));
}

// ---- Shapes

const std::vector<std::string>& shapeNames() {
    static const std::vector<std::string> k = {"box", "quad", "triangle", "mesh"};
    return k;
}

std::vector<std::string> shapeKeys(const std::string& shape) {
    if (shape == "box") return {"centre", "size", "colours"};
    if (shape == "quad" || shape == "triangle") return {"corners", "colours"};
    return {"positions", "normals", "colours", "indices"};
}

std::string peekShape(const Reader& r, const Json& j, const std::string& path) {
    if (!j.is_object() || !j.contains("shape")) return "";
    const std::string shape = r.string(j["shape"], member(path, "shape"));
    if (std::find(shapeNames().begin(), shapeNames().end(), shape) == shapeNames().end()) {
        r.fail(member(path, "shape"),
               "expected one of " + joined(shapeNames()) + ", got " + preview(j["shape"]));
    }
    return shape;
}

Mesh readShape(const Fields& f, const std::string& shape, const std::string& name) {
    const Reader& r = f.reader();
    Mesh m;
    if (shape == "box") {
        glm::vec3 centre(0.0f);
        f.get("centre", centre);
        const Json& s = f.need("size");
        const glm::vec3 size =
            s.is_number() ? glm::vec3(r.real(s, f.at("size"))) : r.vec3(s, f.at("size"));
        if (!(size.x > 0.0f && size.y > 0.0f && size.z > 0.0f))
            r.fail(f.at("size"), "box sizes must be > 0, got " + preview(s));
        m = mesh::box(name, centre, size);
    } else if (shape == "quad" || shape == "triangle") {
        const std::size_t n = shape == "quad" ? 4 : 3;
        const Json& cj = r.array(f.need("corners"), f.at("corners"), n, n);
        std::vector<glm::vec3> c;
        for (std::size_t i = 0; i < n; ++i)
            c.push_back(r.vec3(cj[i], element(f.at("corners"), i)));
        needArea(r, f.at("corners"), c);
        if (n == 4) {
            m = mesh::quad(name, c[0], c[1], c[2], c[3]);
        } else {
            const glm::vec3 p[3] = {c[0], c[1], c[2]};
            const glm::vec3 white[3] = {glm::vec3(1.0f), glm::vec3(1.0f), glm::vec3(1.0f)};
            m = mesh::triangle(name, p, white);
            m.colours.clear();
        }
    } else {
        m.name = name;
        m.positions = readPoints(r, f.need("positions"), f.at("positions"));
        const std::size_t n = m.positions.size();
        if (n == 0) r.fail(f.at("positions"), "a mesh needs at least one triangle");
        if (const Json* ij = f.find("indices")) {
            r.array(*ij, f.at("indices"), 3, 3 * kMaxVertices);
            if (ij->size() % 3 != 0) {
                r.fail(f.at("indices"), "expected a multiple of 3 indices (triangles), got " +
                                            std::to_string(ij->size()));
            }
            m.indices.reserve(ij->size());
            for (std::size_t i = 0; i < ij->size(); ++i) {
                const std::string at = element(f.at("indices"), i);
                const long long v =
                    r.integer((*ij)[i], at, 0, std::numeric_limits<long long>::max());
                if (v >= static_cast<long long>(n)) {
                    r.fail(at, "index " + std::to_string(v) + " is out of range (" +
                                   std::to_string(n) + " positions)");
                }
                m.indices.push_back(std::uint32_t(v));
            }
        } else {
            if (n % 3 != 0) {
                r.fail(f.at("positions"), "without indices, every 3 positions are a triangle: " +
                                              std::to_string(n) + " is not a multiple of 3");
            }
            for (std::size_t i = 0; i < n; ++i)
                m.indices.push_back(std::uint32_t(i));
        }
        if (const Json* nj = f.find("normals")) {
            m.normals = readPoints(r, *nj, f.at("normals"));
            if (m.normals.size() != n) {
                r.fail(f.at("normals"), "expected " + std::to_string(n) +
                                            " normals (one per position), got " +
                                            std::to_string(m.normals.size()));
            }
            for (std::size_t i = 0; i < n; ++i) {
                if (!(glm::length(m.normals[i]) > 0.0f))
                    r.fail(element(f.at("normals"), i), "a normal of length 0");
                m.normals[i] = unitIfNot(m.normals[i]);
            }
        } else {
            // Smooth normals: each vertex averages its triangles' (area-weighted) normals.
            m.normals.assign(n, glm::vec3(0.0f));
            for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
                const std::uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
                const glm::vec3 fn =
                    glm::cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
                m.normals[a] += fn;
                m.normals[b] += fn;
                m.normals[c] += fn;
            }
            for (glm::vec3& v : m.normals) {
                const float len = glm::length(v);
                v = len > 0.0f && std::isfinite(len) ? v / len : glm::vec3(0.0f, 0.0f, 1.0f);
            }
        }
    }
    if (const Json* cj = f.find("colours"))
        m.colours = readColours(r, *cj, f.at("colours"), m.positions.size(), shape != "box");
    return m;
}

// ---- Materials, lights, camera, options

Material readMaterial(const Reader& r, const Json& j, const std::string& path,
                      const std::string& name) {
    const Fields f(r, j, path,
                   {"colour", "specular", "shininess", "unlit", "double-sided", "alpha",
                    "alpha-mode", "alpha-cutoff"});
    Material m;
    m.name = name;
    f.getColour("colour", m.baseColour);
    f.get("specular", m.specular, 0.0f, 1.0f);
    f.get("shininess", m.shininess, 1e-6f, 1e6f);
    f.get("unlit", m.unlit);
    f.get("double-sided", m.doubleSided);
    f.get("alpha", m.alpha, 0.0f, 1.0f);
    f.get("alpha-mode", m.alphaMode, kAlphaModes);
    f.get("alpha-cutoff", m.alphaCutoff, 0.0f, 1.0f);
    return m;
}

Light readLight(const Reader& r, const Json& j, const std::string& path, std::size_t index) {
    const Fields f(
        r, j, path,
        {"name", "type", "enabled", "position", "direction", "colour", "intensity", "attenuation",
         "inner-cone", "outer-cone", "range", "casts-shadows", "shadow-map-size", "shadow-camera"});
    Light l;
    l.name = "light " + std::to_string(index);
    f.get("name", l.name);
    l.type = r.choice(f.need("type"), f.at("type"), kLightTypes);
    f.get("enabled", l.enabled);
    f.get("position", l.position);
    f.get("direction", l.direction);
    l.direction = unitIfNot(l.direction);
    f.getColour("colour", l.colour);
    f.get("intensity", l.intensity, 0.0f, std::numeric_limits<float>::max());
    if (const Json* a = f.find("attenuation")) {
        const glm::vec3 c = r.vec3(*a, f.at("attenuation"));
        l.attenuation = {c.x, c.y, c.z};
    }
    f.get("inner-cone", l.innerConeDegrees);
    f.get("outer-cone", l.outerConeDegrees);
    f.get("range", l.range, 0.0f, std::numeric_limits<float>::max());
    f.get("casts-shadows", l.castsShadows);
    f.get("shadow-map-size", l.shadowMapSize, 64, 8192);
    if (const Json* sc = f.find("shadow-camera")) {
        const Fields s(r, *sc, f.at("shadow-camera"),
                       {"policy", "projection", "target", "up", "fovy", "aspect", "near", "far",
                        "left", "right", "bottom", "top"});
        ShadowCamera& c = l.shadowCamera;
        s.get("policy", c.policy, kPolicies);
        s.get("target", c.target);
        s.get("up", c.up);
        readProjectionNumbers(s, c.projection, c.fovyDegrees, c.aspect, c.near, c.far, c.left,
                              c.right, c.bottom, c.top);
    }
    return l;
}

void fitPlanesLeftOut(const Json* camera, const Json* lights, Scene& out) {
    if (camera && !(camera->contains("near") && camera->contains("far"))) {
        Camera fitted = out.camera;
        fitCameraDepth(out, fitted);
        if (!camera->contains("near")) out.camera.near = fitted.near;
        if (!camera->contains("far")) out.camera.far = fitted.far;
    }
    // Manual and course shadow cameras sit at their light, and fit from there.
    for (std::size_t i = 0; lights && i < lights->size(); ++i) {
        Light& light = out.lights[i];  // readLight took (*lights)[i] as an object
        if (!(*lights)[i].contains("shadow-camera") ||
            light.shadowCamera.policy == ShadowCameraPolicy::Fit)
            continue;
        const Json& given = (*lights)[i].at("shadow-camera");
        ShadowCamera fitted = light.shadowCamera;
        fitShadowCameraDepth(out, light, fitted);
        if (!given.contains("near")) light.shadowCamera.near = fitted.near;
        if (!given.contains("far")) light.shadowCamera.far = fitted.far;
    }
}

Camera readCamera(const Reader& r, const Json& j, const std::string& path, const Camera& start) {
    const Fields f(r, j, path,
                   {"eye", "centre", "up", "projection", "fovy", "aspect", "near", "far", "left",
                    "right", "bottom", "top"});
    Camera c = start;
    f.get("eye", c.eye);
    f.get("centre", c.centre);
    f.get("up", c.up);
    readProjectionNumbers(f, c.projection, c.fovyDegrees, c.aspect, c.near, c.far, c.left, c.right,
                          c.bottom, c.top);
    return c;
}

// One option of the schema from its JSON value: switches as true/false, numbers as numbers
// (integers whole; a named 0 such as "auto" as that string), choices and the size as strings
// (a choice that was once a switch also as true/false).
void readOption(const Reader& r, const OptionSpec& spec, const Json& v, const std::string& at,
                RenderOptions& o) {
    switch (spec.kind) {
        case OptionKind::Switch:
            spec.set(o, r.boolean(v, at) ? 1.0 : 0.0);
            return;
        case OptionKind::Real:
            spec.set(o, r.number(v, at));  // validate() refuses what the option cannot hold
            return;
        case OptionKind::Integer:
            if (v.is_string() && *spec.zeroName) {
                if (v.get<std::string>() != spec.zeroName)
                    r.fail(at, "expected \"" + std::string(spec.zeroName) + "\" or a number, got " +
                                   preview(v));
                spec.set(o, 0.0);
                return;
            }
            spec.set(o, double(r.integer(v, at, std::numeric_limits<int>::min(),
                                         std::numeric_limits<int>::max())));
            return;
        case OptionKind::Choice:
        case OptionKind::Size:
            if (v.is_boolean() && *spec.formerOn) {  // written when the option was a switch
                parseOption(spec, v.get<bool>() ? "on" : "off", o);
                return;
            }
            if (!v.is_string() || parseOption(spec, v.get<std::string>(), o)) {
                r.fail(at, spec.kind == OptionKind::Size
                               ? "expected \"WIDTHxHEIGHT\" such as \"512x512\", got " + preview(v)
                               : "expected one of " + joined(spec.choices) + ", got " + preview(v));
            }
            return;
    }
}

// The keys given in `j` applied over `o`; RenderOptions::validate()'s sentences as errors.
void applyOptions(const Reader& r, const Json& j, const std::string& path, RenderOptions& o) {
    const Fields f(r, j, path, optionKeys());
    if (f.has("size") && (f.has("width") || f.has("height")))
        r.fail(path, "give \"size\" or \"width\" and \"height\", not both");
    for (const OptionSpec& spec : optionSchema()) {
        if (const Json* v = f.find(spec.name)) readOption(r, spec, *v, f.at(spec.name), o);
    }
    f.get("width", o.width, 1, 16384);
    f.get("height", o.height, 1, 16384);
    if (const auto problems = o.validate(); !problems.empty()) r.fail(path, joined(problems, "; "));
}

}  // namespace gnomon::scenefile
