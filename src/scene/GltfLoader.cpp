// glTF 2.0 (.gltf, .glb) into the scene model, through tinygltf: reading the file (external
// files only from inside the scene's folder), walking the default scene's nodes, placing
// lights and cameras; materials and meshes are read by GltfMaterials.cpp and GltfMeshes.cpp.
#include "scene/GltfLoader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include <tiny_gltf.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gnomon/Error.h"
#include "scene/GltfParts.h"
#include "scene/ModelFinish.h"
#include "scene/SceneUtil.h"

namespace gnomon {

namespace {

using gltf::Context;
using gltf::Reader;
namespace fs = std::filesystem;

constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(2) << 30;  // 2 GiB per file
constexpr int kMaxDepth = 256;                                     // node nesting

// The scene's folder: external URIs must resolve inside it.
struct Folder {
    fs::path root;
    std::string error;  // the first refused read, for the message
};

// True when `path` resolves inside the scene's folder. (tinygltf also tries paths relative
// to the working directory: those simply do not exist for it.)
bool inside(const Folder& folder, const std::string& path, fs::path& resolved) {
    std::error_code ec;
    resolved = fs::weakly_canonical(fs::path(path), ec);
    const auto [rootEnd, _] =
        std::mismatch(folder.root.begin(), folder.root.end(), resolved.begin(), resolved.end());
    return !ec && rootEnd == folder.root.end();
}

bool fileExists(const std::string& path, void* user) {
    fs::path resolved;
    if (!inside(*static_cast<Folder*>(user), path, resolved)) return false;
    std::error_code ec;
    return fs::is_regular_file(resolved, ec);
}

std::string expandPath(const std::string& path, void*) {
    return path;  // no ~ or environment expansion: a scene names files, not shells
}

bool readFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
              void* user) {
    Folder& folder = *static_cast<Folder*>(user);
    fs::path resolved;
    if (!inside(folder, path, resolved)) {
        folder.error = "'" + path + "' lies outside the scene's folder '" + folder.root.string() +
                       "' (no absolute paths or .. escapes)";
        if (err) *err = folder.error;
        return false;
    }
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(resolved, ec);
    if (ec) {
        if (err) *err = "cannot read '" + path + "': " + ec.message();
        return false;
    }
    if (size > kMaxFileBytes) {
        folder.error = "'" + path + "' is larger than 2 GiB";
        if (err) *err = folder.error;
        return false;
    }
    std::ifstream in(resolved, std::ios::binary);
    out->resize(std::size_t(size));
    if (!in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size))) {
        if (err) *err = "cannot read '" + path + "'";
        return false;
    }
    return true;
}

bool noWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err = "writing is not allowed";
    return false;
}

// Images: tinygltf hands over their encoded bytes, kept as they are; only the ones a
// material's base colour uses are decoded afterwards (stb_image, size-limited), so normal
// and other maps cost no decoding.
bool keepEncoded(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                 const unsigned char* bytes, int size, void*) {
    image->image.assign(bytes, bytes + std::max(size, 0));
    image->as_is = true;
    return true;
}

// A binary glTF's container (glTF 2.0 specification, "GLB File Format Specification"): a
// 12-byte header (magic, version 2, total length) and chunks of (length, type, data), the
// first JSON, the optional second BIN. tinygltf answers any fault with "Invalid glTF
// binary."; this names the fault and its byte offset first.
void checkGlbLayout(const std::vector<unsigned char>& bytes, const std::string& path) {
    const auto u32 = [&](std::size_t at) {
        std::uint32_t v = 0;
        std::memcpy(&v, bytes.data() + at, 4);
        return v;  // little-endian in the file; gnomon's hosts are little-endian too
    };
    const auto fail = [&](const std::string& what) {
        throw Error(ErrorKind::InvalidInput, path + ": broken binary glTF: " + what);
    };
    const std::size_t size = bytes.size();
    if (size < 12)
        fail("the 12-byte header is cut off (the file has " + std::to_string(size) + " bytes)");
    if (u32(4) != 2) fail("version " + std::to_string(u32(4)) + " at offset 4 (gnomon reads 2)");
    if (u32(8) != size) {
        fail("the header at offset 8 gives a length of " + std::to_string(u32(8)) +
             " bytes, the file has " + std::to_string(size) +
             (u32(8) > size ? " (truncated?)" : ""));
    }
    std::size_t at = 12;
    for (int chunk = 0; at < size; ++chunk) {
        const std::string where =
            "chunk " + std::to_string(chunk) + " at offset " + std::to_string(at);
        if (size - at < 8) fail(where + ": its 8-byte header is cut off at the end of the file");
        const std::uint64_t length = u32(at);
        if (length > size - at - 8) {
            fail(where + " claims " + std::to_string(length) + " bytes of data, only " +
                 std::to_string(size - at - 8) + " remain");
        }
        if (chunk == 0 && u32(at + 4) != 0x4E4F534Au)  // "JSON"
            fail(where + " is not the JSON chunk, which must come first");
        at += 8 + std::size_t(length);
    }
}

