// The strict JSON layer of scene files: limits, JSON paths for messages, enum names, typed
// reads that fail naming the file and the JSON path, and a parse that refuses duplicate keys.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "gnomon/Error.h"
#include "gnomon/Options.h"
#include "gnomon/Scene.h"

namespace gnomon::scenefile {

using Json = nlohmann::json;           // reading: std::map, no quadratic inserts
using OJson = nlohmann::ordered_json;  // writing: keys in a readable order

inline constexpr int kVersion = 1;
inline constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(64) << 20;
inline constexpr std::size_t kMaxIncludeDepth = 8;  // files open at once: this one and 7 includes
inline constexpr std::size_t kMaxIncludes = 64;
inline constexpr std::size_t kMaxLights = 256;         // the renderer's lights in one main pass
inline constexpr std::size_t kMaxItems = 1u << 20;     // materials, meshes, objects
inline constexpr std::size_t kMaxVertices = 1u << 24;  // per mesh
inline constexpr std::size_t kMaxNesting = 64;         // JSON arrays and objects inside each other

// ---- JSON paths for messages: lights[2].type, materials["vertex colour"].colour

std::string member(const std::string& path, const std::string& key);
std::string element(const std::string& path, std::size_t i);
// `v` shortened for a message: "an object", "an array", or its JSON cut at 60 characters.
std::string preview(const Json& v);
std::string joined(const std::vector<std::string>& items, const char* separator = ", ");

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

inline const Names<LightType> kLightTypes = optionNames<LightType>();
inline const Names<Projection> kProjections = optionNames<Projection>();
inline const Names<ShadowCameraPolicy> kPolicies = optionNames<ShadowCameraPolicy>();
inline const Names<AlphaMode> kAlphaModes = {
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

// The document of `text`, or an error naming the file (and the path of a duplicate key).
Parsed parseJson(const std::string& text, const Reader& r);

}  // namespace gnomon::scenefile
