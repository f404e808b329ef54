// The assimp loader's functions (scene/AssimpLoader.h) for a build without assimp (the web
// build; CMake picks this file instead of AssimpLoader.cpp and its parts): the common model
// formats are still recognised by their extension, so that loading one says clearly that
// this build cannot read it, rather than that gnomon does not know the format.
#include <algorithm>
#include <cctype>

#include "gnomon/Error.h"
#include "scene/AssimpLoader.h"

namespace gnomon {
namespace {

// The formats a native build reads through assimp that people most often have.
constexpr const char* kModelExtensions[] = {".3ds", ".3mf", ".blend", ".dae", ".fbx",
                                            ".obj", ".off", ".ply",   ".stl", ".x3d"};

}  // namespace

bool assimpReads(const std::string& extension) {
    std::string ext = extension;
    for (char& c : ext)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return std::any_of(std::begin(kModelExtensions), std::end(kModelExtensions),
                       [&](const char* known) { return ext == known; });
}

std::string assimpExtensions() {
    return "other formats, which this build (without assimp) does not read";
}

Scene loadWithAssimp(const std::string& path, UpAxis) {
    throw Error(ErrorKind::InvalidInput,
                "cannot load scene '" + path +
                    "': OBJ, STL, PLY, 3DS, FBX, COLLADA, glTF 1.0 and the other formats are "
                    "read through assimp, which this build of gnomon does not have; convert "
                    "the model to glTF 2.0 (.gltf, .glb)");
}

}  // namespace gnomon
