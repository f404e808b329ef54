// glTF 2.0 (.gltf, .glb) into the scene model, through tinygltf. What it reads: the default
// scene's node hierarchy (matrix or TRS), triangle primitives (lists, strips and fans,
// indexed or not) with positions, normals (flat ones made where missing), COLOR_0 and the
// base colour texture's TEXCOORD_n; materials' base colour factor and texture (with its
// sampler and KHR_texture_transform), alpha mode and cutoff, roughness, metalness and
// double-sidedness; mirrored nodes (winding flipped), EXT_mesh_gpu_instancing,
// KHR_lights_punctual and cameras. Skins and
// animations are left at the rest pose. Errors name the file, the element (`accessors[3]`)
// and what is wrong; external files are read only from inside the scene's folder.
#include "scene/GltfLoader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <set>

#include <tiny_gltf.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gnomon/Error.h"
#include "scene/SceneUtil.h"
#include "scene/TextureDecode.h"

namespace gnomon {

namespace {

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

class Reader {
public:
    Reader(const tinygltf::Model& model, std::string file) : m(model), file(std::move(file)) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw Error(ErrorKind::InvalidInput, file + ": " + what);
    }

    // Element i of an accessor as `components` floats (normalised integers scaled to
    // [0, 1]), with every bound checked.
    std::vector<float> floats(int index, int components, const char* role) const {
        const tinygltf::Accessor& a = accessor(index, role);
        const int have = tinygltf::GetNumComponentsInType(std::uint32_t(a.type));
        if (have != components && !(components == 4 && have == 3)) {
            fail(name(index) + " (" + role + ") has " + std::to_string(have) +
                 " components, expected " + std::to_string(components));
        }
        std::vector<float> out(std::size_t(a.count) * std::size_t(components), 1.0f);
        const unsigned char* base = nullptr;
        std::size_t stride = 0;
        const int size = tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType));
        if (size <= 0) fail(name(index) + " has an unknown component type");
        view(index, std::size_t(size) * std::size_t(have), base, stride);
        for (std::size_t i = 0; i < a.count; ++i) {
            const unsigned char* e = base + i * stride;
            for (int c = 0; c < have; ++c) {
                float v = 0.0f;
                const unsigned char* p = e + std::size_t(c) * std::size_t(size);
                switch (a.componentType) {
                    case TINYGLTF_COMPONENT_TYPE_FLOAT:
                        std::memcpy(&v, p, 4);
                        break;
                    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                        v = float(*p) / (a.normalized ? 255.0f : 1.0f);
                        break;
                    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                        std::uint16_t u;
                        std::memcpy(&u, p, 2);
                        v = float(u) / (a.normalized ? 65535.0f : 1.0f);
                        break;
                    }
                    case TINYGLTF_COMPONENT_TYPE_BYTE:
                        v = a.normalized ? std::max(float(std::int8_t(*p)) / 127.0f, -1.0f)
                                         : float(std::int8_t(*p));
                        break;
                    case TINYGLTF_COMPONENT_TYPE_SHORT: {
                        std::int16_t s;
                        std::memcpy(&s, p, 2);
                        v = a.normalized ? std::max(float(s) / 32767.0f, -1.0f) : float(s);
                        break;
                    }
                    default:
                        fail(name(index) + " (" + role +
                             ") has a component type gnomon cannot read");
                }
                out[i * std::size_t(components) + std::size_t(c)] = v;
            }
        }
        return out;
    }

    std::vector<std::uint32_t> indices(int index) const {
        const tinygltf::Accessor& a = accessor(index, "indices");
        if (a.type != TINYGLTF_TYPE_SCALAR) fail(name(index) + " (indices) is not SCALAR");
        const int size = tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType));
        if (size != 1 && size != 2 && size != 4) {
            fail(name(index) + " (indices) is not of unsigned byte, short or int");
        }
        const unsigned char* base = nullptr;
        std::size_t stride = 0;
        view(index, std::size_t(size), base, stride);
        std::vector<std::uint32_t> out(a.count);
        for (std::size_t i = 0; i < a.count; ++i) {
            const unsigned char* p = base + i * stride;
            std::uint32_t v = 0;
            if (size == 1) v = *p;
            if (size == 2) {
                std::uint16_t u;
                std::memcpy(&u, p, 2);
                v = u;
            }
            if (size == 4) std::memcpy(&v, p, 4);
            out[i] = v;
        }
        return out;
    }

    std::string name(int accessor) const { return "accessors[" + std::to_string(accessor) + "]"; }