// The file's bytes parsed by tinygltf, external files read through the callbacks above;
// tinygltf's complaint (or the refused read) in the error.
tinygltf::Model parseModel(const std::vector<unsigned char>& bytes, const std::string& path,
                           const std::string& folderPath) {
    std::error_code ec;
    Folder folder;
    folder.root = fs::weakly_canonical(fs::absolute(folderPath), ec);
    tinygltf::TinyGLTF loader;
    tinygltf::FsCallbacks callbacks{&fileExists, &expandPath, &readFile, &noWrite, &folder};
    loader.SetFsCallbacks(callbacks);
    loader.SetImageLoader(&keepEncoded, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    if (bytes.size() > kMaxFileBytes)
        throw Error(ErrorKind::InvalidInput, path + ": larger than 2 GiB");
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    if (binary) checkGlbLayout(bytes, path);
    const std::string base = folder.root.string();
    const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                                         unsigned(bytes.size()), base)
                           : loader.LoadASCIIFromString(&model, &err, &warn,
                                                        reinterpret_cast<const char*>(bytes.data()),
                                                        unsigned(bytes.size()), base);
    if (!ok) {
        std::string why = !folder.error.empty() ? folder.error : err;
        while (!why.empty() && (why.back() == '\n' || why.back() == ' '))
            why.pop_back();
        if (why.find("File not found") != std::string::npos) {
            why +=
                " (external files are looked for inside the scene's folder only: no absolute "
                "paths or .. escapes)";
        }
        throw Error(ErrorKind::InvalidInput, path + ": " + (why.empty() ? "not valid glTF" : why));
    }
    return model;
}

// Extensions the file requires that gnomon lacks fail; ignored ones, animations and skins
// are warned about.
void checkExtensions(Context& cx) {
    const tinygltf::Model& model = cx.model;
    Scene& scene = cx.scene;
    static const std::set<std::string> kSupported = {"KHR_lights_punctual",
                                                     "EXT_mesh_gpu_instancing",
                                                     "KHR_materials_emissive_strength",
                                                     "KHR_texture_transform",
                                                     "KHR_materials_ior",
                                                     "KHR_materials_specular",
                                                     "MSFT_lod"};
    for (const std::string& e : model.extensionsRequired) {
        if (!kSupported.count(e))
            cx.read.fail("requires extension " + e + ", which gnomon does not support");
    }
    for (const std::string& e : model.extensionsUsed) {
        if (!kSupported.count(e)) scene.warnings.push_back("extension " + e + " is ignored");
    }
    if (!model.animations.empty()) scene.warnings.push_back("animations are ignored: rest pose");
    if (!model.skins.empty()) scene.warnings.push_back("skins are ignored: rest pose");
}

glm::mat4 localMatrix(const tinygltf::Node& n) {
    if (n.matrix.size() == 16) {
        glm::mat4 m;
        for (int i = 0; i < 16; ++i)
            glm::value_ptr(m)[i] = float(n.matrix[std::size_t(i)]);
        return m;
    }
    glm::mat4 t(1.0f);
    if (n.translation.size() == 3) {
        t = glm::translate(t, glm::vec3(float(n.translation[0]), float(n.translation[1]),
                                        float(n.translation[2])));
    }
    if (n.rotation.size() == 4) {
        const glm::quat q(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]),
                          float(n.rotation[2]));
        t *= glm::mat4_cast(glm::normalize(q));
    }
    if (n.scale.size() == 3) {
        t = glm::scale(t, glm::vec3(float(n.scale[0]), float(n.scale[1]), float(n.scale[2])));
    }
    return t;
}

