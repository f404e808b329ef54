// glTF 2.0 scenes (.gltf, .glb) into gnomon's scene model (see GltfLoader.cpp for what is read).
#pragma once

#include <string>
#include <vector>

#include "gnomon/Scene.h"

namespace gnomon {

// Throws gnomon::Error: Io when the file cannot be read, InvalidInput naming the file, the
// element and what is wrong for anything malformed or unsupported.
Scene loadGltf(const std::string& path, UpAxis up = UpAxis::Y);
// The same from bytes in memory (a .gltf's JSON or a .glb), `path` naming it in messages and
// external files read only from inside `folder`. The fuzz target's entry point.
Scene loadGltf(const std::vector<unsigned char>& bytes, const std::string& path,
               const std::string& folder, UpAxis up = UpAxis::Y);

}  // namespace gnomon
