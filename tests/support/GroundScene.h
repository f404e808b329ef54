// The start of the scenes that stand things on a ground: one light grey material and a square
// ground box 0.1 thick, its top at y = 0, casting and receiving shadows (object 0).
#pragma once

#include <string>

#include "gnomon/Scene.h"
#include "scene/MeshBuilder.h"

namespace gnomon::test {

inline Scene sceneWithGround(const std::string& name, float width) {
    Scene s;
    s.name = name;
    Material m;
    m.baseColour = glm::vec3(0.8f);
    s.materials.push_back(m);
    s.meshes.push_back(mesh::box("ground", {0.0f, -0.05f, 0.0f}, {width, 0.1f, width}));
    s.objects.push_back({"ground", 0, 0, glm::mat4(1.0f), {}, true, true});
    return s;
}

}  // namespace gnomon::test