private:
    const tinygltf::Accessor& accessor(int index, const char* role) const {
        if (index < 0 || std::size_t(index) >= m.accessors.size()) {
            fail(std::string(role) + " refers to accessors[" + std::to_string(index) +
                 "], which does not exist (" + std::to_string(m.accessors.size()) + " accessors)");
        }
        return m.accessors[std::size_t(index)];
    }

    // The first element's bytes and the stride, after checking that `count` elements of
    // `elementBytes` fit in the buffer view and the view in its buffer.
    void view(int index, std::size_t elementBytes, const unsigned char*& base,
              std::size_t& stride) const {
        const tinygltf::Accessor& a = m.accessors[std::size_t(index)];
        if (a.sparse.isSparse) fail(name(index) + " is sparse, which gnomon does not read");
        if (a.bufferView < 0 || std::size_t(a.bufferView) >= m.bufferViews.size()) {
            fail(name(index) + " refers to bufferViews[" + std::to_string(a.bufferView) +
                 "], which does not exist");
        }
        const tinygltf::BufferView& v = m.bufferViews[std::size_t(a.bufferView)];
        const std::string vname = "bufferViews[" + std::to_string(a.bufferView) + "]";
        if (v.buffer < 0 || std::size_t(v.buffer) >= m.buffers.size()) {
            fail(vname + " refers to buffers[" + std::to_string(v.buffer) +
                 "], which does not exist");
        }
        const tinygltf::Buffer& b = m.buffers[std::size_t(v.buffer)];
        if (v.byteOffset > b.data.size() || v.byteLength > b.data.size() - v.byteOffset) {
            fail(vname + " (offset " + std::to_string(v.byteOffset) + ", length " +
                 std::to_string(v.byteLength) + ") overruns buffers[" + std::to_string(v.buffer) +
                 "] of " + std::to_string(b.data.size()) + " bytes (missing or truncated?)");
        }
        stride = v.byteStride ? v.byteStride : elementBytes;
        if (stride < elementBytes) fail(vname + " has a byte stride smaller than its elements");
        const std::size_t need =
            a.count == 0 ? 0 : a.byteOffset + stride * (a.count - 1) + elementBytes;
        if (a.byteOffset > v.byteLength || need > v.byteLength) {
            fail(name(index) + " (" + std::to_string(a.count) + " elements from byte " +
                 std::to_string(a.byteOffset) + ") overruns " + vname + " of " +
                 std::to_string(v.byteLength) + " bytes");
        }
        base = b.data.data() + v.byteOffset + a.byteOffset;
    }

    const tinygltf::Model& m;
    std::string file;
};

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

}  // namespace

Scene loadGltf(const std::string& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        throw Error(ErrorKind::Io, "cannot load scene '" + path + "': no such file");
    }
    if (fs::file_size(path, ec) > kMaxFileBytes) {
        throw Error(ErrorKind::InvalidInput, path + ": larger than 2 GiB");
    }
    std::ifstream in(path, std::ios::binary);
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) throw Error(ErrorKind::Io, "cannot read '" + path + "'");
    return loadGltf(bytes, path, fs::absolute(path).parent_path().string());
}

