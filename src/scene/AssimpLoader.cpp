// Other model formats into the scene model through assimp: the file checks, the importer call
// (confined to the model's folder), node traversal, lights and cameras, and the steps in order;
// materials are read in AssimpMaterials.cpp, meshes in AssimpMeshes.cpp.
#include "scene/AssimpLoader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <assimp/DefaultIOSystem.h>
#include <assimp/config.h>
#include <assimp/importerdesc.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include "gnomon/Error.h"
#include "scene/AssimpParts.h"
#include "scene/ModelFinish.h"
#include "scene/SceneUtil.h"

namespace gnomon {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
    for (char& c : s)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// assimp's reason made one short line: its parsers quote the text they stopped at, up to a
// few hundred characters of the file with its line breaks as '?' (OpenSCAD's broken STL
// test files), so each quotation is cut to its first kQuoted characters and runs of spaces
// are closed up.
std::string tidied(const std::string& why) {
    constexpr std::size_t kQuoted = 40;
    std::string out;
    bool quoted = false;
    std::size_t inQuote = 0;
    for (char c : why) {
        if (c == '\n' || c == '\r' || c == '\t') c = ' ';
        if (c == '"') {
            if (quoted && inQuote > kQuoted) out += "...";
            quoted = !quoted;
            inQuote = 0;
        } else if (quoted && ++inQuote > kQuoted) {
            continue;
        }
        if (c == ' ' && !out.empty() && out.back() == ' ') continue;
        out += c;
    }
    while (!out.empty() && out.back() == ' ')
        out.pop_back();
    return out;
}

// A file that starts as a zip archive does (the compressed form the AMF standard allows).
bool zipped(const std::string& path) {
    char magic[4] = {};
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return false;
    const std::size_t got = std::fread(magic, 1, sizeof magic, f);
    std::fclose(f);
    return got == sizeof magic && std::memcmp(magic, "PK\x03\x04", sizeof magic) == 0;
}

}  // namespace

namespace assimp_parts {

bool inside(const fs::path& root, const std::string& path, fs::path& resolved) {
    std::error_code ec;
    resolved = fs::weakly_canonical(fs::absolute(fs::path(path), ec), ec);
    if (ec) return false;
    const auto [rootEnd, _] =
        std::mismatch(root.begin(), root.end(), resolved.begin(), resolved.end());
    return rootEnd == root.end();
}

namespace {

constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(2) << 30;  // 2 GiB, as for glTF
constexpr int kMaxDepth = 256;                                     // node nesting

// assimp's file access, refusing anything outside the model's folder (an OBJ's mtllib, a
// 3DS or FBX texture, an X file's includes...) and any writing.
class FolderIO : public Assimp::DefaultIOSystem {
public:
    explicit FolderIO(fs::path root) : mRoot(std::move(root)) {}
    using DefaultIOSystem::Exists;
    using DefaultIOSystem::Open;
    bool Exists(const char* file) const override {
        fs::path resolved;
        if (!inside(mRoot, file, resolved)) {
            refuse(file);
            return false;
        }
        return DefaultIOSystem::Exists(resolved.c_str());
    }
    Assimp::IOStream* Open(const char* file, const char* mode) override {
        fs::path resolved;
        if (std::strpbrk(mode, "wa+") != nullptr || !inside(mRoot, file, resolved)) {
            refuse(file);
            return nullptr;
        }
        return DefaultIOSystem::Open(resolved.c_str(), mode);
    }
    const std::string& refused() const { return mRefused; }

private:
    void refuse(const char* file) const {
        if (mRefused.empty()) {
            mRefused = "'" + std::string(file) + "' lies outside the model's folder '" +
                       mRoot.string() + "' (no absolute paths or .. escapes)";
        }
    }
    fs::path mRoot;
    mutable std::string mRefused;  // the first refused access, for the message
};

// Refuses a path that is not a regular file (Io) or is too large (InvalidInput).
void checkFile(const std::string& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        throw Error(ErrorKind::InvalidInput, "cannot load scene '" + path + "': no such file");
    }
    if (fs::file_size(path, ec) > kMaxFileBytes) {
        throw Error(ErrorKind::InvalidInput, path + ": larger than 2 GiB");
    }
}

void configure(Assimp::Importer& importer) {
    importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
    importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, kCreaseDegrees);
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, 0);  // points and lines: we warn
    // FindInvalidData would also drop a set of texture coordinates that are all equal.
    importer.SetPropertyBool(AI_CONFIG_PP_FID_IGNORE_TEXTURECOORDS, true);
}

