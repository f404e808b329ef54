// Internal to shadow/: the fits of lights that sit at a point (spot and point lights), and
// what they share with the rest of the fitting in ShadowMath.cpp. A spot's cone or a point
// light's cube, each narrowed to the window of what the view sees when view samples exist.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "core/Aabb.h"
#include "shadow/ShadowMath.h"
#include "shadow/ViewSamples.h"

namespace gnomon::shadow::fit {

// The boxes Fit works with in one frame: visible receivers (clipped to the view frustum's
// box) and all casters.
struct FitBoxes {
    // The frame's (FitScene::visibleReceivers, when filled) or this fit's own.
    const std::vector<Aabb>* shared = nullptr;
    std::vector<Aabb> own;
    const std::vector<Aabb>& receivers() const { return shared ? *shared : own; }
    const std::vector<Aabb>* casters = nullptr;
    bool snap = false;           // the fit follows the view: keep it steady
    HeldExtent* held = nullptr;  // with snap: the extent kept from the previous frame
    // A spot's or point light's range (0: none) around `apex`, its position: receivers and
    // samples beyond it are unlit and casters beyond it shadow nothing lit, so neither counts.
    float reach = 0.0f;
    glm::vec3 apex{0.0f};
    bool beyondReach(const Aabb& box) const { return reach > 0.0f && box.distanceTo(apex) > reach; }
};

// Depth range of the bounds' corners in front of a light camera (view looks down -z).
void depthRange(const Aabb& bounds, const glm::mat4& lightFromWorld, float& nearest,
                float& farthest);
// Rounds `x` up to a step of 1/16 of its power of two: few distinct sizes, at most 1/16 more.
float quantizeUp(float x);

// A point light: one frustum over the view's samples (narrowed to where casters can shadow
// them) when they fit a cube face's angle around their mean direction, else six faces around
// the light.
LightCameraFrame fitPoint(const glm::vec3& position, const ViewSamples* samples,
                          const FitBoxes& boxes, int mapSize);
// Face `face` (0..5: +X, -X, +Y, -Y, +Z, -Z, as cubeFaceRotation) of a point light as one
// perspective frustum: the face's pyramid widened by `marginTan` tan units, narrowed to the
// window of the view's samples in it and to where casters can shadow them; invalid when no
// caster can.
LightCameraFrame fitPointFace(const glm::vec3& position, int face, float marginTan,
                              const ViewSamples* samples, const FitBoxes& boxes, int mapSize);
// A spot light: its cone's window (fovy twice the outer cone angle), narrowed to the part the
// view's samples lie in and to where casters can shadow them (invalid when none can).
LightCameraFrame fitSpot(const glm::vec3& position, const glm::vec3& axis, float fovyRadians,
                         const ViewSamples* samples, const FitBoxes& boxes, int mapSize);

}  // namespace gnomon::shadow::fit
