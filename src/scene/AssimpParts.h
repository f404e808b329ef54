// What the assimp loader's files share (internal): small conversions, the context the loading
// steps pass along, and the steps AssimpMaterials.cpp and AssimpMeshes.cpp provide.
#pragma once

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <utility>

#include <assimp/scene.h>
#include <glm/gtc/type_ptr.hpp>

#include "gnomon/Error.h"
#include "gnomon/Scene.h"

namespace gnomon::assimp_parts {

constexpr float kCreaseDegrees = 80.0f;  // generated normals are not smoothed across more

// Throws InvalidInput naming the file.
struct Fail {
    std::string file;
    [[noreturn]] void operator()(const std::string& what) const {
        throw Error(ErrorKind::InvalidInput, file + ": " + what);
    }
};

inline glm::mat4 toGlm(const aiMatrix4x4& m) {
    // assimp is row-major (a1..a4 the first row), glm column-major.
    return glm::transpose(glm::make_mat4(&m.a1));
}
inline glm::vec3 toGlm(const aiVector3D& v) {
    return {v.x, v.y, v.z};
}
inline bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        if (!finite(glm::vec3(m[c])) || !std::isfinite(m[c][3])) return false;
    return true;
}
inline glm::vec3 clampColour(const glm::vec3& c) {
    if (!finite(c)) return glm::vec3(1.0f);
    return glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f));
}

inline std::string meshName(const aiMesh& m, unsigned index) {
    return m.mName.length > 0 ? "mesh '" + std::string(m.mName.C_Str()) + "'"
                              : "meshes[" + std::to_string(index) + "]";
}

// True when `path` (absolute, or relative to the working directory as assimp opens it)
// resolves inside `root`; `resolved` receives where it leads (AssimpLoader.cpp).
bool inside(const std::filesystem::path& root, const std::string& path,
            std::filesystem::path& resolved);

// What the loading steps share once assimp has read and processed the file: its scene, the
// model's folder, the scene being built, and what one step leaves for the next.
struct Context {
    Context(const aiScene& ai_, std::filesystem::path root_, const Fail& fail_, Scene& scene_)
        : ai(ai_), root(std::move(root_)), fail(fail_), scene(scene_) {}

    const aiScene& ai;
    const std::filesystem::path root;  // the model's folder, the only one files are read from
    const Fail fail;
    Scene& scene;
    // Textures: one gnomon texture per file (or embedded image) and wrap modes.
    std::map<std::string, int> textureOf;
    // One gnomon mesh per assimp mesh (and per winding, for mirrored nodes).
    std::map<std::pair<unsigned, bool>, std::int64_t> meshOf;
    std::set<unsigned> reported;     // meshes already warned about and counted
    std::set<unsigned> sidedByFile;  // materials whose file says single- or double-sided
    long zeroArea = 0;               // triangles skipped, for one warning at the end
    // Nodes' world transforms by name, for lights and cameras.
    std::map<std::string, glm::mat4> worldOf;
};

// Before post-processing: refuses non-finite positions and empty faces, and sets each mesh's
// primitive types from its faces (AssimpMeshes.cpp).
void checkMeshesAsRead(const aiScene& ai, const Fail& fail);

// Warns about each triangle mesh without normals, which post-processing then generates
// (AssimpMeshes.cpp).
void warnMissingNormals(const aiScene& ai, Scene& scene);

// Materials: every material of the file into cx.scene (with the textures they use), or a
// default one when there are none (AssimpMaterials.cpp).
void readMaterials(Context& cx);

// Materials the file does not call single- or double-sided (OBJ, STL and PLY never do) are
// drawn double-sided where an object using them is not a closed surface wound outwards:
// culling its back faces would show the inside of an open shell or of a solid wound inwards
// (AssimpMaterials.cpp). After the objects are made.
void sidesFromTopology(Context& cx);

// The gnomon mesh of assimp mesh `index` (winding reversed when `flipped`), made on first
// use; -1 when it draws no triangles (AssimpMeshes.cpp).
std::int64_t assimpMesh(Context& cx, unsigned index, bool flipped);

}  // namespace gnomon::assimp_parts