// Keeps the items a node places (a light or camera is placed by the node of its name),
// deleting the others; returns how many are kept.
template <typename T>
unsigned keepPlaced(const aiNode& root, T** items, unsigned count) {
    unsigned kept = 0;
    for (unsigned i = 0; i < count; ++i) {
        if (root.FindNode(items[i]->mName)) {
            items[kept++] = items[i];
        } else {
            delete items[i];
        }
    }
    return kept;
}

// What gnomon does not use and assimp's validation refuses, dropped with a warning before it
// validates (the importer owns the scene it returned, made mutable): animations (gnomon
// draws the pose the nodes give; a key past its clip's end, as in Minetest's .b3d carts and
// characters, refused the whole model), and lights and cameras no node places (an OpenGEX
// light object no light node uses, as in assimp-testmodels' collada.ogex).
void dropUnused(aiScene& owned, const std::string& file, Scene& scene) {
    if (owned.mNumAnimations > 0) {
        for (unsigned i = 0; i < owned.mNumAnimations; ++i)
            delete owned.mAnimations[i];
        delete[] owned.mAnimations;
        owned.mAnimations = nullptr;
        owned.mNumAnimations = 0;
        scene.warnings.push_back(file +
                                 ": its animations are not played (drawn as the nodes pose it)");
    }
    if (!owned.mRootNode) return;
    const unsigned lights = owned.mNumLights, cameras = owned.mNumCameras;
    owned.mNumLights = keepPlaced(*owned.mRootNode, owned.mLights, lights);
    owned.mNumCameras = keepPlaced(*owned.mRootNode, owned.mCameras, cameras);
    // An array left empty is freed here: assimp's destructor may free only one with a count.
    if (owned.mNumLights == 0) {
        delete[] owned.mLights;
        owned.mLights = nullptr;
    }
    if (owned.mNumCameras == 0) {
        delete[] owned.mCameras;
        owned.mCameras = nullptr;
    }
    const unsigned dropped = lights + cameras - owned.mNumLights - owned.mNumCameras;
    if (dropped > 0) {
        scene.warnings.push_back(file + ": " + std::to_string(dropped) +
                                 " light(s) or camera(s) that no node places, skipped");
    }
}

// The importer call: the file read and post-processed into the scene returned, refusals
// naming the stage; names and describes `scene` and adds the warnings these steps give.
const aiScene& importScene(Assimp::Importer& importer, const FolderIO& io, const std::string& path,
                           const Fail& fail, Scene& scene) {
    auto refusal = [&](const char* stage) {
        const std::string why =
            tidied(!io.refused().empty() ? io.refused() : importer.GetErrorString());
        return std::string(stage) + (why.empty() ? "" : ": " + why);
    };

    // Read as the file is, less what gnomon does not use (dropUnused); check what validation
    // and post-processing could hide; validate, then process.
    const aiScene* ai = importer.ReadFile(path, 0);
    if (!ai && lower(fs::path(path).extension().string()) == ".amf" && zipped(path)) {
        fail(
            "a zip-compressed AMF file, which assimp cannot read: unzip it (the archive "
            "holds the AMF's XML) and load that");
    }
    if (!ai) fail(refusal("assimp cannot read it"));
    dropUnused(const_cast<aiScene&>(*ai), fs::path(path).filename().string(), scene);
    checkMeshesAsRead(*ai, fail);
    ai = importer.ApplyPostProcessing(aiProcess_ValidateDataStructure);
    if (!ai) fail(refusal("assimp cannot read it"));
    ai = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_SortByPType |
                                      aiProcess_FindInvalidData | aiProcess_TransformUVCoords);
    if (!ai) fail(refusal("assimp's post-processing refused it"));
    scene.name = fs::path(path).stem().string();
    std::string format = lower(fs::path(path).extension().string());
    if (const int importerIndex = importer.GetImporterIndex(format.c_str()); importerIndex >= 0) {
        if (const aiImporterDesc* d = importer.GetImporterInfo(std::size_t(importerIndex)))
            format = d->mName;
    }
    scene.description = "model file " + path + " (read by assimp: " + format + ")";
    warnMissingNormals(*ai, scene);
    ai = importer.ApplyPostProcessing(aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices |
                                      aiProcess_FlipUVs | aiProcess_ValidateDataStructure);
    if (!ai) fail(refusal("assimp's post-processing refused it"));
    if (ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) fail("assimp read it only in part (incomplete)");
    if (!io.refused().empty()) scene.warnings.push_back(io.refused() + ": not read");
    if (!ai->mRootNode) fail("no node hierarchy");
    return *ai;
}

