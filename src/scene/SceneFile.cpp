// Scene description files (docs/scene-file.md). The reader is strict: an unknown key, a wrong
// type, a bad name or an out-of-range value is an error naming the file and the JSON path, so
// a typo never passes silently. The writer saves what a viewer tuned over an included scene.
#include "gnomon/SceneFile.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "gnomon/Error.h"
#include "gnomon/Image.h"
#include "scene/MeshBuilder.h"
#include "scene/SceneUtil.h"

namespace gnomon {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;           // reading: std::map, no quadratic inserts
using OJson = nlohmann::ordered_json;  // writing: keys in a readable order

constexpr int kVersion = 1;
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(64) << 20;
constexpr std::size_t kMaxIncludeDepth = 8;  // files open at once: this one and 7 includes
constexpr std::size_t kMaxIncludes = 64;
constexpr std::size_t kMaxLights = 256;         // the renderer's lights in one main pass
constexpr std::size_t kMaxItems = 1u << 20;     // materials, meshes, objects
constexpr std::size_t kMaxVertices = 1u << 24;  // per mesh
constexpr std::size_t kMaxNesting = 64;         // JSON arrays and objects inside each other

// ---- JSON paths for messages: lights[2].type, materials["vertex colour"].colour

bool plainKey(const std::string& k) {
    return !k.empty() && std::all_of(k.begin(), k.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
    });
}

std::string member(const std::string& path, const std::string& key) {
    if (plainKey(key)) return path.empty() ? key : path + "." + key;
    return path + "[" + Json(key).dump() + "]";
}

std::string element(const std::string& path, std::size_t i) {
    return path + "[" + std::to_string(i) + "]";
}

std::string preview(const Json& v) {
    switch (v.type()) {
        case Json::value_t::object:
            return "an object";
        case Json::value_t::array:
            return "an array";
        case Json::value_t::null:
            return "null";
        default:
            break;
    }
    std::string s = v.dump();
    if (s.size() > 60) s = s.substr(0, 57) + "...";
    return s;
}

std::string joined(const std::vector<std::string>& items, const char* separator = ", ") {
    std::string out;
    for (const std::string& s : items)
        out += (out.empty() ? "" : separator) + s;
    return out;
}

// ---- Names of enum values

template <typename E>
using Names = std::vector<std::pair<std::string, E>>;

// The spellings of toString (Options.h, Scene.h), in enum order: "?" past the last value.
template <typename E>
Names<E> optionNames() {
    Names<E> out;
    for (int i = 0; i < 64; ++i) {
        const std::string name = toString(E(i));
        if (name == "?") break;
        out.emplace_back(name, E(i));
    }
    return out;
}

const Names<LightType> kLightTypes = optionNames<LightType>();
const Names<Projection> kProjections = optionNames<Projection>();
const Names<ShadowCameraPolicy> kPolicies = optionNames<ShadowCameraPolicy>();
const Names<AlphaMode> kAlphaModes = {
    {"opaque", AlphaMode::Opaque}, {"mask", AlphaMode::Mask}, {"blend", AlphaMode::Blend}};

template <typename E>
std::string nameOf(const Names<E>& names, E v) {
    for (const auto& [name, value] : names)
        if (value == v) return name;
    return "?";
}

// ---- Reading typed values; every failure names the file and the JSON path

class Reader {
public:
    explicit Reader(std::string file) : mFile(std::move(file)) {}
    const std::string& file() const { return mFile; }

    [[noreturn]] void fail(const std::string& path, const std::string& message) const {
        throw Error(ErrorKind::InvalidInput,
                    mFile + ": " + (path.empty() ? "" : path + ": ") + message);
    }

