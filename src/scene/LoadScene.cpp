// Scene lookup by name or path: built-in scenes by name, glTF files by path, other model
// formats through assimp; anything else gets a clear error rather than a guess.
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

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

// What a glTF file tinygltf refused says of itself: whether it is glTF 1.0, which assimp
// reads (a binary glTF of version 1, or JSON whose asset says version 1.x, or which keys its
// accessors, meshes or nodes by name: 1.0's dictionaries, where 2.0 has arrays), and the
// extensions it requires (a Draco-compressed mesh fails tinygltf's parse before gnomon can
// name the extension it lacks).
struct GltfHeader {
    bool version1 = false;
    bool binary = false;
    std::vector<std::string> required;
};

GltfHeader peekGltf(const std::string& path) {
    GltfHeader h;
    std::ifstream in(path, std::ios::binary);
    char head[20] = {};
    in.read(head, sizeof head);
    std::string text;
    if (in.gcount() >= 8 && std::memcmp(head, "glTF", 4) == 0) {
        std::uint32_t version = 0, length = 0;
        std::memcpy(&version, head + 4, sizeof version);
        h.version1 = version == 1;
        h.binary = true;
        if (h.version1 || in.gcount() < 20) return h;
        std::memcpy(&length, head + 12, sizeof length);  // the first chunk, JSON
        text.resize(std::min<std::uint32_t>(length, 1u << 26));
        in.read(text.data(), std::streamsize(text.size()));
    } else {
        in.clear();
        in.seekg(0);
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) return h;
    if (const auto r = j.find("extensionsRequired"); r != j.end() && r->is_array()) {
        for (const nlohmann::json& e : *r)
            if (e.is_string()) h.required.push_back(e.get<std::string>());
    }
    // 1.0 exporters wrote the version as a string or a number ("1.0", 1).
    if (const auto asset = j.find("asset"); asset != j.end() && asset->is_object()) {
        const auto version = asset->find("version");
        if (version != asset->end() && version->is_string()) {
            h.version1 = version->get<std::string>().rfind("1", 0) == 0;
            return h;
        }
        if (version != asset->end() && version->is_number()) {
            h.version1 = version->get<double>() < 2.0;
            return h;
        }
    }
    for (const char* key : {"accessors", "meshes", "nodes"})
        if (const auto k = j.find(key); k != j.end() && k->is_object()) h.version1 = true;
    return h;
}

// A glTF file: tinygltf for 2.0, assimp for what it refuses as 1.0 (asked only after a
// refusal, so a 2.0 file is read once); a refusal names the extensions the file requires.
Scene loadAnyGltf(const std::string& path, UpAxis up) {
    try {
        return loadGltf(path, up);
    } catch (const Error& e) {
        const GltfHeader h = peekGltf(path);
        if (!h.version1) {
            const std::string what = e.what();
            std::string list;  // the ones the refusal does not already name
            for (const std::string& r : h.required)
                if (what.find(r) == std::string::npos) list += (list.empty() ? "" : ", ") + r;
            if (list.empty()) throw;
            throw Error(e.kind(), what + " (the file requires " + list + ")");
        }
        if (h.binary) {
            // Debian's assimp 5.2 has no reader for binary 1.0 either.
            throw Error(ErrorKind::InvalidInput,
                        path +
                            ": binary glTF 1.0, which neither gnomon's glTF loader (2.0 only) "
                            "nor assimp reads; convert it to glTF 2.0");
        }
    }
    return loadWithAssimp(path, up);
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

// --up names a model file's axis; scene files and built-in scenes are already upright.
[[noreturn]] void refuseUp(const std::string& nameOrPath, const std::string& what) {
    throw Error(ErrorKind::InvalidInput,
                "--up applies to model files; '" + nameOrPath + "' is " + what);
}

}  // namespace

Scene loadScene(const std::string& nameOrPath, UpAxis up) {
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
        if (ext == ".gltf" || ext == ".glb") return loadAnyGltf(nameOrPath, up);
        if (ext == ".json") {
            if (up != UpAxis::Y) refuseUp(nameOrPath, "a scene file: give \"up\" on its include");
            return loadSceneFile(nameOrPath);
        }
        if (assimpReads(ext)) return loadWithAssimp(nameOrPath, up);
        throw Error(ErrorKind::InvalidInput,
                    "cannot load scene '" + nameOrPath + "': '" + ext +
                        "' files are not supported; gnomon reads glTF 2.0 (.gltf, .glb), scene "
                        "files (.json) and, through assimp, glTF 1.0 and " +
                        assimpExtensions());
    }
    if (up != UpAxis::Y) refuseUp(nameOrPath, "a built-in scene, which stands as it is");
    return builtinScene(nameOrPath);
}

}  // namespace gnomon
