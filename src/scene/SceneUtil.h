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
// The point the renderer and the reference take their coordinates relative to, for a scene
// whose objects' world bounds are `worldBox`: 0 while the box lies within a few of its radii
// of the world's origin (scenes built around it keep their numbers bit for bit), else its
// centre snapped to a power-of-two grid of about its size (objects moving within the scene
// do not move it). Far from the origin a float keeps few bits below a model's size (at
// 10 000 it steps by 0.001): positions interpolated across a triangle and multiplied by a
// light's matrix, or shadow rays started off a surface, go wrong there by that much.
glm::vec3 coordinateOrigin(const Aabb& worldBox);
// The scene's coordinateOrigin, its objects placed at `seconds` (reads every vertex).
glm::vec3 sceneOrigin(const Scene& scene, double seconds);
// What the world places, moved to coordinates relative to `origin` (the renderer's scene
// near the origin, render/RelativeScene.h, and the reference's rays, truth/ShadowRays.h, both
// through these, so the two agree to the bit). In double precision, then float: as exact as
// the world's own floats.
glm::vec3 relativeTo(const glm::vec3& worldPoint, const glm::vec3& origin);
void makeRelative(Object& object, const glm::vec3& origin);  // its matrix and spin pivot
void makeRelative(Light& light, const glm::vec3& origin);    // position, shadow-camera target
void makeRelative(Camera& camera, const glm::vec3& origin);  // eye and centre
// Is light `index` on for these options (RenderOptions::lightOnly overrides the scene)?
bool lightIsOn(const Scene& scene, const RenderOptions& options, std::size_t index);

}  // namespace gnomon
