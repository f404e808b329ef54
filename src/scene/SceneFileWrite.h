// Writing scene files: what a viewer tuned over an included scene, as readable JSON (arrays of
// numbers on one line, floats in their shortest decimal form).
#pragma once

#include <string>

#include "gnomon/Options.h"
#include "gnomon/Scene.h"

namespace gnomon::scenefile {

// Writes (atomically) to `path` a scene file including `include` (as written in the file)
// without its lights and camera, then `scene`'s lights, camera and ambient and every field of
// `options`; "ground": true when `ground`; the include's "up" when `up` is not Y. Throws Error
// (InvalidInput for NaN or infinity).
void writeSceneFile(const std::string& path, const std::string& include, const Scene& scene,
                    const RenderOptions& options, bool ground, UpAxis up = UpAxis::Y);

}  // namespace gnomon::scenefile