int extensionInt(const tinygltf::ExtensionMap& ext, const char* name, const char* key) {
    auto it = ext.find(name);
    if (it == ext.end() || !it->second.IsObject() || !it->second.Has(key)) return -1;
    const tinygltf::Value& v = it->second.Get(key);
    return v.IsInt() ? v.Get<int>() : v.IsNumber() ? int(v.GetNumberAsDouble()) : -1;
}

// Cameras and lights found while walking, with their world transforms.
struct Placed {
    int index;
    glm::mat4 world;
};

// The node walk's state: the path from the root, to catch cycles, and what it placed.
struct Walk {
    Context& cx;
    std::vector<int> stack;
    std::vector<Placed> cameras, lights;
};

// Instances: EXT_mesh_gpu_instancing gives one transform per instance.
std::vector<glm::mat4> instanceTransforms(const Context& cx, const tinygltf::Node& node,
                                          const glm::mat4& world) {
    const Reader& read = cx.read;
    std::vector<glm::mat4> instances = {world};
    if (auto it = node.extensions.find("EXT_mesh_gpu_instancing");
        it != node.extensions.end() && node.mesh >= 0) {
        const tinygltf::Value& attrs = it->second.Get("attributes");
        auto column = [&](const char* key, int comps) {
            std::vector<float> v;
            if (attrs.IsObject() && attrs.Has(key)) {
                v = read.floats(attrs.Get(key).GetNumberAsInt(), comps, key);
            }
            return v;
        };
        const std::vector<float> t = column("TRANSLATION", 3), r = column("ROTATION", 4),
                                 s = column("SCALE", 3);
        const std::size_t count = std::max({t.size() / 3, r.size() / 4, s.size() / 3});
        if (count > 0) {
            instances.clear();
            for (std::size_t i = 0; i < count; ++i) {
                glm::mat4 m(1.0f);
                if (i < t.size() / 3)
                    m = glm::translate(m, glm::vec3(t[3 * i], t[3 * i + 1], t[3 * i + 2]));
                if (i < r.size() / 4) {
                    m *= glm::mat4_cast(glm::normalize(
                        glm::quat(r[4 * i + 3], r[4 * i], r[4 * i + 1], r[4 * i + 2])));
                }
                if (i < s.size() / 3)
                    m = glm::scale(m, glm::vec3(s[3 * i], s[3 * i + 1], s[3 * i + 2]));
                instances.push_back(world * m);
            }
        }
    }
    return instances;
}

// One object per instance and triangle primitive of nodes[n]'s mesh; mirrored instances
// get the primitive's mesh with its winding flipped. The file's coarser versions of the
// mesh (MSFT_lod) go with each primitive's mesh, for --caster-detail to draw into maps.
void placeMesh(Context& cx, int n, const tinygltf::Node& node,
               const std::vector<glm::mat4>& instances) {
    const tinygltf::Model& model = cx.model;
    if (std::size_t(node.mesh) >= model.meshes.size()) {
        cx.read.fail("nodes[" + std::to_string(n) + "] refers to meshes[" +
                     std::to_string(node.mesh) + "], which does not exist");
    }
    const tinygltf::Mesh& mesh = model.meshes[std::size_t(node.mesh)];
    const std::vector<int> lods = gltf::lodNodes(cx, n, node);
    const glm::mat4 fromNode = lods.empty() ? glm::mat4(1.0f) : glm::inverse(localMatrix(node));
    for (const glm::mat4& m : instances) {
        const bool mirrored = glm::determinant(glm::mat3(m)) < 0.0f;
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::int64_t gm = gltf::primitiveMesh(cx, node.mesh, int(p), mirrored);
            if (gm < 0) continue;
            Mesh& made = cx.scene.meshes[std::size_t(gm)];
            for (std::size_t k = 0; made.lods.size() < lods.size() && k < lods.size(); ++k) {
                const tinygltf::Node& lod = model.nodes[std::size_t(lods[k])];
                made.lods.push_back(gltf::primitiveLod(cx, lod.mesh, int(p), mirrored,
                                                       fromNode * localMatrix(lod)));
            }
            const int mat = mesh.primitives[p].material;
            if (mat >= int(model.materials.size())) {
                cx.read.fail("meshes[" + std::to_string(node.mesh) + "].primitives[" +
                             std::to_string(p) + "] refers to a missing material");
            }
            Object o;
            o.name = node.name.empty() ? "nodes[" + std::to_string(n) + "]" : node.name;
            o.mesh = std::uint32_t(gm);
            o.material = mat >= 0 ? std::uint32_t(mat) : cx.defaultMaterial;
            o.worldFromModel = m;
            cx.scene.objects.push_back(o);
        }
    }
}

