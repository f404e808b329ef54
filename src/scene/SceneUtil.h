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

// Model loaders: objects whose material is textured but whose mesh has no texture
// coordinates get an untextured copy of that material (one copy per material).
void untextureObjectsWithoutUvs(Scene& scene);
// Model loaders: when `scene` has no lights, adds a default sun and says so in its warnings.
void addDefaultSun(Scene& scene);
// Model loaders without a camera: a 45-degree camera framing `bounds`, and a warning.
void frameWithCamera(Scene& scene, const Aabb& bounds);

}  // namespace gnomon