    const Json& object(const Json& j, const std::string& path) const {
        if (!j.is_object()) fail(path, "expected an object {...}, got " + preview(j));
        return j;
    }
    const Json& array(const Json& j, const std::string& path, std::size_t minSize,
                      std::size_t maxSize) const {
        if (!j.is_array()) fail(path, "expected an array [...], got " + preview(j));
        if (j.size() < minSize || j.size() > maxSize) {
            fail(path, minSize == maxSize ? "expected " + std::to_string(minSize) +
                                                " elements, got " + std::to_string(j.size())
                                          : "expected " + std::to_string(minSize) + " to " +
                                                std::to_string(maxSize) + " elements, got " +
                                                std::to_string(j.size()));
        }
        return j;
    }
    double number(const Json& j, const std::string& path) const {
        if (!j.is_number()) fail(path, "expected a number, got " + preview(j));
        return j.get<double>();
    }
    float real(const Json& j, const std::string& path) const {
        const double d = number(j, path);
        if (!(std::fabs(d) <= double(std::numeric_limits<float>::max())))
            fail(path, "the number " + preview(j) + " is too large for a 32-bit float");
        return float(d);
    }
    float realIn(const Json& j, const std::string& path, float lo, float hi) const {
        const float v = real(j, path);
        if (!(v >= lo && v <= hi)) {
            std::ostringstream s;
            s << "expected a number in [" << lo << ", " << hi << "], got " << preview(j);
            fail(path, s.str());
        }
        return v;
    }
    long long integer(const Json& j, const std::string& path, long long lo, long long hi) const {
        long long v = 0;
        bool ok = false;
        if (j.is_number_unsigned()) {
            const auto u = j.get<unsigned long long>();
            ok = u <= static_cast<unsigned long long>(std::numeric_limits<long long>::max());
            v = ok ? static_cast<long long>(u) : 0;
        } else if (j.is_number_integer()) {
            v = j.get<long long>();
            ok = true;
        } else if (j.is_number_float()) {
            const double d = j.get<double>();
            ok = std::floor(d) == d && std::fabs(d) < 9.0e15;
            v = ok ? static_cast<long long>(d) : 0;
        } else {
            fail(path, "expected an integer, got " + preview(j));
        }
        if (!ok || v < lo || v > hi) {
            fail(path, "expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi) +
                           ", got " + preview(j));
        }
        return v;
    }
    bool boolean(const Json& j, const std::string& path) const {
        if (!j.is_boolean()) fail(path, "expected true or false, got " + preview(j));
        return j.get<bool>();
    }
    std::string string(const Json& j, const std::string& path) const {
        if (!j.is_string()) fail(path, "expected a string, got " + preview(j));
        return j.get<std::string>();
    }
    glm::vec3 vec3(const Json& j, const std::string& path) const {
        if (!j.is_array() || j.size() != 3)
            fail(path, "expected [x, y, z] (3 numbers), got " + preview(j));
        return {real(j[0], element(path, 0)), real(j[1], element(path, 1)),
                real(j[2], element(path, 2))};
    }
    // [r, g, b] or one number g for [g, g, g]; linear, each >= 0.
    glm::vec3 colour(const Json& j, const std::string& path) const {
        glm::vec3 c;
        if (j.is_number()) {
            c = glm::vec3(real(j, path));
        } else {
            if (!j.is_array() || j.size() != 3)
                fail(path, "expected a colour [r, g, b] or one number, got " + preview(j));
            c = vec3(j, path);
        }
        if (!(c.x >= 0.0f && c.y >= 0.0f && c.z >= 0.0f))
            fail(path, "colour components must be >= 0, got " + preview(j));
        return c;
    }
    template <typename E>
    E choice(const Json& j, const std::string& path, const Names<E>& names) const {
        std::vector<std::string> known;
        for (const auto& [name, value] : names) {
            if (j.is_string() && j.get<std::string>() == name) return value;
            known.push_back(name);
        }
        fail(path, "expected one of " + joined(known) + ", got " + preview(j));
    }

private:
    std::string mFile;
};

// One JSON object being read: its keys checked against the known ones on construction.
class Fields {
public:
    Fields(const Reader& r, const Json& j, std::string path, const std::vector<std::string>& known)
        : mReader(r), mJson(r.object(j, path)), mPath(std::move(path)) {
        for (auto it = mJson.begin(); it != mJson.end(); ++it) {
            if (std::find(known.begin(), known.end(), it.key()) == known.end()) {
                mReader.fail(mPath, "unknown key " + Json(it.key()).dump() +
                                        (known.empty() ? " (this object takes no keys)"
                                                       : " (known keys: " + joined(known) + ")"));
            }
        }
    }
    const Json* find(const char* key) const {
        auto it = mJson.find(key);
        return it == mJson.end() ? nullptr : &*it;
    }
    bool has(const char* key) const { return find(key) != nullptr; }
    std::string at(const char* key) const { return member(mPath, key); }
    const std::string& path() const { return mPath; }
    const Json& json() const { return mJson; }
    const Reader& reader() const { return mReader; }
    const Json& need(const char* key) const {
        if (const Json* v = find(key)) return *v;
        mReader.fail(mPath, std::string("missing required key \"") + key + "\"");
    }

