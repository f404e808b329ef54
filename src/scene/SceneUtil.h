// Helpers over the scene model used by the renderer and the shadow math (no GL).
#pragma once

#include <vector>

#include "core/Aabb.h"
#include "gnomon/Scene.h"

namespace gnomon {

// Model-space bounds of every mesh, in Scene::meshes order.
std::vector<Aabb> meshBounds(const Scene& scene);
// World-space bounds of the objects at `seconds`; `castersOnly` keeps shadow casters only.
Aabb worldBounds(const Scene& scene, const std::vector<Aabb>& meshBoxes, double seconds,
                 bool castersOnly);
// Is light `index` on for these options (RenderOptions::lightOnly overrides the scene)?
bool lightIsOn(const Scene& scene, const RenderOptions& options, std::size_t index);

}  // namespace gnomon
