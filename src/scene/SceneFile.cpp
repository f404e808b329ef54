// Scene description files (docs/scene-file.md). The reader is strict: an unknown key, a wrong
// type, a bad name or an out-of-range value is an error naming the file and the JSON path, so
// a typo never passes silently. The writer saves what a viewer tuned over an included scene.
// Here: includes and the order of the reading; the parts in SceneFileRead, the writer in
// SceneFileWrite, the strict JSON layer in SceneFileJson.
#include "gnomon/SceneFile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "gnomon/Error.h"
#include "scene/ModelFinish.h"
#include "scene/SceneFileJson.h"
#include "scene/SceneFileRead.h"
#include "scene/SceneFileWrite.h"
#include "scene/SceneUtil.h"

namespace gnomon {
namespace {

using namespace scenefile;
namespace fs = std::filesystem;

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

Scene loadFile(const std::string& path, LoadState& state) {
    return parseText(readFileText(path, "scene file"), path, state);
}

// The included scene, as a built-in name or a path relative to the including file's folder;
// a model file turned so that `up` stands up (built-in scenes and scene files are upright).
Scene loadInclude(const Reader& r, const std::string& name, const std::string& at,
                  const std::string& folder, UpAxis up, LoadState& state) {
    if (!looksLikePath(name)) {
        if (up != UpAxis::Y) r.fail(at, "\"up\" applies to model files, not built-in scenes");
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
        if (ext != ".json") return loadScene(file, up);
        if (up != UpAxis::Y) r.fail(at, "\"up\" applies to model files, not scene files");
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

// How much `t` stretches lengths along `direction` (1 for a zero direction).
float stretchAlong(const glm::mat4& t, const glm::vec3& direction) {
    const float length = glm::length(direction);
    return length > 0.0f ? glm::length(glm::mat3(t) * (direction / length)) : 1.0f;
}

// A camera's distances (near, far) and orthographic volume go with the transform's scale along
// its view and across it: an included model scaled by 1000 keeps the framing it came with.
template <typename C>
void scaleVolume(C& c, const glm::mat4& t, const glm::vec3& forward, const glm::vec3& up) {
    const float along = stretchAlong(t, forward);
    const glm::vec3 side = glm::cross(forward, up);
    const float across = stretchAlong(t, side), upward = stretchAlong(t, glm::cross(side, forward));
    c.near *= along;
    c.far *= along;
    c.left *= across;
    c.right *= across;
    c.bottom *= upward;
    c.top *= upward;
}

// The light moves with the transform and its distances scale with it: range, the attenuation's
// distance terms (so the light falls off as it did across the scaled model) and a manual or
// course shadow camera's volume.
void placeLight(Light& l, const glm::mat4& t) {
    if (t == glm::mat4(1.0f)) return;
    const float scale = std::cbrt(std::abs(glm::determinant(glm::mat3(t))));
    const glm::vec3 toTarget = l.shadowCamera.target - l.position;
    scaleVolume(l.shadowCamera, t, glm::length(toTarget) > 0.0f ? toTarget : l.direction,
                l.shadowCamera.up);
    l.position = transformPoint(t, l.position);
    l.direction = glm::mat3(t) * l.direction;
    if (glm::length(l.direction) > 0.0f) l.direction = glm::normalize(l.direction);
    l.shadowCamera.target = transformPoint(t, l.shadowCamera.target);
    l.shadowCamera.up = glm::mat3(t) * l.shadowCamera.up;
    l.range *= scale;
    l.attenuation.linear /= scale;
    l.attenuation.quadratic /= scale * scale;
}

void placeCamera(Camera& c, const glm::mat4& t) {
    if (t == glm::mat4(1.0f)) return;
    scaleVolume(c, t, c.centre - c.eye, c.up);
    c.eye = transformPoint(t, c.eye);
    c.centre = transformPoint(t, c.centre);
    c.up = glm::mat3(t) * c.up;
}

// The warnings model loaders give when they add what the including file replaces.
const char* const kFramedCameraWarning = "no camera: one framing the scene was added";

// What the includes bring that the file may replace: lights, camera, options and ambient (the
// options and ambient of the first include).
struct Included {
    std::vector<Light> lights;
    std::optional<Camera> camera;
    std::optional<RenderOptions> options, textbook;
    std::optional<glm::vec3> ambient;
};

// The materials and shared meshes the file names: index by name, and the names in file order.
struct Library {
    std::map<std::string, std::uint32_t> materials;
    std::vector<std::string> materialNames;
    std::map<std::string, std::uint32_t> meshes;
    std::vector<std::string> meshNames;
};

void checkVersion(const Reader& r, const Json& doc) {
    if (!doc.contains("gnomon-scene"))
        r.fail("", "missing required key \"gnomon-scene\" (the format version, 1)");
    const long long version = r.integer(doc["gnomon-scene"], "gnomon-scene", 0, 1000000);
    if (version != kVersion) {
        r.fail("gnomon-scene", "this gnomon reads format version " + std::to_string(kVersion) +
                                   ", got " + std::to_string(version));
    }
}

// Includes: their geometry always; their lights and camera unless the file has its own.
Included readIncludes(const Fields& root, const std::string& folder, LoadState& state, Scene& out) {
    const Reader& r = root.reader();
    Included included;
    if (const Json* inc = root.find("include")) {
        r.array(*inc, root.at("include"), 0, kMaxIncludes);
        for (std::size_t i = 0; i < inc->size(); ++i) {
            const std::string at = element(root.at("include"), i);
            const Fields f(r, (*inc)[i], at,
                           {"scene", "up", "transform", "lights", "camera", "casts-shadows",
                            "receives-shadows"});
            const std::string name = r.string(f.need("scene"), f.at("scene"));
            const UpAxis up = f.find("up") ? readUpAxis(r, *f.find("up"), f.at("up")) : UpAxis::Y;
            glm::mat4 t(1.0f);
            if (const Json* tj = f.find("transform")) t = readTransform(r, *tj, f.at("transform"));
            bool useLights = true, useCamera = true;
            f.get("lights", useLights);
            f.get("camera", useCamera);
            useLights = useLights && !root.has("lights");
            useCamera = useCamera && !root.has("camera");
            Scene s = loadInclude(r, name, f.at("scene"), folder, up, state);
            if (i == 0) {
                included.options = s.options;
                included.textbook = s.textbookOptions;
                included.ambient = s.ambient;
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
                    included.lights.push_back(std::move(l));
                }
            }
            if (useCamera && !included.camera) {
                placeCamera(s.camera, t);
                included.camera = s.camera;
            }
            // Given, these set every included object's flags (a model that only casts, say).
            for (const char* key : {"casts-shadows", "receives-shadows"}) {
                if (!f.has(key)) continue;
                bool on = true;
                f.get(key, on);
                for (Object& o : s.objects)
                    (key[0] == 'c' ? o.castsShadows : o.receivesShadows) = on;
            }
            appendInclude(out, std::move(s), t);
        }
    }
    return included;
}

// Materials and shared meshes by name, in file order.
Library readLibrary(const Fields& root, Parsed& parsed, Scene& out) {
    const Reader& r = root.reader();
    Library lib;
    if (const Json* mj = root.find("materials")) {
        r.object(*mj, root.at("materials"));
        if (mj->size() > kMaxItems) r.fail(root.at("materials"), "too many materials");
        for (const std::string& name : parsed.order["materials"]) {
            lib.materials[name] = std::uint32_t(out.materials.size());
            lib.materialNames.push_back(name);
            out.materials.push_back(
                readMaterial(r, mj->at(name), member(root.at("materials"), name), name));
        }
    }
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
            lib.meshes[name] = std::uint32_t(out.meshes.size());
            lib.meshNames.push_back(name);
            out.meshes.push_back(readShape(f, shape, name));
        }
    }
    return lib;
}

// The index of a named material or mesh; an unknown name is an error listing the known.
std::uint32_t named(const Reader& r, const Json& value, const std::string& path, const char* kind,
                    const char* list, const std::map<std::string, std::uint32_t>& byName,
                    const std::vector<std::string>& names) {
    const std::string name = r.string(value, path);
    const auto found = byName.find(name);
    if (found == byName.end()) {
        r.fail(path, std::string("no ") + kind + " " + Json(name).dump() + " in " + list +
                         (names.empty() ? " (there are none)" : " (known: " + joined(names) + ")"));
    }
    return found->second;
}

// Objects: a shared mesh or a shape of their own, a material (or a default one), placement.
void readObjects(const Fields& root, const Library& lib, Scene& out) {
    const Reader& r = root.reader();
    std::optional<std::uint32_t> defaultMaterial;
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
                o.mesh = named(r, *mj, f.at("mesh"), "mesh", "meshes", lib.meshes, lib.meshNames);
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
                o.material = named(r, *mj, f.at("material"), "material", "materials", lib.materials,
                                   lib.materialNames);
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
}

// Lights, camera, ambient, ground and options: the file's own, else the included ones, else
// defaults (a sun; a camera framing the objects).
void readLightingAndOptions(const Fields& root, Included included, Scene& out) {
    const Reader& r = root.reader();
    const Json* lj = root.find("lights");
    if (lj) {
        r.array(*lj, root.at("lights"), 0, kMaxLights);
        for (std::size_t i = 0; i < lj->size(); ++i)
            out.lights.push_back(readLight(r, (*lj)[i], element(root.at("lights"), i), i));
    } else {
        out.lights = std::move(included.lights);
    }

    const Json* cj = root.find("camera");
    if (cj) {
        out.camera = readCamera(r, *cj, root.at("camera"));
    } else if (included.camera) {
        out.camera = *included.camera;
    } else if (!out.objects.empty()) {
        frameWithCamera(out, worldBounds(out, meshBounds(out), 0.0, false));
    }
    if (!lj && out.lights.empty()) addDefaultSun(out);  // over the final camera's shoulder

    if (const Json* aj = root.find("ambient")) {
        out.ambient = r.colour(*aj, root.at("ambient"));
    } else if (included.ambient) {
        out.ambient = *included.ambient;
    }

    // After the camera is framed: the ground is not part of what it frames.
    if (const Json* gj = root.find("ground"); gj && r.boolean(*gj, root.at("ground"))) {
        addGround(out);
    }
    fitPlanesLeftOut(cj, lj, out);  // once the ground is in

    out.options = included.options.value_or(RenderOptions{});
    if (const Json* oj = root.find("options"))
        applyOptions(r, *oj, root.at("options"), out.options);
    out.textbookOptions = included.textbook;
    if (const Json* tj = root.find("textbook-options")) {
        RenderOptions t = included.textbook.value_or(out.options);
        if (!included.textbook) t.shadow.shadowRays = ShadowRayMode::Off;  // a textbook's maps
        applyOptions(r, *tj, root.at("textbook-options"), t);
        out.textbookOptions = t;
    }
}

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
    checkVersion(r, doc);
    const std::string folder = fs::path(path).parent_path().string();

