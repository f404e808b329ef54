// Other model formats into the scene model through assimp (OBJ, PLY, STL, 3DS, FBX, DAE and
// whatever else the installed assimp reads). What it reads: the node hierarchy (transforms
// accumulated, mirrored nodes' winding flipped), triangles (polygons triangulated, points and
// lines skipped with a warning), normals (smooth ones generated where missing, creases kept
// above 80 degrees), vertex colour set 0, texture coordinate set 0 for a base colour texture;
// materials' diffuse (or base) colour, opacity, two-sidedness, Blinn-Phong shininess and
// specular colour, unlit shading, and the diffuse (or base colour) texture from a file inside
// the model's folder or embedded; directional, point and spot lights; the first camera.
// Errors name the file, the element and what is wrong, with assimp's own message where it is
// the one refusing the file. Every file assimp opens (the model, an OBJ's .mtl) must lie
// inside the model's folder.
#include "scene/AssimpLoader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <set>

#include <assimp/DefaultIOSystem.h>
#include <assimp/config.h>
#include <assimp/importerdesc.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gnomon/Error.h"
#include "scene/SceneUtil.h"
#include "scene/TextureDecode.h"

namespace gnomon {

namespace {

namespace fs = std::filesystem;

constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(2) << 30;  // 2 GiB, as for glTF
constexpr int kMaxDepth = 256;                                     // node nesting
constexpr float kCreaseDegrees = 80.0f;  // generated normals are not smoothed across more

// True when `path` (absolute, or relative to the working directory as assimp opens it)
// resolves inside `root`; `resolved` receives where it leads.
bool inside(const fs::path& root, const std::string& path, fs::path& resolved) {
    std::error_code ec;
    resolved = fs::weakly_canonical(fs::absolute(fs::path(path), ec), ec);
    if (ec) return false;
    const auto [rootEnd, _] =
        std::mismatch(root.begin(), root.end(), resolved.begin(), resolved.end());
    return rootEnd == root.end();
}

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

// Throws InvalidInput naming the file.
struct Fail {
    std::string file;
    [[noreturn]] void operator()(const std::string& what) const {
        throw Error(ErrorKind::InvalidInput, file + ": " + what);
    }
};

glm::mat4 toGlm(const aiMatrix4x4& m) {
    // assimp is row-major (a1..a4 the first row), glm column-major.
    return glm::transpose(glm::make_mat4(&m.a1));
}
glm::vec3 toGlm(const aiVector3D& v) {
    return {v.x, v.y, v.z};
}
bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        if (!finite(glm::vec3(m[c])) || !std::isfinite(m[c][3])) return false;
    return true;
}
glm::vec3 clampColour(const glm::vec3& c) {
    if (!finite(c)) return glm::vec3(1.0f);
    return glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f));
}

std::string lower(std::string s) {
    for (char& c : s)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string meshName(const aiMesh& m, unsigned index) {
    return m.mName.length > 0 ? "mesh '" + std::string(m.mName.C_Str()) + "'"
                              : "meshes[" + std::to_string(index) + "]";
}

TextureWrap wrapOf(aiTextureMapMode mode) {
    switch (mode) {
        case aiTextureMapMode_Clamp:
        case aiTextureMapMode_Decal:
            return TextureWrap::ClampToEdge;
        case aiTextureMapMode_Mirror:
            return TextureWrap::MirroredRepeat;
        default:
            return TextureWrap::Repeat;
    }
}

}  // namespace

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