Scene loadGltf(const std::vector<unsigned char>& bytes, const std::string& path,
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
    const Reader read(model, path);

    static const std::set<std::string> kSupported = {
        "KHR_lights_punctual",   "EXT_mesh_gpu_instancing", "KHR_materials_emissive_strength",
        "KHR_texture_transform", "KHR_materials_ior",       "KHR_materials_specular"};
    Scene scene;
    scene.name = fs::path(path).stem().string();
    scene.description = "glTF file " + path;
    for (const std::string& e : model.extensionsRequired) {
        if (!kSupported.count(e))
            read.fail("requires extension " + e + ", which gnomon does not support");
    }
    for (const std::string& e : model.extensionsUsed) {
        if (!kSupported.count(e)) scene.warnings.push_back("extension " + e + " is ignored");
    }
    if (!model.animations.empty()) scene.warnings.push_back("animations are ignored: rest pose");
    if (!model.skins.empty()) scene.warnings.push_back("skins are ignored: rest pose");

    // Textures: a glTF texture (image + sampler) becomes one gnomon texture on first use.
    std::map<int, int> textureOf;
    auto texture = [&](int index, const std::string& where) -> int {
        if (auto it = textureOf.find(index); it != textureOf.end()) return it->second;
        if (index < 0 || std::size_t(index) >= model.textures.size()) {
            read.fail(where + " refers to textures[" + std::to_string(index) +
                      "], which does not exist");
        }
        const tinygltf::Texture& t = model.textures[std::size_t(index)];
        const std::string tname = "textures[" + std::to_string(index) + "]";
        if (t.source < 0 || std::size_t(t.source) >= model.images.size()) {
            read.fail(tname + " has no image gnomon can read (source " + std::to_string(t.source) +
                      ")");
        }
        const tinygltf::Image& image = model.images[std::size_t(t.source)];
        const std::string iname =
            "images[" + std::to_string(t.source) + "]" +
            (image.uri.empty() || image.uri.rfind("data:", 0) == 0 ? "" : " ('" + image.uri + "')");
        Texture g;
        g.name = image.name.empty() ? iname : image.name;
        if (!image.as_is) read.fail(iname + " holds no encoded image data");
        if (const std::string why = decodeTexture(image.image.data(), image.image.size(), g);
            !why.empty()) {
            read.fail(iname + ": " + why);
        }
        if (t.sampler >= 0 && std::size_t(t.sampler) < model.samplers.size()) {
            const tinygltf::Sampler& sm = model.samplers[std::size_t(t.sampler)];
            auto wrap = [](int w) {
                return w == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE     ? TextureWrap::ClampToEdge
                       : w == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT ? TextureWrap::MirroredRepeat
                                                                    : TextureWrap::Repeat;
            };
            g.wrapS = wrap(sm.wrapS);
            g.wrapT = wrap(sm.wrapT);
            g.nearest = sm.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
        }
        scene.textures.push_back(std::move(g));
        textureOf[index] = int(scene.textures.size() - 1);
        return textureOf[index];
    };

    // Materials: the base colour factor (linear) and texture, alpha, Blinn-Phong from
    // roughness and metalness. texCoordOf: the TEXCOORD_n set each material's texture reads.
    std::vector<int> texCoordOf;
    for (std::size_t mi = 0; mi < model.materials.size(); ++mi) {
        const tinygltf::Material& mat = model.materials[mi];
        const std::string where = "materials[" + std::to_string(mi) + "]";
        Material g;
        g.name = mat.name;
        const auto& pbr = mat.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() >= 3) {
            g.baseColour = glm::vec3(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]),
                                     float(pbr.baseColorFactor[2]));
        }
        if (pbr.baseColorFactor.size() == 4)
            g.alpha = std::clamp(float(pbr.baseColorFactor[3]), 0.0f, 1.0f);
        int texCoord = -1;
        if (pbr.baseColorTexture.index >= 0) {
            g.baseColourTexture = texture(pbr.baseColorTexture.index, where);
            texCoord = pbr.baseColorTexture.texCoord;
            const tinygltf::ExtensionMap& ext = pbr.baseColorTexture.extensions;
            if (auto it = ext.find("KHR_texture_transform");
                it != ext.end() && it->second.IsObject()) {
                const tinygltf::Value& x = it->second;
                auto pair = [&](const char* key, glm::vec2 fallback) {
                    if (!x.Has(key) || !x.Get(key).IsArray() || x.Get(key).ArrayLen() != 2)
                        return fallback;
                    return glm::vec2(float(x.Get(key).Get(0).GetNumberAsDouble()),
                                     float(x.Get(key).Get(1).GetNumberAsDouble()));
                };
                const glm::vec2 offset = pair("offset", glm::vec2(0.0f));
                const glm::vec2 scale = pair("scale", glm::vec2(1.0f));
                const float r =
                    x.Has("rotation") ? float(x.Get("rotation").GetNumberAsDouble()) : 0.0f;
                // uv' = T R S uv, rotating counter-clockwise in uv space (the extension's
                // example: offset (0, 1), rotation pi/2, scale 0.5 picks the lower-left
                // quadrant turned clockwise).
                const float c = std::cos(r), sn = std::sin(r);
                const glm::mat3 T(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
                const glm::mat3 R(c, -sn, 0, sn, c, 0, 0, 0, 1);
                const glm::mat3 S(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
                g.uvTransform = T * R * S;
                if (x.Has("texCoord")) texCoord = x.Get("texCoord").GetNumberAsInt();
                bool finiteTransform = true;
                for (int col = 0; col < 3; ++col)
                    for (int row = 0; row < 3; ++row)
                        finiteTransform = finiteTransform && std::isfinite(g.uvTransform[col][row]);
                if (!finiteTransform)
                    read.fail(where + " has a KHR_texture_transform that is not finite");
            }
        }
        texCoordOf.push_back(texCoord);
        if (mat.alphaMode == "MASK") {
            g.alphaMode = AlphaMode::Mask;
            g.alphaCutoff = std::clamp(float(mat.alphaCutoff), 0.0f, 1.0f);
        } else if (mat.alphaMode == "BLEND") {
            g.alphaMode = AlphaMode::Blend;
        } else if (!mat.alphaMode.empty() && mat.alphaMode != "OPAQUE") {
            read.fail(where + " has alphaMode '" + mat.alphaMode +
                      "' (expected OPAQUE, MASK or BLEND)");
        }
        const float roughness = std::clamp(float(pbr.roughnessFactor), 0.02f, 1.0f);
        g.shininess = std::clamp(2.0f / (roughness * roughness * roughness * roughness) - 2.0f,
                                 1.0f, 2048.0f);
        g.specular = 0.04f + 0.5f * float(pbr.metallicFactor) * (1.0f - roughness);
        g.doubleSided = mat.doubleSided;
        scene.materials.push_back(g);
    }
    const std::uint32_t defaultMaterial = std::uint32_t(scene.materials.size());
    {
        Material m;  // glTF's default: white, fully rough
        m.name = "default";
        m.specular = 0.04f;
        m.shininess = 1.0f;
        scene.materials.push_back(m);
    }

    // One gnomon mesh per primitive (and per winding, for mirrored nodes).
    std::map<std::tuple<int, int, bool>, std::uint32_t> meshOf;
    long zeroArea = 0;
    auto primitiveMesh = [&](int meshIndex, int primIndex, bool flipped) -> std::int64_t {
        const auto key = std::make_tuple(meshIndex, primIndex, flipped);
        if (auto it = meshOf.find(key); it != meshOf.end()) return it->second;
        const tinygltf::Primitive& p =
            model.meshes[std::size_t(meshIndex)].primitives[std::size_t(primIndex)];
        const std::string where = "meshes[" + std::to_string(meshIndex) + "].primitives[" +
                                  std::to_string(primIndex) + "]";
        if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            p.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            scene.warnings.push_back(where + " draws points or lines: ignored");
            return -1;
        }
        auto attr = p.attributes.find("POSITION");
        if (attr == p.attributes.end()) read.fail(where + " has no POSITION");
        const std::vector<float> pos = read.floats(attr->second, 3, "POSITION");
        const std::size_t vertices = pos.size() / 3;
        for (float v : pos) {
            if (!std::isfinite(v))
                read.fail(read.name(attr->second) + " (POSITION) holds NaN or infinity");
        }
        std::vector<std::uint32_t> order;
        if (p.indices >= 0) {
            order = read.indices(p.indices);
            for (std::uint32_t i : order) {
                if (i >= vertices) {
                    read.fail(read.name(p.indices) + " holds index " + std::to_string(i) + " but " +
                              where + " has " + std::to_string(vertices) + " vertices");
                }
            }
        } else {
            order.resize(vertices);
            for (std::size_t i = 0; i < vertices; ++i)
                order[i] = std::uint32_t(i);
        }
        // Triangle list (strips and fans converted, keeping each triangle's winding).
        std::vector<std::uint32_t> tri;
        if (p.mode == TINYGLTF_MODE_TRIANGLES) {
            tri.assign(order.begin(), order.end() - std::ptrdiff_t(order.size() % 3));
        } else {
            for (std::size_t i = 2; i < order.size(); ++i) {
                if (p.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
                    const bool odd = (i % 2) == 1;
                    tri.insert(tri.end(), {order[i - 2], odd ? order[i] : order[i - 1],
                                           odd ? order[i - 1] : order[i]});
                } else {
                    tri.insert(tri.end(), {order[0], order[i - 1], order[i]});
                }
            }
        }
        Mesh mesh;
        mesh.name = model.meshes[std::size_t(meshIndex)].name + "/" + std::to_string(primIndex);
        auto position = [&](std::uint32_t i) {
            return glm::vec3(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]);
        };
        auto normalAttr = p.attributes.find("NORMAL");
        auto colourAttr = p.attributes.find("COLOR_0");
        std::vector<float> normals, colours, uvs;
        const int texCoord = p.material >= 0 && std::size_t(p.material) < texCoordOf.size()
                                 ? texCoordOf[std::size_t(p.material)]
                                 : -1;
        if (texCoord >= 0) {
            const std::string set = "TEXCOORD_" + std::to_string(texCoord);
            auto uvAttr = p.attributes.find(set);
            if (uvAttr == p.attributes.end()) {
                scene.warnings.push_back(where + " has a textured material but no " + set +
                                         ": drawn untextured");
            } else {
                uvs = read.floats(uvAttr->second, 2, set.c_str());
                if (uvs.size() / 2 != vertices)
                    read.fail(where + " has a " + set + " count unlike POSITION's");
                for (float v : uvs) {
                    if (!std::isfinite(v))
                        read.fail(read.name(uvAttr->second) + " (" + set +
                                  ") holds NaN or infinity");
                }
            }
        }
        if (normalAttr != p.attributes.end())
            normals = read.floats(normalAttr->second, 3, "NORMAL");
        if (colourAttr != p.attributes.end())
            colours = read.floats(colourAttr->second, 4, "COLOR_0");
        if (!normals.empty() && normals.size() != pos.size())
            read.fail(where + " has a NORMAL count unlike POSITION's");
        if (!colours.empty() && colours.size() / 4 != vertices)
            read.fail(where + " has a COLOR_0 count unlike POSITION's");
        // Without normals: flat ones, one per triangle (its vertices are split); with them,
        // the vertices are kept and shared.
        const bool flat = normals.empty();
        if (flat) scene.warnings.push_back(where + " has no normals: flat ones generated");
        if (!flat) {
            mesh.positions.resize(vertices);
            mesh.normals.resize(vertices);
            for (std::uint32_t k = 0; k < vertices; ++k) {
                mesh.positions[k] = position(k);
                const glm::vec3 nk(normals[3 * k], normals[3 * k + 1], normals[3 * k + 2]);
                const float len = glm::length(nk);
                mesh.normals[k] = len > 0.0f && std::isfinite(len) ? nk / len : glm::vec3(0, 1, 0);
            }
            if (!colours.empty()) {
                mesh.colours.resize(vertices);
                for (std::uint32_t k = 0; k < vertices; ++k)
                    mesh.colours[k] =
                        glm::vec3(colours[4 * k], colours[4 * k + 1], colours[4 * k + 2]);
            }
            if (!uvs.empty()) {
                mesh.uvs.resize(vertices);
                for (std::uint32_t k = 0; k < vertices; ++k)
                    mesh.uvs[k] = glm::vec2(uvs[2 * k], uvs[2 * k + 1]);
            }
        }
        for (std::size_t t = 0; t + 2 < tri.size(); t += 3) {
            std::uint32_t v[3] = {tri[t], tri[t + 1], tri[t + 2]};
            if (flipped) std::swap(v[1], v[2]);
            const glm::vec3 a = position(v[0]), b = position(v[1]), c = position(v[2]);
            const glm::vec3 n = glm::cross(b - a, c - a);
            if (!(glm::length(n) > 0.0f)) {
                ++zeroArea;
                continue;
            }
            if (!flat) {
                mesh.indices.insert(mesh.indices.end(), {v[0], v[1], v[2]});
                continue;
            }
            for (std::uint32_t k : v) {
                mesh.positions.push_back(position(k));
                mesh.normals.push_back(glm::normalize(n));
                if (!colours.empty()) {
                    mesh.colours.push_back(
                        glm::vec3(colours[4 * k], colours[4 * k + 1], colours[4 * k + 2]));
                }
                if (!uvs.empty()) mesh.uvs.push_back(glm::vec2(uvs[2 * k], uvs[2 * k + 1]));
                mesh.indices.push_back(std::uint32_t(mesh.indices.size()));
            }
        }
        if (mesh.indices.empty()) return -1;
        scene.meshes.push_back(std::move(mesh));
        meshOf[key] = std::uint32_t(scene.meshes.size() - 1);
        return std::int64_t(scene.meshes.size() - 1);
    };

    // Cameras and lights found while walking, with their world transforms.
    struct Placed {
        int index;
        glm::mat4 world;
    };
    std::vector<Placed> cameras, lights;

    std::vector<int> stack;  // the path from the root, to catch cycles
    std::function<void(int, const glm::mat4&)> walk = [&](int n, const glm::mat4& parent) {
        if (n < 0 || std::size_t(n) >= model.nodes.size()) {
            read.fail("a scene or node refers to nodes[" + std::to_string(n) +
                      "], which does not exist");
        }
        if (std::find(stack.begin(), stack.end(), n) != stack.end()) {
            read.fail("nodes[" + std::to_string(n) +
                      "] is its own ancestor (the node graph has a cycle)");
        }
        if (stack.size() >= std::size_t(kMaxDepth)) read.fail("nodes nest deeper than 256 levels");
        stack.push_back(n);
        const tinygltf::Node& node = model.nodes[std::size_t(n)];
        const glm::mat4 world = parent * localMatrix(node);
        // Instances: EXT_mesh_gpu_instancing gives one transform per instance.
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
        if (node.mesh >= 0) {
            if (std::size_t(node.mesh) >= model.meshes.size()) {
                read.fail("nodes[" + std::to_string(n) + "] refers to meshes[" +
                          std::to_string(node.mesh) + "], which does not exist");
            }
            const tinygltf::Mesh& mesh = model.meshes[std::size_t(node.mesh)];
            for (const glm::mat4& m : instances) {
                const bool mirrored = glm::determinant(glm::mat3(m)) < 0.0f;
                for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
                    const std::int64_t gm = primitiveMesh(node.mesh, int(p), mirrored);
                    if (gm < 0) continue;
                    const int mat = mesh.primitives[p].material;
                    if (mat >= int(model.materials.size())) {
                        read.fail("meshes[" + std::to_string(node.mesh) + "].primitives[" +
                                  std::to_string(p) + "] refers to a missing material");
                    }
                    Object o;
                    o.name = node.name.empty() ? "nodes[" + std::to_string(n) + "]" : node.name;
                    o.mesh = std::uint32_t(gm);
                    o.material = mat >= 0 ? std::uint32_t(mat) : defaultMaterial;
                    o.worldFromModel = m;
                    scene.objects.push_back(o);
                }
            }
        }
        if (node.camera >= 0) cameras.push_back({node.camera, world});
        if (const int l = extensionInt(node.extensions, "KHR_lights_punctual", "light"); l >= 0) {
            lights.push_back({l, world});
        }
        for (int child : node.children)
            walk(child, world);
        stack.pop_back();
    };
    if (!model.scenes.empty()) {
        const int s = model.defaultScene >= 0 ? model.defaultScene : 0;
        if (std::size_t(s) >= model.scenes.size())
            read.fail("scene " + std::to_string(s) + " does not exist");
        for (int n : model.scenes[std::size_t(s)].nodes)
            walk(n, glm::mat4(1.0f));
    } else {
        std::vector<bool> child(model.nodes.size());
        for (const tinygltf::Node& node : model.nodes) {
            for (int c : node.children)
                if (c >= 0 && std::size_t(c) < child.size()) child[std::size_t(c)] = true;
        }
        for (std::size_t n = 0; n < model.nodes.size(); ++n)
            if (!child[n]) walk(int(n), glm::mat4(1.0f));
    }
    untextureObjectsWithoutUvs(scene);  // each was warned about: no TEXCOORD
    if (zeroArea > 0)
        scene.warnings.push_back(std::to_string(zeroArea) + " zero-area triangles skipped");
    if (scene.objects.empty()) read.fail("the scene has no triangles to draw");

    // World bounds of what is drawn (as the renderer's fitting sees them).
    const Aabb bounds = worldBounds(scene, meshBounds(scene), 0.0, false);
    const glm::vec3 centre = bounds.centre();
    const float radius = std::max(bounds.radius(), 1e-6f);

    // Lights (KHR_lights_punctual): intensities in the spec's units (candela, lux) used as
    // gnomon's intensity, point and spot falling off as 1/d^2.
    for (const Placed& pl : lights) {
        if (std::size_t(pl.index) >= model.lights.size()) {
            read.fail("a node refers to KHR_lights_punctual light " + std::to_string(pl.index) +
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
    // gnomon has no exposure control: photometric intensities (tens of candela at lamp
    // scale) would saturate. Keep their ratios and scale them so the brightest point or
    // spot light gives 1 at a quarter of the scene's size, and no sun exceeds 1.
    float brightest = 0.0f, brightestSun = 0.0f;
    for (const Light& l : scene.lights) {
        (l.type == LightType::Directional ? brightestSun : brightest) =
            std::max(l.type == LightType::Directional ? brightestSun : brightest, l.intensity);
    }
    const float quarter = 0.5f * radius;
    const float pointScale = brightest > 0.0f ? quarter * quarter / brightest : 1.0f;
    const float sunScale = brightestSun > 1.0f ? 1.0f / brightestSun : 1.0f;
    for (Light& l : scene.lights)
        l.intensity *= l.type == LightType::Directional ? sunScale : pointScale;
    if (brightest > 0.0f || sunScale != 1.0f) {
        scene.warnings.push_back("light intensities scaled for display (point and spot x" +
                                 std::to_string(pointScale) + ", directional x" +
                                 std::to_string(sunScale) + ")");
    }
    addDefaultSun(scene);

    // The camera: the first one placed, else one framing the bounds.
    Camera& cam = scene.camera;
    if (!cameras.empty() && std::size_t(cameras.front().index) < model.cameras.size()) {
        const tinygltf::Camera& c = model.cameras[std::size_t(cameras.front().index)];
        const glm::mat4& w = cameras.front().world;
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
    } else {
        frameWithCamera(scene, bounds);
    }
    scene.ambient = glm::vec3(0.1f);
    scene.options.width = scene.options.height = 512;
    scene.options.shading.output =
        OutputEncoding::Srgb;  // authored for display, as viewers show it
    return scene;
}

}  // namespace gnomon