// The node hierarchy: objects with accumulated transforms; nodes' world transforms kept
// by name for lights and cameras.
void walk(Context& cx, const aiNode& node, const glm::mat4& parent, int depth) {
    if (depth >= kMaxDepth) cx.fail("nodes nest deeper than 256 levels");
    const std::string name = node.mName.C_Str();
    const glm::mat4 world = parent * toGlm(node.mTransformation);
    if (!finite(world)) cx.fail("node '" + name + "' has a transform that is not finite");
    cx.worldOf.emplace(name, world);
    const bool mirrored = glm::determinant(glm::mat3(world)) < 0.0f;
    for (unsigned k = 0; k < node.mNumMeshes; ++k) {
        const unsigned mi = node.mMeshes[k];
        if (mi >= cx.ai.mNumMeshes) {
            cx.fail("node '" + name + "' refers to meshes[" + std::to_string(mi) +
                    "], which does not exist");
        }
        const std::int64_t gm = assimpMesh(cx, mi, mirrored);
        if (gm < 0) continue;
        Object o;
        o.name = name.empty() ? "node" : name;
        o.mesh = std::uint32_t(gm);
        o.material = cx.ai.mMeshes[mi]->mMaterialIndex;
        o.worldFromModel = world;
        cx.scene.objects.push_back(o);
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c) {
        if (node.mChildren[c]) walk(cx, *node.mChildren[c], world, depth + 1);
    }
}

// The world transform of the node named `name`, else the origin (with a warning naming
// `what`).
glm::mat4 placed(Context& cx, const aiString& name, const std::string& what) {
    if (auto it = cx.worldOf.find(name.C_Str()); it != cx.worldOf.end()) return it->second;
    cx.scene.warnings.push_back(what + " '" + name.C_Str() +
                                "' has no node of its name: placed at the origin");
    return glm::mat4(1.0f);
}