    void get(const char* key, float& out) const {
        if (const Json* v = find(key)) out = mReader.real(*v, at(key));
    }
    void get(const char* key, float& out, float lo, float hi) const {
        if (const Json* v = find(key)) out = mReader.realIn(*v, at(key), lo, hi);
    }
    void get(const char* key, double& out) const {
        if (const Json* v = find(key)) out = mReader.number(*v, at(key));
    }
    void get(const char* key, int& out, long long lo, long long hi) const {
        if (const Json* v = find(key)) out = int(mReader.integer(*v, at(key), lo, hi));
    }
    void get(const char* key, bool& out) const {
        if (const Json* v = find(key)) out = mReader.boolean(*v, at(key));
    }
    void get(const char* key, std::string& out) const {
        if (const Json* v = find(key)) out = mReader.string(*v, at(key));
    }
    void get(const char* key, glm::vec3& out) const {
        if (const Json* v = find(key)) out = mReader.vec3(*v, at(key));
    }
    void getColour(const char* key, glm::vec3& out) const {
        if (const Json* v = find(key)) out = mReader.colour(*v, at(key));
    }
    template <typename E>
    void get(const char* key, E& out, const Names<E>& names) const {
        if (const Json* v = find(key)) out = mReader.choice(*v, at(key), names);
    }

private:
    const Reader& mReader;
    const Json& mJson;
    std::string mPath;
};

// ---- Parsing: comments allowed; duplicate keys and deep nesting refused with their path

// The document, and the order of the keys of "materials" and "meshes" (std::map sorts them).
struct Parsed {
    Json doc;
    std::map<std::string, std::vector<std::string>> order;  // top-level key -> its keys
};

// A first pass over the text without building anything (nlohmann's callback parser is
// quadratic in an object's size): syntax, duplicate keys, nesting depth, key order.
class Checker {
public:
    Checker(const Reader& r, Parsed& out) : mReader(r), mOut(out) {}
    bool null() { return value(); }
    bool boolean(bool) { return value(); }
    bool number_integer(Json::number_integer_t) { return value(); }
    bool number_unsigned(Json::number_unsigned_t) { return value(); }
    bool number_float(Json::number_float_t, const Json::string_t&) { return value(); }
    bool string(Json::string_t&) { return value(); }
    bool binary(Json::binary_t&) { return value(); }
    bool start_object(std::size_t) { return start(false); }
    bool start_array(std::size_t) { return start(true); }
    bool end_object() { return end(); }
    bool end_array() { return end(); }
    bool key(Json::string_t& k) {
        Frame& f = mFrames.back();
        f.key = k;
        if (!f.keys.insert(k).second)
            mReader.fail(pathOf(mFrames.size() - 1), "duplicate key " + Json(k).dump());
        if (mFrames.size() == 2 && (mFrames[0].key == "materials" || mFrames[0].key == "meshes"))
            mOut.order[mFrames[0].key].push_back(k);
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) {
        std::string what = e.what();
        if (auto at = what.find("] "); at != std::string::npos) what = what.substr(at + 2);
        mReader.fail("", "not valid JSON: " + what);
    }

private:
    struct Frame {
        bool array = false;
        std::size_t count = 0;  // arrays: elements started so far
        std::string key;        // objects: the key being read
        std::set<std::string> keys;
    };
    std::string pathOf(std::size_t n) const {
        std::string p;
        for (std::size_t i = 0; i < n; ++i)
            p = mFrames[i].array ? element(p, mFrames[i].count - 1) : member(p, mFrames[i].key);
        return p;
    }
    bool value() {
        if (!mFrames.empty() && mFrames.back().array) ++mFrames.back().count;
        return true;
    }
    bool start(bool array) {
        value();
        if (mFrames.size() >= kMaxNesting) {
            mReader.fail(pathOf(mFrames.size()), "arrays and objects nest deeper than " +
                                                     std::to_string(kMaxNesting) + " levels");
        }
        mFrames.push_back(Frame{array, 0, {}, {}});
        return true;
    }
    bool end() {
        if (!mFrames.empty()) mFrames.pop_back();
        return true;
    }

    const Reader& mReader;
    Parsed& mOut;
    std::vector<Frame> mFrames;
};

Parsed parseJson(const std::string& text, const Reader& r) {
    Parsed out;
    Checker checker(r, out);
    if (!Json::sax_parse(text, &checker, Json::input_format_t::json, true, true))
        r.fail("", "not valid JSON");
    out.doc = Json::parse(text, nullptr, true, true);
    return out;
}

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

