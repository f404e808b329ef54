// Scene lookup by name or path. Model files are not loaded by this version: a path gets a
// clear error rather than a guess.
#include <filesystem>

#include "gnomon/Error.h"
#include "gnomon/Scene.h"

namespace gnomon {

Scene loadScene(const std::string& nameOrPath) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const bool looksLikePath =
        nameOrPath.find('/') != std::string::npos || nameOrPath.find('.') != std::string::npos;
    if (looksLikePath || fs::exists(nameOrPath, ec)) {
        if (!fs::exists(nameOrPath, ec)) {
            throw Error(ErrorKind::Io, "cannot load scene '" + nameOrPath +
                                           "': no such file (and no built-in scene by that name)");
        }
        throw Error(ErrorKind::InvalidInput,
                    "cannot load scene '" + nameOrPath +
                        "': loading model files is not supported by this version of gnomon; "
                        "use a built-in scene (gnomon scenes)");
    }
    return builtinScene(nameOrPath);
}

}  // namespace gnomon