// Lights: colour and intensity as the file gives them (the brightest channel becomes
// the intensity), attenuation c0 + c1 d + c2 d^2 as given; spot cones are taken as full
// angles (assimp 5.2's Collada, FBX and 3DS importers give those).
void readLights(Context& cx) {
    for (unsigned li = 0; li < cx.ai.mNumLights; ++li) {
        const aiLight& src = *cx.ai.mLights[li];
        const std::string lname = src.mName.C_Str();
        const std::string where = "light '" + lname + "'";
        Light l;
        l.name = lname;
        glm::vec3 colour(src.mColorDiffuse.r, src.mColorDiffuse.g, src.mColorDiffuse.b);
        if (!finite(colour) || glm::length(colour) <= 0.0f) {
            if (src.mType != aiLightSource_AMBIENT) {
                cx.scene.warnings.push_back(where + " is black: ignored");
                continue;
            }
            colour = glm::vec3(0.0f);
        }
        if (src.mType == aiLightSource_AMBIENT) {
            cx.scene.ambient = clampColour(colour);
            continue;
        }
        if (src.mType != aiLightSource_DIRECTIONAL && src.mType != aiLightSource_POINT &&
            src.mType != aiLightSource_SPOT) {
            cx.scene.warnings.push_back(where + " is an area or unknown light type: ignored");
            continue;
        }
        const float brightest = std::max({colour.r, colour.g, colour.b, 0.0f});
        l.intensity = brightest;
        l.colour = glm::max(colour / brightest, glm::vec3(0.0f));
        const glm::mat4 world = placed(cx, src.mName, "light");
        l.position = glm::vec3(world * glm::vec4(toGlm(src.mPosition), 1.0f));
        glm::vec3 dir = glm::mat3(world) * toGlm(src.mDirection);
        if (!(glm::length(dir) > 1e-12f) || !finite(dir)) {
            dir = glm::mat3(world) * glm::vec3(0, 0, -1);
            if (src.mType != aiLightSource_POINT)
                cx.scene.warnings.push_back(where + " has no direction: its node's -z used");
        }
        l.direction = glm::length(dir) > 0.0f ? glm::normalize(dir) : glm::vec3(0, -1, 0);
        if (src.mType == aiLightSource_DIRECTIONAL) {
            l.type = LightType::Directional;
        } else {
            l.type = src.mType == aiLightSource_POINT ? LightType::Point : LightType::Spot;
            l.attenuation = {src.mAttenuationConstant, src.mAttenuationLinear,
                             src.mAttenuationQuadratic};
            const Attenuation& a = l.attenuation;
            if (!(a.constant >= 0.0f && a.linear >= 0.0f && a.quadratic >= 0.0f &&
                  a.constant + a.linear + a.quadratic > 0.0f) ||
                !std::isfinite(a.constant + a.linear + a.quadratic)) {
                cx.scene.warnings.push_back(where + " has unusable attenuation: none used");
                l.attenuation = {};
            }
            if (l.type == LightType::Spot) {
                const float outer = 0.5f * glm::degrees(src.mAngleOuterCone);
                const float inner = 0.5f * glm::degrees(src.mAngleInnerCone);
                l.outerConeDegrees = std::isfinite(outer) ? std::clamp(outer, 0.1f, 89.0f) : 30.0f;
                if (l.outerConeDegrees != outer)
                    cx.scene.warnings.push_back(where + ": cone clamped to below 90 degrees");
                l.innerConeDegrees =
                    std::isfinite(inner) ? std::clamp(inner, 0.0f, l.outerConeDegrees) : 0.0f;
            }
        }
        cx.scene.lights.push_back(l);
    }
}

// The file's first camera, given the bounds of what is drawn. assimp 5.2's importers give the full
// horizontal angle (despite its header; assimp issue 2256): vertical = 2 atan(tan(h/2)/a).
void readCamera(Context& cx, Camera& cam, const Aabb& bounds) {
    const glm::vec3 centre = bounds.centre();
    const float radius = std::max(bounds.radius(), 1e-6f);
    {
        const aiCamera& c = *cx.ai.mCameras[0];
        const std::string where = "camera '" + std::string(c.mName.C_Str()) + "'";
        const glm::mat4 world = placed(cx, c.mName, "camera");
        cam.eye = glm::vec3(world * glm::vec4(toGlm(c.mPosition), 1.0f));
        glm::vec3 look = glm::mat3(world) * toGlm(c.mLookAt);
        glm::vec3 up = glm::mat3(world) * toGlm(c.mUp);
        if (!(glm::length(look) > 1e-12f) || !finite(look)) look = glm::vec3(0, 0, -1);
        look = glm::normalize(look);
        if (!(glm::length(glm::cross(look, up)) > 1e-12f) || !finite(up)) {
            up = std::abs(look.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
        }
        cam.centre = cam.eye + look * radius;
        cam.up = glm::normalize(up);
        const float aspect = c.mAspect > 0.0f && std::isfinite(c.mAspect) ? c.mAspect : 0.0f;
        cam.aspect = aspect;
        if (c.mOrthographicWidth > 0.0f) {
            cam.projection = Projection::Orthographic;
            cam.right = c.mOrthographicWidth;
            cam.left = -cam.right;
            cam.top = aspect > 0.0f ? cam.right / aspect : cam.right;
            cam.bottom = -cam.top;
        } else {
            float h = c.mHorizontalFOV;
            if (!(h > 0.0f && h < glm::radians(180.0f))) {
                cx.scene.warnings.push_back(where +
                                            " has an unusable field of view: 45 degrees used");
                h = glm::radians(45.0f);
            }
            if (aspect == 0.0f) {
                cx.scene.warnings.push_back(where +
                                            " gives no aspect ratio: its horizontal field of view "
                                            "is used as the vertical one");
            }
            const float a = aspect > 0.0f ? aspect : 1.0f;
            cam.fovyDegrees =
                std::clamp(glm::degrees(2.0f * std::atan(std::tan(0.5f * h) / a)), 1.0f, 179.0f);
        }
        cam.near = c.mClipPlaneNear;
        cam.far = c.mClipPlaneFar;
        if (!(cam.near > 0.0f && cam.far > cam.near && std::isfinite(cam.far))) {
            cam.near = radius * 1e-3f;
            cam.far = glm::length(cam.eye - centre) + 4.0f * radius;
        }
        if (!finite(cam.eye)) cx.fail(where + " has a position that is not finite");
    }
}

}  // namespace

}  // namespace assimp_parts