// Directions are kept unit length when given so (the loader normalizes what is not).
glm::vec3 unitIfNot(const glm::vec3& d) {
    const float len = glm::length(d);
    return len > 0.0f && std::fabs(len - 1.0f) > 1e-6f ? d / len : d;
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

Camera readCamera(const Reader& r, const Json& j, const std::string& path) {
    const Fields f(r, j, path,
                   {"eye", "centre", "up", "projection", "fovy", "aspect", "near", "far", "left",
                    "right", "bottom", "top"});
    Camera c;
    f.get("eye", c.eye);
    f.get("centre", c.centre);
    f.get("up", c.up);
    readProjectionNumbers(f, c.projection, c.fovyDegrees, c.aspect, c.near, c.far, c.left, c.right,
                          c.bottom, c.top);
    return c;
}

const std::vector<std::string>& optionKeys() {
    static const std::vector<std::string> k = {"size",
                                               "width",
                                               "height",
                                               "time",
                                               "light-only",
                                               "shadows",
                                               "outside",
                                               "map-size",
                                               "bias-constant",
                                               "bias-depth-aware",
                                               "bias-slope",
                                               "bias-units",
                                               "normal-offset",
                                               "receiver-plane",
                                               "cull",
                                               "filter",
                                               "pcf-size",
                                               "light-radius",
                                               "light-angle",
                                               "cascades",
                                               "cascade-lambda",
                                               "cascade-blend",
                                               "debug-view",
                                               "depth-format",
                                               "map-filter",
                                               "blend-shadows",
                                               "shadowed",
                                               "shadow-factor",
                                               "output-encoding",
                                               "fit-to"};
    return k;
}

// The keys given in `j` applied over `o`; RenderOptions::validate()'s sentences as errors.
void applyOptions(const Reader& r, const Json& j, const std::string& path, RenderOptions& o) {
    const Fields f(r, j, path, optionKeys());
    if (const Json* s = f.find("size")) {
        if (f.has("width") || f.has("height"))
            r.fail(path, "give \"size\" or \"width\" and \"height\", not both");
        static const std::regex kSize(R"((\d{1,5})x(\d{1,5}))");
        const std::string text = r.string(*s, f.at("size"));
        std::smatch m;
        if (!std::regex_match(text, m, kSize))
            r.fail(f.at("size"),
                   "expected \"WIDTHxHEIGHT\" such as \"512x512\", got " + preview(*s));
        o.width = std::stoi(m[1].str());
        o.height = std::stoi(m[2].str());
    }
    f.get("width", o.width, 1, 16384);
    f.get("height", o.height, 1, 16384);
    f.get("time", o.time);
    f.get("light-only", o.lightOnly, -1, std::numeric_limits<int>::max());
    f.get("shadows", o.shadow.enabled);
    ShadowOptions& s = o.shadow;
    f.get("outside", s.outside, optionNames<OutsidePolicy>());
    f.get("map-size", s.mapSize, std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
    f.get("bias-constant", s.biasConstant);
    f.get("bias-depth-aware", s.biasDepthAware);
    f.get("bias-slope", s.biasSlope);
    f.get("bias-units", s.biasUnits);
    f.get("normal-offset", s.normalOffset);
    f.get("receiver-plane", s.receiverPlane);
    f.get("cull", s.cull, optionNames<CullMode>());
    f.get("filter", s.filter, optionNames<ShadowFilter>());
    f.get("pcf-size", s.pcfSize, std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
    f.get("light-radius", s.lightRadius);
    f.get("light-angle", s.lightAngle);
    if (const Json* c = f.find("cascades"); c && c->is_string()) {
        if (r.string(*c, f.at("cascades")) != "auto")
            r.fail(f.at("cascades"), "expected \"auto\" or a count 1..4, got " + preview(*c));
        s.cascades = 0;
    } else {
        f.get("cascades", s.cascades, std::numeric_limits<int>::min(),
              std::numeric_limits<int>::max());
    }
    f.get("fit-to", s.fitTo, optionNames<FitTo>());
    f.get("cascade-lambda", s.cascadeLambda);
    f.get("cascade-blend", s.cascadeBlend);
    f.get("debug-view", o.debugView, optionNames<DebugView>());
    f.get("depth-format", s.depthFormat, optionNames<DepthFormat>());
    f.get("map-filter", s.mapFilter, optionNames<MapFilter>());
    f.get("blend-shadows", s.blendShadows, optionNames<BlendShadows>());
    f.get("shadowed", o.shading.shadowedRule, optionNames<ShadowedRule>());
    f.get("shadow-factor", o.shading.shadowFactor);
    f.get("output-encoding", o.shading.output, optionNames<OutputEncoding>());
    if (const auto problems = o.validate(); !problems.empty()) r.fail(path, joined(problems, "; "));
}

// ---- Includes

struct LoadState {
    std::vector<std::string> open;  // canonical paths of the files being read, outermost first
};

std::string canonicalName(const std::string& path) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
    if (ec) p = fs::absolute(path, ec).lexically_normal();
    return p.string();
}

bool looksLikePath(const std::string& s) {
    return s.find('/') != std::string::npos || s.find('.') != std::string::npos;
}

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

Scene parseText(const std::string& text, const std::string& path, LoadState& state);

std::string readFileText(const std::string& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        throw Error(ErrorKind::Io, "cannot read scene file '" + path + "': no such file");
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) throw Error(ErrorKind::Io, "cannot read scene file '" + path + "': " + ec.message());
    if (size > kMaxFileBytes) {
        throw Error(ErrorKind::InvalidInput, path + ": the file is " + std::to_string(size >> 20) +
                                                 " MiB; scene files are limited to " +
                                                 std::to_string(kMaxFileBytes >> 20) +
                                                 " MiB (put geometry in a model file)");
    }
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) throw Error(ErrorKind::Io, "cannot read scene file '" + path + "'");
    return text.str();
}