// nodes[n] and its descendants under `parent`: objects into the scene, cameras and lights
// into the walk.
void walkNode(Walk& w, int n, const glm::mat4& parent) {
    const tinygltf::Model& model = w.cx.model;
    const Reader& read = w.cx.read;
    if (n < 0 || std::size_t(n) >= model.nodes.size()) {
        read.fail("a scene or node refers to nodes[" + std::to_string(n) +
                  "], which does not exist");
    }
    if (std::find(w.stack.begin(), w.stack.end(), n) != w.stack.end()) {
        read.fail("nodes[" + std::to_string(n) +
                  "] is its own ancestor (the node graph has a cycle)");
    }
    if (w.stack.size() >= std::size_t(kMaxDepth)) read.fail("nodes nest deeper than 256 levels");
    w.stack.push_back(n);
    const tinygltf::Node& node = model.nodes[std::size_t(n)];
    const glm::mat4 world = parent * localMatrix(node);
    const std::vector<glm::mat4> instances = instanceTransforms(w.cx, node, world);
    if (node.mesh >= 0) placeMesh(w.cx, n, node, instances);
    if (node.camera >= 0) w.cameras.push_back({node.camera, world});
    if (const int l = extensionInt(node.extensions, "KHR_lights_punctual", "light"); l >= 0) {
        w.lights.push_back({l, world});
    }
    for (int child : node.children)
        walkNode(w, child, world);
    w.stack.pop_back();
}

// The default scene's root nodes (the first scene's without one); with no scenes at all,
// every node that is no node's child.
void walkNodes(Walk& w) {
    const tinygltf::Model& model = w.cx.model;
    if (!model.scenes.empty()) {
        const int s = model.defaultScene >= 0 ? model.defaultScene : 0;
        if (std::size_t(s) >= model.scenes.size())
            w.cx.read.fail("scene " + std::to_string(s) + " does not exist");
        for (int n : model.scenes[std::size_t(s)].nodes)
            walkNode(w, n, glm::mat4(1.0f));
    } else {
        std::vector<bool> child(model.nodes.size());
        for (const tinygltf::Node& node : model.nodes) {
            for (int c : node.children)
                if (c >= 0 && std::size_t(c) < child.size()) child[std::size_t(c)] = true;
        }
        for (std::size_t n = 0; n < model.nodes.size(); ++n)
            if (!child[n]) walkNode(w, int(n), glm::mat4(1.0f));
    }
}

// Lights (KHR_lights_punctual): intensities in the spec's units (candela, lux) used as
// gnomon's intensity, point and spot falling off as 1/d^2.
void readLights(Context& cx, const std::vector<Placed>& lights) {
    const tinygltf::Model& model = cx.model;
    Scene& scene = cx.scene;
    for (const Placed& pl : lights) {
        if (std::size_t(pl.index) >= model.lights.size()) {
            cx.read.fail("a node refers to KHR_lights_punctual light " + std::to_string(pl.index) +
                         ", which does not exist");
        }
        const tinygltf::Light& src = model.lights[std::size_t(pl.index)];
        Light l;
        l.name = src.name;
        if (src.color.size() >= 3)
            l.colour = glm::vec3(float(src.color[0]), float(src.color[1]), float(src.color[2]));
        l.intensity = float(src.intensity);
        l.position = glm::vec3(pl.world[3]);
        l.direction = glm::normalize(glm::mat3(pl.world) * glm::vec3(0, 0, -1));
        if (src.type == "directional") {
            l.type = LightType::Directional;
        } else if (src.type == "point" || src.type == "spot") {
            l.type = src.type == "point" ? LightType::Point : LightType::Spot;
            l.attenuation = {0.0f, 0.0f, 1.0f};
            if (l.type == LightType::Spot) {
                l.innerConeDegrees = float(glm::degrees(src.spot.innerConeAngle));
                l.outerConeDegrees =
                    std::clamp(float(glm::degrees(src.spot.outerConeAngle)), 0.1f, 89.0f);
                l.innerConeDegrees = std::clamp(l.innerConeDegrees, 0.0f, l.outerConeDegrees);
            }
        } else {
            scene.warnings.push_back("light '" + src.name + "' has unknown type '" + src.type +
                                     "': ignored");
            continue;
        }
        if (l.type != LightType::Directional && src.range > 0.0 && std::isfinite(src.range))
            l.range = float(src.range);
        scene.lights.push_back(l);
    }
}