bool assimpReads(const std::string& extension) {
    if (extension.size() < 2 || extension[0] != '.') return false;
    Assimp::Importer importer;
    return importer.IsExtensionSupported(lower(extension).c_str());
}

std::string assimpExtensions() {
    Assimp::Importer importer;
    std::string list;  // "*.3ds;*.obj;..."
    importer.GetExtensionList(list);
    std::string out;
    std::size_t start = 0;
    while (start < list.size()) {
        std::size_t end = list.find(';', start);
        if (end == std::string::npos) end = list.size();
        std::string e = list.substr(start, end - start);
        if (e.rfind("*", 0) == 0) e.erase(0, 1);
        if (!e.empty()) out += (out.empty() ? "" : " ") + e;
        start = end + 1;
    }
    return out;
}

// What it reads (OBJ, PLY, STL, 3DS, FBX, DAE and whatever else the installed assimp reads):
// the node hierarchy (transforms accumulated, mirrored nodes' winding flipped), triangles
// (polygons triangulated, points and lines skipped with a warning), normals (smooth ones
// generated where missing, creases kept above 80 degrees), vertex colour set 0, texture
// coordinate set 0 for a base colour texture; materials' diffuse (or base) colour, opacity,
// two-sidedness, Blinn-Phong shininess and specular colour, unlit shading, and the diffuse (or
// base colour) texture from a file inside the model's folder or embedded; directional, point
// and spot lights; the first camera. Errors name the file, the element and what is wrong, with
// assimp's own message where it is the one refusing the file. Every file assimp opens (the
// model, an OBJ's .mtl) must lie inside the model's folder.
Scene loadWithAssimp(const std::string& path, UpAxis up) {
    using namespace assimp_parts;
    checkFile(path);
    const Fail fail{path};
    std::error_code ec;
    const fs::path root = fs::weakly_canonical(fs::absolute(path).parent_path(), ec);

    Assimp::Importer importer;
    auto* io = new FolderIO(root);
    importer.SetIOHandler(io);  // the importer owns it
    configure(importer);
    Scene scene;
    Context cx(importScene(importer, *io, path, fail, scene), root, fail, scene);

    readMaterials(cx);
    walk(cx, *cx.ai.mRootNode, glm::mat4(1.0f), 0);
    sidesFromTopology(cx);
    readLights(cx);
    LoadedModel loaded;
    loaded.file = path;
    loaded.zeroAreaTriangles = cx.zeroArea;
    loaded.up = up;
    if (cx.ai.mNumCameras > 0) {
        loaded.placeCamera = [&cx](Camera& cam, const Aabb& bounds) {
            readCamera(cx, cam, bounds);
        };
    }
    finishModelScene(scene, loaded);
    return scene;
}

}  // namespace gnomon