Scene loadFile(const std::string& path, LoadState& state) {
    return parseText(readFileText(path), path, state);
}

// The included scene, as a built-in name or a path relative to the including file's folder.
Scene loadInclude(const Reader& r, const std::string& name, const std::string& at,
                  const std::string& folder, LoadState& state) {
    if (!looksLikePath(name)) {
        try {
            return builtinScene(name);
        } catch (const Error& e) {
            r.fail(at, e.what());
        }
    }
    const fs::path p = fs::path(name).is_absolute() ? fs::path(name) : fs::path(folder) / name;
    const std::string file = p.lexically_normal().string();
    std::error_code ec;
    if (!fs::exists(file, ec)) r.fail(at, "no such file '" + file + "'");
    const std::string ext = lowerExtension(file);
    try {
        if (ext != ".json") return loadScene(file);
        const std::string canonical = canonicalName(file);
        const auto again = std::find(state.open.begin(), state.open.end(), canonical);
        if (again != state.open.end()) {
            std::string chain;
            for (auto it = again; it != state.open.end(); ++it)
                chain += fs::path(*it).filename().string() + " -> ";
            r.fail(at, "include cycle: " + chain + fs::path(canonical).filename().string());
        }
        if (state.open.size() >= kMaxIncludeDepth) {
            r.fail(at, "includes nest deeper than " + std::to_string(kMaxIncludeDepth) + " files");
        }
        state.open.push_back(canonical);
        Scene s = loadFile(file, state);
        state.open.pop_back();
        return s;
    } catch (const Error& e) {
        const std::string what = e.what();
        if (what.rfind(r.file() + ": ", 0) == 0) throw;  // ours, already placed
        throw Error(e.kind(), what + " (included by " + r.file() + ": " + at + ")");
    }
}

// A scene loaded by an include, placed by `t` and appended to `out`.
void appendInclude(Scene& out, Scene s, const glm::mat4& t) {
    const bool moved = t != glm::mat4(1.0f);
    const auto meshBase = std::uint32_t(out.meshes.size());
    const auto materialBase = std::uint32_t(out.materials.size());
    const int textureBase = int(out.textures.size());
    for (Mesh& m : s.meshes)
        out.meshes.push_back(std::move(m));
    for (Texture& tex : s.textures)
        out.textures.push_back(std::move(tex));
    for (Material m : s.materials) {
        if (m.baseColourTexture >= 0) m.baseColourTexture += textureBase;
        out.materials.push_back(std::move(m));
    }
    for (Object o : s.objects) {
        o.mesh += meshBase;
        o.material += materialBase;
        if (moved) {
            o.worldFromModel = t * o.worldFromModel;
            o.spin.pivot = transformPoint(t, o.spin.pivot);
            o.spin.axis = glm::mat3(t) * o.spin.axis;
        }
        out.objects.push_back(std::move(o));
    }
}

void placeLight(Light& l, const glm::mat4& t) {
    if (t == glm::mat4(1.0f)) return;
    l.position = transformPoint(t, l.position);
    l.direction = glm::mat3(t) * l.direction;
    if (glm::length(l.direction) > 0.0f) l.direction = glm::normalize(l.direction);
    l.shadowCamera.target = transformPoint(t, l.shadowCamera.target);
    l.shadowCamera.up = glm::mat3(t) * l.shadowCamera.up;
}