    Scene out;
    out.name = fs::path(path).stem().string();
    root.get("name", out.name);
    root.get("description", out.description);
    Included included = readIncludes(root, folder, state, out);
    const Library library = readLibrary(root, parsed, out);
    readObjects(root, library, out);
    readLightingAndOptions(root, std::move(included), out);

    if (const auto problems = out.validate(); !problems.empty()) r.fail("", joined(problems, "; "));
    return out;
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
    return parseSceneFile(readFileText(path, "scene file"), path);
}

void saveSceneFile(const std::string& path, const std::string& source, const Scene& scene,
                   const RenderOptions& options, bool ground, UpAxis up) {
    std::string include = source;
    if (looksLikePath(source)) {
        const fs::path folder = fs::absolute(fs::path(path)).parent_path().lexically_normal();
        const fs::path model = fs::absolute(fs::path(source)).lexically_normal();
        const fs::path relative = model.lexically_relative(folder);
        include = relative.empty() ? model.generic_string() : relative.generic_string();
    }
    writeSceneFile(path, include, scene, options, ground, up);
}

namespace scenefile {

std::string readFileText(const std::string& path, const std::string& what) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        throw Error(ErrorKind::InvalidInput,
                    "cannot read " + what + " '" + path + "': no such file");
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) throw Error(ErrorKind::Io, "cannot read " + what + " '" + path + "': " + ec.message());
    if (size > kMaxFileBytes) {
        throw Error(ErrorKind::InvalidInput, path + ": the file is " + std::to_string(size >> 20) +
                                                 " MiB; " + what + "s are limited to " +
                                                 std::to_string(kMaxFileBytes >> 20) + " MiB");
    }
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) throw Error(ErrorKind::Io, "cannot read " + what + " '" + path + "'");
    return text.str();
}

}  // namespace scenefile

}  // namespace gnomon