// The first camera placed in the file, given the bounds of what is drawn.
void placeCamera(const tinygltf::Camera& c, const glm::mat4& w, Camera& cam, const Aabb& bounds) {
    const glm::vec3 centre = bounds.centre();
    const float radius = std::max(bounds.radius(), 1e-6f);
    cam.eye = glm::vec3(w[3]);
    cam.centre = cam.eye + glm::normalize(glm::mat3(w) * glm::vec3(0, 0, -1)) * radius;
    cam.up = glm::normalize(glm::mat3(w) * glm::vec3(0, 1, 0));
    if (c.type == "orthographic") {
        cam.projection = Projection::Orthographic;
        cam.right = float(c.orthographic.xmag);
        cam.left = -cam.right;
        cam.top = float(c.orthographic.ymag);
        cam.bottom = -cam.top;
        cam.near = float(c.orthographic.znear);
        cam.far = float(c.orthographic.zfar);
    } else {
        cam.fovyDegrees = float(glm::degrees(c.perspective.yfov));
        cam.aspect = float(c.perspective.aspectRatio);
        cam.near = float(c.perspective.znear);
        cam.far = c.perspective.zfar > 0.0 ? float(c.perspective.zfar)
                                           : glm::length(cam.eye - centre) + 4.0f * radius;
    }
    if (!(cam.near > 0.0f && cam.far > cam.near)) {
        cam.near = radius * 1e-3f;
        cam.far = glm::length(cam.eye - centre) + 4.0f * radius;
    }
}

}  // namespace

Scene loadGltf(const std::string& path, UpAxis up) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        throw Error(ErrorKind::InvalidInput, "cannot load scene '" + path + "': no such file");
    }
    if (fs::file_size(path, ec) > kMaxFileBytes) {
        throw Error(ErrorKind::InvalidInput, path + ": larger than 2 GiB");
    }
    std::ifstream in(path, std::ios::binary);
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) throw Error(ErrorKind::Io, "cannot read '" + path + "'");
    return loadGltf(bytes, path, fs::absolute(path).parent_path().string(), up);
}

// What it reads: the default scene's node hierarchy (matrix or TRS), triangle primitives
// (lists, strips and fans, indexed or not) with positions, normals (flat ones made where
// missing), COLOR_0 and the base colour texture's TEXCOORD_n; materials' base colour factor
// and texture (with its sampler and KHR_texture_transform), alpha mode and cutoff,
// roughness, metalness and double-sidedness; mirrored nodes (winding flipped),
// EXT_mesh_gpu_instancing, MSFT_lod on nodes (coarser versions of their meshes, for stand-in
// casters), KHR_lights_punctual and cameras. Skins and animations are left
// at the rest pose. Errors name the file, the element (`accessors[3]`) and what is wrong.
Scene loadGltf(const std::vector<unsigned char>& bytes, const std::string& path,
               const std::string& folderPath, UpAxis up) {
    const tinygltf::Model model = parseModel(bytes, path, folderPath);
    const Reader read(model, path);

    Scene scene;
    scene.name = fs::path(path).stem().string();
    scene.description = "glTF file " + path;
    Context cx(model, read, scene);
    checkExtensions(cx);
    gltf::readMaterials(cx);

    Walk walk{cx, {}, {}, {}};
    walkNodes(walk);
    readLights(cx, walk.lights);

    LoadedModel loaded;
    loaded.file = path;
    loaded.zeroAreaTriangles = cx.zeroArea;
    loaded.photometricLights = true;
    loaded.up = up;
    if (!walk.cameras.empty() && std::size_t(walk.cameras.front().index) < model.cameras.size()) {
        const tinygltf::Camera& c = model.cameras[std::size_t(walk.cameras.front().index)];
        const glm::mat4 world = walk.cameras.front().world;
        loaded.placeCamera = [&c, world](Camera& cam, const Aabb& bounds) {
            placeCamera(c, world, cam, bounds);
        };
    }
    finishModelScene(scene, loaded);
    return scene;
}

}  // namespace gnomon