void placeCamera(Camera& c, const glm::mat4& t) {
    if (t == glm::mat4(1.0f)) return;
    c.eye = transformPoint(t, c.eye);
    c.centre = transformPoint(t, c.centre);
    c.up = glm::mat3(t) * c.up;
}

// The warnings model loaders give when they add what the including file replaces.
const char* const kDefaultSunWarning = "no lights: a default sun was added";
const char* const kFramedCameraWarning = "no camera: one framing the scene was added";

Scene parseText(const std::string& text, const std::string& path, LoadState& state) {
    const Reader r(path);
    if (text.size() > kMaxFileBytes)
        r.fail("", "scene files are limited to " + std::to_string(kMaxFileBytes >> 20) + " MiB");
    Parsed parsed = parseJson(text, r);
    const Json& doc = parsed.doc;
    const Fields root(
        r, doc, "",
        {"gnomon-scene", "name", "description", "include", "materials", "meshes", "objects",
         "lights", "camera", "ambient", "ground", "options", "textbook-options"});
    if (!doc.contains("gnomon-scene"))
        r.fail("", "missing required key \"gnomon-scene\" (the format version, 1)");
    const long long version = r.integer(doc["gnomon-scene"], "gnomon-scene", 0, 1000000);
    if (version != kVersion) {
        r.fail("gnomon-scene", "this gnomon reads format version " + std::to_string(kVersion) +
                                   ", got " + std::to_string(version));
    }
    const std::string folder = fs::path(path).parent_path().string();

    Scene out;
    out.name = fs::path(path).stem().string();
    root.get("name", out.name);
    root.get("description", out.description);

    // Includes: their geometry always; their lights and camera unless the file has its own.
    std::vector<Light> includedLights;
    std::optional<Camera> includedCamera;
    std::optional<RenderOptions> baseOptions, baseTextbook;
    std::optional<glm::vec3> includedAmbient;
    if (const Json* inc = root.find("include")) {
        r.array(*inc, root.at("include"), 0, kMaxIncludes);
        for (std::size_t i = 0; i < inc->size(); ++i) {
            const std::string at = element(root.at("include"), i);
            const Fields f(r, (*inc)[i], at, {"scene", "transform", "lights", "camera"});
            const std::string name = r.string(f.need("scene"), f.at("scene"));
            glm::mat4 t(1.0f);
            if (const Json* tj = f.find("transform")) t = readTransform(r, *tj, f.at("transform"));
            bool useLights = true, useCamera = true;
            f.get("lights", useLights);
            f.get("camera", useCamera);
            useLights = useLights && !root.has("lights");
            useCamera = useCamera && !root.has("camera");
            Scene s = loadInclude(r, name, f.at("scene"), folder, state);
            if (i == 0) {
                baseOptions = s.options;
                baseTextbook = s.textbookOptions;
                includedAmbient = s.ambient;
            }
            for (const std::string& w : s.warnings) {
                if ((!useLights && w == kDefaultSunWarning) ||
                    (!useCamera && w == kFramedCameraWarning)) {
                    continue;
                }
                out.warnings.push_back(name + ": " + w);
            }
            if (useLights) {
                for (Light l : s.lights) {
                    placeLight(l, t);
                    includedLights.push_back(std::move(l));
                }
            }
            if (useCamera && !includedCamera) {
                placeCamera(s.camera, t);
                includedCamera = s.camera;
            }
            appendInclude(out, std::move(s), t);
        }
    }

    // Materials by name, in file order.
    std::map<std::string, std::uint32_t> materials;
    std::vector<std::string> materialNames;
    if (const Json* mj = root.find("materials")) {
        r.object(*mj, root.at("materials"));
        if (mj->size() > kMaxItems) r.fail(root.at("materials"), "too many materials");
        for (const std::string& name : parsed.order["materials"]) {
            materials[name] = std::uint32_t(out.materials.size());
            materialNames.push_back(name);
            out.materials.push_back(
                readMaterial(r, mj->at(name), member(root.at("materials"), name), name));
        }
    }
    std::optional<std::uint32_t> defaultMaterial;

    // Shared meshes by name, in file order.
    std::map<std::string, std::uint32_t> meshes;
    std::vector<std::string> meshNames;
    if (const Json* mj = root.find("meshes")) {
        r.object(*mj, root.at("meshes"));
        if (mj->size() > kMaxItems) r.fail(root.at("meshes"), "too many meshes");
        for (const std::string& name : parsed.order["meshes"]) {
            const Json& value = mj->at(name);
            const std::string at = member(root.at("meshes"), name);
            const std::string shape = peekShape(r, value, at);
            if (shape.empty())
                r.fail(at, "missing required key \"shape\" (" + joined(shapeNames()) + ")");
            std::vector<std::string> known = shapeKeys(shape);
            known.insert(known.begin(), "shape");
            const Fields f(r, value, at, known);
            meshes[name] = std::uint32_t(out.meshes.size());
            meshNames.push_back(name);
            out.meshes.push_back(readShape(f, shape, name));
        }
    }

    // The index of a named material or mesh; an unknown name is an error listing the known.
    auto named = [&](const Json& value, const std::string& path, const char* kind, const char* list,
                     const std::map<std::string, std::uint32_t>& byName,
                     const std::vector<std::string>& names) {
        const std::string name = r.string(value, path);
        const auto found = byName.find(name);
        if (found == byName.end()) {
            r.fail(path,
                   std::string("no ") + kind + " " + Json(name).dump() + " in " + list +
                       (names.empty() ? " (there are none)" : " (known: " + joined(names) + ")"));
        }
        return found->second;
    };

    if (const Json* oj = root.find("objects")) {
        r.array(*oj, root.at("objects"), 0, kMaxItems);
        for (std::size_t i = 0; i < oj->size(); ++i) {
            const std::string at = element(root.at("objects"), i);
            const std::string shape = peekShape(r, (*oj)[i], at);
            std::vector<std::string> known = {
                "name",      "mesh", "shape",         "material",
                "transform", "spin", "casts-shadows", "receives-shadows"};
            if (!shape.empty()) {
                for (const std::string& k : shapeKeys(shape))
                    known.push_back(k);
            }
            const Fields f(r, (*oj)[i], at, known);
            Object o;
            if (const Json* mj = f.find("mesh")) {
                if (!shape.empty()) r.fail(at, "give \"mesh\" or \"shape\", not both");
                o.mesh = named(*mj, f.at("mesh"), "mesh", "meshes", meshes, meshNames);
                o.name = r.string(*mj, f.at("mesh"));
            } else if (shape.empty()) {
                r.fail(at, "needs \"shape\" (" + joined(shapeNames()) +
                               ") or \"mesh\" (a name from meshes)");
            } else {
                o.name = "object " + std::to_string(i);
            }
            f.get("name", o.name);
            if (!shape.empty()) {
                o.mesh = std::uint32_t(out.meshes.size());
                out.meshes.push_back(readShape(f, shape, o.name));
            }
            if (const Json* mj = f.find("material")) {
                o.material =
                    named(*mj, f.at("material"), "material", "materials", materials, materialNames);
            } else {
                if (!defaultMaterial) {
                    defaultMaterial = std::uint32_t(out.materials.size());
                    Material m;
                    m.name = "default";
                    out.materials.push_back(m);
                }
                o.material = *defaultMaterial;
            }
            if (const Json* tj = f.find("transform"))
                o.worldFromModel = readTransform(r, *tj, f.at("transform"));
            if (const Json* sj = f.find("spin")) {
                const Fields s(r, *sj, f.at("spin"), {"axis", "degrees-per-second", "pivot"});
                s.get("axis", o.spin.axis);
                s.get("degrees-per-second", o.spin.degreesPerSecond);
                s.get("pivot", o.spin.pivot);
                if (o.spin.degreesPerSecond != 0.0f && !(glm::length(o.spin.axis) > 0.0f))
                    r.fail(s.at("axis"), "a spin needs a non-zero axis");
            }
            f.get("casts-shadows", o.castsShadows);
            f.get("receives-shadows", o.receivesShadows);
            out.objects.push_back(std::move(o));
        }
    }

    if (const Json* lj = root.find("lights")) {
        r.array(*lj, root.at("lights"), 0, kMaxLights);
        for (std::size_t i = 0; i < lj->size(); ++i)
            out.lights.push_back(readLight(r, (*lj)[i], element(root.at("lights"), i), i));
    } else {
        out.lights = std::move(includedLights);
        if (out.lights.empty()) addDefaultSun(out);
    }

    if (const Json* cj = root.find("camera")) {
        out.camera = readCamera(r, *cj, root.at("camera"));
    } else if (includedCamera) {
        out.camera = *includedCamera;
    } else if (!out.objects.empty()) {
        frameWithCamera(out, worldBounds(out, meshBounds(out), 0.0, false));
    }

    if (const Json* aj = root.find("ambient")) {
        out.ambient = r.colour(*aj, root.at("ambient"));
    } else if (includedAmbient) {
        out.ambient = *includedAmbient;
    }

    // After the camera is framed: the ground is not part of what it frames.
    if (const Json* gj = root.find("ground"); gj && r.boolean(*gj, root.at("ground"))) {
        addGround(out);
    }

    out.options = baseOptions.value_or(RenderOptions{});
    if (const Json* oj = root.find("options"))
        applyOptions(r, *oj, root.at("options"), out.options);
    out.textbookOptions = baseTextbook;
    if (const Json* tj = root.find("textbook-options")) {
        RenderOptions t = baseTextbook.value_or(out.options);
        applyOptions(r, *tj, root.at("textbook-options"), t);
        out.textbookOptions = t;
    }

    if (const auto problems = out.validate(); !problems.empty()) r.fail("", joined(problems, "; "));
    return out;
}

