// Other model formats (OBJ, PLY, STL, 3DS, FBX, DAE...) into gnomon's scene model through
// assimp (see AssimpLoader.cpp for what is read).
#pragma once

#include <string>

#include "gnomon/Scene.h"

namespace gnomon {

// Does assimp read files with this extension (".obj", case-insensitive)?
bool assimpReads(const std::string& extension);
// The extensions assimp reads, as ".3ds .obj ..." for messages.
std::string assimpExtensions();

// Throws gnomon::Error: Io when the file cannot be read, InvalidInput naming the file, the
// element and what is wrong for anything malformed or unusable (assimp's own message
// included). External files (materials, textures) are read only from inside the model's
// folder.
Scene loadWithAssimp(const std::string& path, UpAxis up = UpAxis::Y);

}  // namespace gnomon
