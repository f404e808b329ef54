// glTF 2.0 scenes (.gltf, .glb) into gnomon's scene model (see GltfLoader.cpp for what is read).
#pragma once

#include <string>

#include "gnomon/Scene.h"

namespace gnomon {

// Throws gnomon::Error: Io when the file cannot be read, InvalidInput naming the file, the
// element and what is wrong for anything malformed or unsupported.
Scene loadGltf(const std::string& path);

}  // namespace gnomon