// ---- Writing

// The shortest decimal that reads back as the same float (0.1f is written 0.1, not
// 0.10000000149011612).
OJson number(float v) {
    if (!std::isfinite(v)) return OJson(double(v));  // refused by checkFinite
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof buf, v);
    *res.ptr = '\0';
    return OJson(std::strtod(buf, nullptr));
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
    j["shadow-map-size"] = l.shadowMapSize;
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

OJson optionsJson(const RenderOptions& o) {
    const ShadowOptions& s = o.shadow;
    OJson j;
    j["size"] = std::to_string(o.width) + "x" + std::to_string(o.height);
    j["time"] = o.time;
    j["light-only"] = o.lightOnly;
    j["shadows"] = s.enabled;
    j["outside"] = toString(s.outside);
    j["map-size"] = s.mapSize;
    j["bias-constant"] = number(s.biasConstant);
    j["bias-depth-aware"] = number(s.biasDepthAware);
    j["bias-slope"] = number(s.biasSlope);
    j["bias-units"] = number(s.biasUnits);
    j["normal-offset"] = number(s.normalOffset);
    j["receiver-plane"] = s.receiverPlane;
    j["cull"] = toString(s.cull);
    j["filter"] = toString(s.filter);
    j["pcf-size"] = s.pcfSize;
    j["light-radius"] = number(s.lightRadius);
    j["light-angle"] = number(s.lightAngle);
    if (s.cascades == 0) {
        j["cascades"] = "auto";
    } else {
        j["cascades"] = s.cascades;
    }
    j["fit-to"] = toString(s.fitTo);
    j["cascade-lambda"] = number(s.cascadeLambda);
    j["cascade-blend"] = number(s.cascadeBlend);
    j["debug-view"] = toString(o.debugView);
    j["depth-format"] = toString(s.depthFormat);
    j["map-filter"] = toString(s.mapFilter);
    j["blend-shadows"] = toString(s.blendShadows);
    j["shadowed"] = toString(o.shading.shadowedRule);
    j["shadow-factor"] = number(o.shading.shadowFactor);
    j["output-encoding"] = toString(o.shading.output);
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

Scene parseSceneFile(const std::string& text, const std::string& path) {
    LoadState state;
    state.open.push_back(canonicalName(path));
    try {
        return parseText(text, path, state);
    } catch (const Json::exception& e) {  // a bug of ours rather than of the file; still say where
        throw Error(ErrorKind::InvalidInput, path + ": " + e.what());
    }
}

Scene loadSceneFile(const std::string& path) {
    return parseSceneFile(readFileText(path), path);
}

void saveSceneFile(const std::string& path, const std::string& source, const Scene& scene,
                   const RenderOptions& options, bool ground) {
    std::string include = source;
    if (looksLikePath(source)) {
        const fs::path folder = fs::absolute(fs::path(path)).parent_path().lexically_normal();
        const fs::path model = fs::absolute(fs::path(source)).lexically_normal();
        const fs::path relative = model.lexically_relative(folder);
        include = relative.empty() ? model.generic_string() : relative.generic_string();
    }
    OJson doc;
    doc["gnomon-scene"] = kVersion;
    doc["name"] = scene.name;
    doc["description"] = scene.description;
    doc["include"] =
        OJson::array({OJson{{"scene", include}, {"lights", false}, {"camera", false}}});
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

}  // namespace gnomon