Scene loadWithAssimp(const std::string& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        throw Error(ErrorKind::Io, "cannot load scene '" + path + "': no such file");
    }
    if (fs::file_size(path, ec) > kMaxFileBytes) {
        throw Error(ErrorKind::InvalidInput, path + ": larger than 2 GiB");
    }
    const Fail fail{path};
    const fs::path root = fs::weakly_canonical(fs::absolute(path).parent_path(), ec);

    Assimp::Importer importer;
    auto* io = new FolderIO(root);
    importer.SetIOHandler(io);  // the importer owns it
    importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
    importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, kCreaseDegrees);
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, 0);  // points and lines: we warn
    // FindInvalidData would also drop a set of texture coordinates that are all equal.
    importer.SetPropertyBool(AI_CONFIG_PP_FID_IGNORE_TEXTURECOORDS, true);
    auto refusal = [&](const char* stage) {
        std::string why = !io->refused().empty() ? io->refused() : importer.GetErrorString();
        while (!why.empty() && (why.back() == '\n' || why.back() == ' '))
            why.pop_back();
        return std::string(stage) + (why.empty() ? "" : ": " + why);
    };

    // Read as the file is (validated), check what post-processing could hide, then process.
    const aiScene* ai = importer.ReadFile(path, aiProcess_ValidateDataStructure);
    if (!ai) fail(refusal("assimp cannot read it"));
    for (unsigned i = 0; i < ai->mNumMeshes; ++i) {
        const aiMesh& m = *ai->mMeshes[i];
        for (unsigned v = 0; v < m.mNumVertices; ++v) {
            if (!finite(toGlm(m.mVertices[v]))) {
                fail(meshName(m, i) + " vertex " + std::to_string(v) +
                     " has a position that is NaN or infinite");
            }
        }
    }
    // assimp 5.2's PLY importer marks triangle meshes as polygons and lets empty faces
    // through; either makes Triangulate abort the process (an assertion left on in Debian's
    // build). Empty faces are refused, the types taken from the faces.
    for (unsigned i = 0; i < ai->mNumMeshes; ++i) {
        aiMesh& m = *ai->mMeshes[i];
        unsigned types = 0;
        for (unsigned f = 0; f < m.mNumFaces; ++f) {
            if (m.mFaces[f].mNumIndices == 0)
                fail(meshName(m, i) + " face " + std::to_string(f) + " has no vertices");
            types |= unsigned(AI_PRIMITIVE_TYPE_FOR_N_INDICES(m.mFaces[f].mNumIndices));
        }
        m.mPrimitiveTypes = types;
    }
    ai = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_SortByPType |
                                      aiProcess_FindInvalidData | aiProcess_TransformUVCoords);
    if (!ai) fail(refusal("assimp's post-processing refused it"));
    Scene scene;
    scene.name = fs::path(path).stem().string();
    std::string format = lower(fs::path(path).extension().string());
    if (const int importerIndex = importer.GetImporterIndex(format.c_str()); importerIndex >= 0) {
        if (const aiImporterDesc* d = importer.GetImporterInfo(std::size_t(importerIndex)))
            format = d->mName;
    }
    scene.description = "model file " + path + " (read by assimp: " + format + ")";
    for (unsigned i = 0; i < ai->mNumMeshes; ++i) {
        const aiMesh& m = *ai->mMeshes[i];
        if ((m.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) && !m.HasNormals()) {
            scene.warnings.push_back(meshName(m, i) +
                                     " has no normals: smooth ones generated (creases above " +
                                     std::to_string(int(kCreaseDegrees)) + " degrees kept)");
        }
    }
    ai = importer.ApplyPostProcessing(aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices |
                                      aiProcess_FlipUVs | aiProcess_ValidateDataStructure);
    if (!ai) fail(refusal("assimp's post-processing refused it"));
    if (ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) fail("assimp read it only in part (incomplete)");
    if (!io->refused().empty()) scene.warnings.push_back(io->refused() + ": not read");
    if (!ai->mRootNode) fail("no node hierarchy");

    // Textures: one gnomon texture per file (or embedded image) and wrap modes.
    std::map<std::string, int> textureOf;
    auto texture = [&](const aiMaterial& mat, aiTextureType type, const std::string& where) -> int {
        aiString file;
        aiTextureMapping mapping = aiTextureMapping_UV;
        unsigned uvIndex = 0;
        aiTextureMapMode modes[2] = {aiTextureMapMode_Wrap, aiTextureMapMode_Wrap};
        if (mat.GetTexture(type, 0, &file, &mapping, &uvIndex, nullptr, nullptr, modes) !=
            AI_SUCCESS) {
            return -1;
        }
        std::string name = file.C_Str();
        std::replace(name.begin(), name.end(), '\\', '/');
        if (mapping != aiTextureMapping_UV) {
            scene.warnings.push_back(where + ": texture '" + name +
                                     "' is projected (not UV-mapped), which gnomon does not do: "
                                     "drawn untextured");
            return -1;
        }
        if (uvIndex != 0) {
            scene.warnings.push_back(where + ": texture '" + name +
                                     "' uses texture coordinate set " + std::to_string(uvIndex) +
                                     "; gnomon reads set 0 only: drawn untextured");
            return -1;
        }
        const std::string key =
            name + "|" + std::to_string(int(modes[0])) + "|" + std::to_string(int(modes[1]));
        if (auto it = textureOf.find(key); it != textureOf.end()) return it->second;
        Texture t;
        t.name = name;
        std::string why;
        if (const aiTexture* embedded = ai->GetEmbeddedTexture(file.C_Str())) {
            if (embedded->mHeight == 0) {  // compressed (PNG, JPEG...): mWidth bytes
                why = decodeTexture(reinterpret_cast<const unsigned char*>(embedded->pcData),
                                    embedded->mWidth, t);
            } else if (embedded->mWidth > unsigned(kMaxTextureSide) ||
                       embedded->mHeight > unsigned(kMaxTextureSide)) {
                why = "the embedded image is " + std::to_string(embedded->mWidth) + "x" +
                      std::to_string(embedded->mHeight) + ", outside 1.." +
                      std::to_string(kMaxTextureSide) + " per side";
            } else {  // raw BGRA texels, rows top-down
                t.width = int(embedded->mWidth);
                t.height = int(embedded->mHeight);
                t.rgba.resize(std::size_t(t.width) * std::size_t(t.height) * 4);
                for (std::size_t i = 0; i < std::size_t(t.width) * std::size_t(t.height); ++i) {
                    const aiTexel& x = embedded->pcData[i];
                    t.rgba[4 * i] = x.r;
                    t.rgba[4 * i + 1] = x.g;
                    t.rgba[4 * i + 2] = x.b;
                    t.rgba[4 * i + 3] = x.a;
                }
            }
        } else if (!name.empty() && name[0] == '*') {
            why = "the embedded image does not exist (" + std::to_string(ai->mNumTextures) +
                  " embedded)";
        } else {
            const fs::path rel(name);
            const bool absolute = rel.is_absolute() || (name.size() > 1 && name[1] == ':');
            const bool escapes =
                std::any_of(rel.begin(), rel.end(), [](const fs::path& p) { return p == ".."; });
            fs::path resolved;
            if (name.empty()) {
                why = "the texture names no file";
            } else if (absolute || escapes || !inside(root, (root / rel).string(), resolved)) {
                why =
                    "it lies outside the model's folder (textures are read only from inside "
                    "it: no absolute paths or .. escapes)";
            } else {
                try {
                    const Texture loaded = loadTextureFile(resolved.string());
                    t.width = loaded.width;
                    t.height = loaded.height;
                    t.rgba = loaded.rgba;
                } catch (const Error& e) {
                    why = e.what();
                }
            }
        }
        if (!why.empty()) {
            scene.warnings.push_back(where + ": texture '" + name + "' cannot be used (" + why +
                                     "): drawn untextured");
            return textureOf[key] = -1;
        }
        t.wrapS = wrapOf(modes[0]);
        t.wrapT = wrapOf(modes[1]);
        scene.textures.push_back(std::move(t));
        return textureOf[key] = int(scene.textures.size() - 1);
    };

    // Materials: colour as the file gives it (an OBJ's Kd taken as linear), opacity, sides,
    // Blinn-Phong from shininess and the specular colour, the base colour texture.
    for (unsigned mi = 0; mi < ai->mNumMaterials; ++mi) {
        const aiMaterial& mat = *ai->mMaterials[mi];
        Material g;
        aiString name;
        g.name = mat.Get(AI_MATKEY_NAME, name) == AI_SUCCESS
                     ? std::string(name.C_Str())
                     : "materials[" + std::to_string(mi) + "]";
        const std::string where = "material '" + g.name + "'";
        aiColor4D colour;
        if (mat.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == AI_SUCCESS ||
            mat.Get(AI_MATKEY_BASE_COLOR, colour) == AI_SUCCESS) {
            g.baseColour = clampColour({colour.r, colour.g, colour.b});
        }
        float opacity = 1.0f;
        if (mat.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS && opacity < 1.0f) {
            if (!(opacity > 0.0f)) {
                scene.warnings.push_back(where +
                                         " has opacity 0 (what many exporters write for 'not "
                                         "set'): taken as opaque");
            } else {
                g.alphaMode = AlphaMode::Blend;
                g.alpha = std::clamp(opacity, 0.0f, 1.0f);
            }
        }
        int twoSided = 0;
        if (mat.Get(AI_MATKEY_TWOSIDED, twoSided) == AI_SUCCESS) g.doubleSided = twoSided != 0;
        float shininess = 0.0f;
        if (mat.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS && std::isfinite(shininess))
            g.shininess = std::clamp(shininess, 1.0f, 2048.0f);
        aiColor3D specular;
        if (mat.Get(AI_MATKEY_COLOR_SPECULAR, specular) == AI_SUCCESS) {
            float strength = 1.0f;
            mat.Get(AI_MATKEY_SHININESS_STRENGTH, strength);
            const float s = std::max({specular.r, specular.g, specular.b}) * strength;
            g.specular = std::isfinite(s) ? std::clamp(s, 0.0f, 1.0f) : 0.0f;
        }
        int shading = 0;
        if (mat.Get(AI_MATKEY_SHADING_MODEL, shading) == AI_SUCCESS) {
            if (shading == aiShadingMode_NoShading) g.unlit = true;
            if (shading == aiShadingMode_Flat || shading == aiShadingMode_Gouraud)
                g.specular = 0.0f;  // diffuse only (an OBJ's illum 1)
        }
        g.baseColourTexture = texture(mat, aiTextureType_DIFFUSE, where);
        if (g.baseColourTexture < 0 && mat.GetTextureCount(aiTextureType_DIFFUSE) == 0)
            g.baseColourTexture = texture(mat, aiTextureType_BASE_COLOR, where);
        // Cut-outs: an opacity map that is the diffuse texture's own alpha (an OBJ's map_d
        // naming the map_Kd file) cuts at 0.5; another opacity map is not read.
        aiString diffuseFile, opacityFile;
        if (mat.GetTexture(aiTextureType_OPACITY, 0, &opacityFile) == AI_SUCCESS) {
            mat.GetTexture(aiTextureType_DIFFUSE, 0, &diffuseFile);
            if (g.baseColourTexture >= 0 &&
                std::strcmp(opacityFile.C_Str(), diffuseFile.C_Str()) == 0) {
                if (g.alphaMode == AlphaMode::Opaque) g.alphaMode = AlphaMode::Mask;
            } else {
                scene.warnings.push_back(where + ": opacity map '" +
                                         std::string(opacityFile.C_Str()) + "' is ignored");
            }
        }
        scene.materials.push_back(g);
    }
    if (scene.materials.empty()) {
        Material m;
        m.name = "default";
        scene.materials.push_back(m);
    }
    // One gnomon mesh per assimp mesh (and per winding, for mirrored nodes).
    std::map<std::pair<unsigned, bool>, std::int64_t> meshOf;
    std::set<unsigned> reported;  // meshes already warned about and counted
    long zeroArea = 0;
    auto gnomonMesh = [&](unsigned index, bool flipped) -> std::int64_t {
        const auto key = std::make_pair(index, flipped);
        if (auto it = meshOf.find(key); it != meshOf.end()) return it->second;
        std::int64_t& result = meshOf[key] = -1;
        const aiMesh& m = *ai->mMeshes[index];
        const std::string where = meshName(m, index);
        const bool report = reported.insert(index).second;
        if (!(m.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) {
            if (report) scene.warnings.push_back(where + " draws points or lines only: skipped");
            return result;
        }
        if (m.mMaterialIndex >= scene.materials.size())
            fail(where + " refers to a missing material (" + std::to_string(m.mMaterialIndex) +
                 ")");
        const bool textured = scene.materials[m.mMaterialIndex].baseColourTexture >= 0;
        Mesh mesh;
        mesh.name = m.mName.length > 0 ? m.mName.C_Str() : "meshes[" + std::to_string(index) + "]";
        const unsigned n = m.mNumVertices;
        mesh.positions.resize(n);
        mesh.normals.resize(n);
        for (unsigned v = 0; v < n; ++v) {
            mesh.positions[v] = toGlm(m.mVertices[v]);
            if (!finite(mesh.positions[v]))
                fail(where + " vertex " + std::to_string(v) +
                     " has a position that is NaN or infinite");
            const glm::vec3 nv = m.HasNormals() ? toGlm(m.mNormals[v]) : glm::vec3(0, 1, 0);
            const float len = glm::length(nv);
            mesh.normals[v] = len > 0.0f && std::isfinite(len) ? nv / len : glm::vec3(0, 1, 0);
        }
        if (m.HasVertexColors(0)) {
            mesh.colours.resize(n);
            for (unsigned v = 0; v < n; ++v) {
                const aiColor4D& c = m.mColors[0][v];
                mesh.colours[v] = clampColour({c.r, c.g, c.b});
            }
        }
        if (textured && m.HasTextureCoords(0)) {
            mesh.uvs.resize(n);
            for (unsigned v = 0; v < n; ++v) {
                mesh.uvs[v] = {m.mTextureCoords[0][v].x, m.mTextureCoords[0][v].y};
                if (!std::isfinite(mesh.uvs[v].x) || !std::isfinite(mesh.uvs[v].y)) {
                    fail(where + " vertex " + std::to_string(v) +
                         " has texture coordinates that are NaN or infinite");
                }
            }
        } else if (textured && report) {
            scene.warnings.push_back(where +
                                     " has a textured material but no texture coordinates: "
                                     "drawn untextured");
        }
        for (unsigned f = 0; f < m.mNumFaces; ++f) {
            const aiFace& face = m.mFaces[f];
            if (face.mNumIndices != 3) continue;  // a point or line left among triangles
            std::uint32_t v[3] = {face.mIndices[0], face.mIndices[1], face.mIndices[2]};
            for (std::uint32_t i : v) {
                if (i >= n) {
                    fail(where + " face " + std::to_string(f) + " refers to vertex " +
                         std::to_string(i) + " but the mesh has " + std::to_string(n) +
                         " vertices");
                }
            }
            if (flipped) std::swap(v[1], v[2]);
            const glm::vec3 a = mesh.positions[v[0]];
            if (!(glm::length(glm::cross(mesh.positions[v[1]] - a, mesh.positions[v[2]] - a)) >
                  0.0f)) {
                if (report) ++zeroArea;
                continue;
            }
            mesh.indices.insert(mesh.indices.end(), {v[0], v[1], v[2]});
        }
        if (mesh.indices.empty()) return result;
        scene.meshes.push_back(std::move(mesh));
        return result = std::int64_t(scene.meshes.size() - 1);
    };

    // The node hierarchy: objects with accumulated transforms; nodes' world transforms kept
    // by name for lights and cameras.
    std::map<std::string, glm::mat4> worldOf;
    std::function<void(const aiNode&, const glm::mat4&, int)> walk =
        [&](const aiNode& node, const glm::mat4& parent, int depth) {
            if (depth >= kMaxDepth) fail("nodes nest deeper than 256 levels");
            const std::string name = node.mName.C_Str();
            const glm::mat4 world = parent * toGlm(node.mTransformation);
            if (!finite(world)) fail("node '" + name + "' has a transform that is not finite");
            worldOf.emplace(name, world);
            const bool mirrored = glm::determinant(glm::mat3(world)) < 0.0f;
            for (unsigned k = 0; k < node.mNumMeshes; ++k) {
                const unsigned mi = node.mMeshes[k];
                if (mi >= ai->mNumMeshes) {
                    fail("node '" + name + "' refers to meshes[" + std::to_string(mi) +
                         "], which does not exist");
                }
                const std::int64_t gm = gnomonMesh(mi, mirrored);
                if (gm < 0) continue;
                Object o;
                o.name = name.empty() ? "node" : name;
                o.mesh = std::uint32_t(gm);
                o.material = ai->mMeshes[mi]->mMaterialIndex;
                o.worldFromModel = world;
                scene.objects.push_back(o);
            }
            for (unsigned c = 0; c < node.mNumChildren; ++c) {
                if (node.mChildren[c]) walk(*node.mChildren[c], world, depth + 1);
            }
        };
    walk(*ai->mRootNode, glm::mat4(1.0f), 0);
    untextureObjectsWithoutUvs(scene);  // each was warned about with its mesh
    if (zeroArea > 0)
        scene.warnings.push_back(std::to_string(zeroArea) + " zero-area triangles skipped");
    if (scene.objects.empty()) fail("the scene has no triangles to draw");

    const Aabb bounds = worldBounds(scene, meshBounds(scene), 0.0, false);
    const glm::vec3 centre = bounds.centre();
    const float radius = std::max(bounds.radius(), 1e-6f);
    auto placed = [&](const aiString& name, const std::string& what) {
        if (auto it = worldOf.find(name.C_Str()); it != worldOf.end()) return it->second;
        scene.warnings.push_back(what + " '" + name.C_Str() +
                                 "' has no node of its name: placed at the origin");
        return glm::mat4(1.0f);
    };

    // Lights: colour and intensity as the file gives them (the brightest channel becomes
    // the intensity), attenuation c0 + c1 d + c2 d^2 as given; spot cones are taken as full
    // angles (assimp 5.2's Collada, FBX and 3DS importers give those).
    for (unsigned li = 0; li < ai->mNumLights; ++li) {
        const aiLight& src = *ai->mLights[li];
        const std::string lname = src.mName.C_Str();
        const std::string where = "light '" + lname + "'";
        Light l;
        l.name = lname;
        glm::vec3 colour(src.mColorDiffuse.r, src.mColorDiffuse.g, src.mColorDiffuse.b);
        if (!finite(colour) || glm::length(colour) <= 0.0f) {
            if (src.mType != aiLightSource_AMBIENT) {
                scene.warnings.push_back(where + " is black: ignored");
                continue;
            }
            colour = glm::vec3(0.0f);
        }
        if (src.mType == aiLightSource_AMBIENT) {
            scene.ambient = clampColour(colour);
            continue;
        }
        if (src.mType != aiLightSource_DIRECTIONAL && src.mType != aiLightSource_POINT &&
            src.mType != aiLightSource_SPOT) {
            scene.warnings.push_back(where + " is an area or unknown light type: ignored");
            continue;
        }
        const float brightest = std::max({colour.r, colour.g, colour.b, 0.0f});
        l.intensity = brightest;
        l.colour = glm::max(colour / brightest, glm::vec3(0.0f));
        const glm::mat4 world = placed(src.mName, "light");
        l.position = glm::vec3(world * glm::vec4(toGlm(src.mPosition), 1.0f));
        glm::vec3 dir = glm::mat3(world) * toGlm(src.mDirection);
        if (!(glm::length(dir) > 1e-12f) || !finite(dir)) {
            dir = glm::mat3(world) * glm::vec3(0, 0, -1);
            if (src.mType != aiLightSource_POINT)
                scene.warnings.push_back(where + " has no direction: its node's -z used");
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
                scene.warnings.push_back(where + " has unusable attenuation: none used");
                l.attenuation = {};
            }
            if (l.type == LightType::Spot) {
                const float outer = 0.5f * glm::degrees(src.mAngleOuterCone);
                const float inner = 0.5f * glm::degrees(src.mAngleInnerCone);
                l.outerConeDegrees = std::isfinite(outer) ? std::clamp(outer, 0.1f, 89.0f) : 30.0f;
                if (l.outerConeDegrees != outer)
                    scene.warnings.push_back(where + ": cone clamped to below 90 degrees");
                l.innerConeDegrees =
                    std::isfinite(inner) ? std::clamp(inner, 0.0f, l.outerConeDegrees) : 0.0f;
            }
        }
        scene.lights.push_back(l);
    }
    addDefaultSun(scene);

    // The first camera, else one framing the bounds. assimp 5.2's importers give the full
    // horizontal angle (despite its header; assimp issue 2256): vertical = 2 atan(tan(h/2)/a).
    Camera& cam = scene.camera;
    if (ai->mNumCameras > 0) {
        const aiCamera& c = *ai->mCameras[0];
        const std::string where = "camera '" + std::string(c.mName.C_Str()) + "'";
        const glm::mat4 world = placed(c.mName, "camera");
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
                scene.warnings.push_back(where + " has an unusable field of view: 45 degrees used");
                h = glm::radians(45.0f);
            }
            if (aspect == 0.0f) {
                scene.warnings.push_back(where +
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
        if (!finite(cam.eye)) fail(where + " has a position that is not finite");
    } else {
        frameWithCamera(scene, bounds);
    }
    scene.options.width = scene.options.height = 512;
    scene.options.shading.output =
        OutputEncoding::Srgb;  // authored for display, as viewers show it

    if (const std::vector<std::string> problems = scene.validate(); !problems.empty()) {
        std::string all;
        for (const std::string& p : problems)
            all += (all.empty() ? "" : "; ") + p;
        fail("the loaded scene is inconsistent: " + all);
    }
    return scene;
}

}  // namespace gnomon
