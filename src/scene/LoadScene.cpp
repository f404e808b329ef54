// Scene lookup by name or path: built-in scenes by name, glTF files by path, other model
// formats through assimp; anything else gets a clear error rather than a guess.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

#include "gnomon/Error.h"
#include "gnomon/Scene.h"
#include "gnomon/SceneFile.h"
#include "scene/AssimpLoader.h"
#include "scene/GltfLoader.h"

namespace gnomon {
namespace {

bool readable(const std::string& ext) {
    return ext == ".gltf" || ext == ".glb" || ext == ".json" || assimpReads(ext);
}

std::string lowerExtension(const std::filesystem::path& p) {
    std::string ext = p.extension().string();
    for (char& c : ext)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

// A folder given as the scene: the files in it gnomon could load (up to three), so that the
// message says which one to give.
[[noreturn]] void refuseFolder(const std::string& path) {
    namespace fs = std::filesystem;
    std::vector<std::string> found;
    std::error_code ec;
    for (fs::directory_iterator it(path, ec), end; !ec && it != end; it.increment(ec)) {
        if (it->is_regular_file(ec) && readable(lowerExtension(it->path())))
            found.push_back(it->path().filename().string());
    }
    std::sort(found.begin(), found.end());
    std::string hint = "it holds no file gnomon reads";
    if (!found.empty()) {
        hint = "give one of the files in it, such as";
        for (std::size_t i = 0; i < std::min<std::size_t>(found.size(), 3); ++i)
            hint += (i ? ", " : " ") + (fs::path(path) / found[i]).string();
        if (found.size() > 3) hint += " (" + std::to_string(found.size()) + " in all)";
    }
    throw Error(ErrorKind::InvalidInput,
                "cannot load scene '" + path + "': it is a folder; " + hint);
}

}  // namespace

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
        if (fs::is_directory(nameOrPath, ec)) refuseFolder(nameOrPath);
        const std::string ext = lowerExtension(nameOrPath);
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
