// Scene lookup by name or path: built-in scenes by name, glTF files by path, other model
// formats through assimp; anything else gets a clear error rather than a guess.
#include <cctype>
#include <filesystem>

#include "gnomon/Error.h"
#include "gnomon/Scene.h"
#include "gnomon/SceneFile.h"
#include "scene/AssimpLoader.h"
#include "scene/GltfLoader.h"

namespace gnomon {

Scene loadScene(const std::string& nameOrPath) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const bool looksLikePath =
        nameOrPath.find('/') != std::string::npos || nameOrPath.find('.') != std::string::npos;
    if (looksLikePath || fs::exists(nameOrPath, ec)) {
        if (!fs::exists(nameOrPath, ec)) {
            throw Error(ErrorKind::InvalidInput,
                        "cannot load scene '" + nameOrPath +
                            "': no such file (and no built-in scene by that name)");
        }
        std::string ext = fs::path(nameOrPath).extension().string();
        for (char& c : ext)
            c = char(std::tolower(static_cast<unsigned char>(c)));
        if (ext == ".gltf" || ext == ".glb") return loadGltf(nameOrPath);
        if (ext == ".json") return loadSceneFile(nameOrPath);
        if (assimpReads(ext)) return loadWithAssimp(nameOrPath);
        throw Error(ErrorKind::InvalidInput,
                    "cannot load scene '" + nameOrPath + "': '" + ext +
                        "' files are not supported; gnomon reads glTF 2.0 (.gltf, .glb), scene "
                        "files (.json) and, through assimp, " +
                        assimpExtensions());
    }
    return builtinScene(nameOrPath);
}

}  // namespace gnomon
