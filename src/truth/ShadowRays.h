// The scene's triangles in a tracer (truth/Tracer.h) and its lights, for the reference's rays:
// what the camera sees (every object) and what shadows it (the casters), with masked and
// blended surfaces answering through truth/AlphaRays.h. traceReference builds one and keeps it with
// the Reference, so that the score can trace more shadow rays where it needs to look along a
// surface (Metrics.h: extendBandAlongSurfaces). It points into the Scene it was built from
// (meshes, materials, textures): use it only while that Scene lives.
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "gnomon/Options.h"
#include "gnomon/Scene.h"
#include "truth/AlphaRays.h"
#include "truth/Tracer.h"

namespace gnomon::truth {

class ShadowRays {
public:
    // Throws gnomon::Error (InvalidInput) when the tracer cannot be made for the scene.
    // `kind`: the tracer behind the rays (truth/Tracer.h).
    ShadowRays(const Scene& scene, const RenderOptions& options, TracerKind kind = defaultTracer());
    ShadowRays(const ShadowRays&) = delete;
    ShadowRays& operator=(const ShadowRays&) = delete;

    // The rays themselves: view rays against every object, shadow rays against the casters.
    const Tracer& tracer() const { return *mTracer; }
    // Throws gnomon::Error when the tracer reports a failure since the last call.
    void check(const char* what) const { mTracer->check(what); }

    // Every point, position and light here is relative to this one (coordinateOrigin of the
    // scene's bounds), as the renderer's are: rays started off a surface 10 000 units out
    // otherwise start a float's step (0.001) or more away from it.
    const glm::vec3& origin() const { return mOrigin; }
    // Object o's positions relative to origin() (as the renderer places them at options.time).
    const std::vector<glm::vec3>& positions(std::size_t o) const { return mPositions[o]; }
    // Light l, placed relative to origin().
    const Light& light(std::size_t l) const { return mLights[l]; }
    // The scene's size, for ray offsets.
    float scale() const { return mScale; }
    // How far along `dir` a ray leaving the surface point `point` (normal `n`, on the side
    // the ray leaves from) starts. The ray keeps to the line through the point itself and
    // skips only the stretch within a margin of the surface's plane (float rounding of the
    // point: it grows with the scene and with the distance from the origin). A start pushed
    // off along the normal would move the whole ray sideways by that margin, past occluders
    // thinner than it (tests/crosscheck's exact caster finds those).
    float lead(const glm::vec3& point, const glm::vec3& n, const glm::vec3& dir) const;

    // Light l's direction from `point` and the distance to it (infinite for a sun); false
    // where the light does not reach that far (off, behind an area light's plane, beyond
    // its range, outside a spot's cone): there is no shadow of it to show.
    bool towardsLight(std::size_t l, const glm::vec3& point, glm::vec3& toLight,
                      float& distance) const;
    // The share of light arriving along the ray point + t dir, near < t < far: 0 when
    // something opaque is in the way, the product of dithered blended surfaces' 1 - alpha
    // otherwise; `tint` (if set) gets the product of coloured blended surfaces' transmittance.
    float transmitted(const glm::vec3& point, const glm::vec3& dir, float near, float far,
                      glm::vec3* tint = nullptr) const;

    // Light l's hard shadow at a surface point of normal `n`: 1 lit, 0 shadowed or facing
    // away (its attached shadow), -1 where the light does not reach (towardsLight).
    int side(std::size_t l, const glm::vec3& point, const glm::vec3& n) const;
    // True when light l's hard shadow is not `here` somewhere on the surface around `point`
    // within `radius` of it: probed at 16 points on two circles in the surface's plane, each
    // moved onto the surface it lies nearest (within the radius) along the normal. A
    // boundary there can be out of the camera's sight (under the caster, behind a fold).
    bool otherSideWithin(std::size_t l, const glm::vec3& point, const glm::vec3& n, float radius,
                         int here) const;

    // A light's direction, normalised (straight down where it has none).
    static glm::vec3 directionOf(const Light& light);

    // A surface the light meets at under 0.06 degrees counts as edge-on: in its own attached
    // shadow, as one facing away is. A flat face there gets under a thousandth of the light
    // (under half an 8-bit step at full intensity), so no picture shows which it is; the light's
    // map holds it in no texel of its own, and which side of it the light lies on is decided by
    // the rounding of its vertices and of the light's direction (a wall under a sun whose
    // azimuth is a multiple of 90 degrees: cos 90 degrees is 4e-8 in float). The lookups call a
    // plane edge-on at the same angle (shaders/receiver_plane.glsl) and move off it; scored as
    // lit or shadowed, such faces would count what no picture can show.
    static constexpr float kEdgeOnCosine = 1e-3f;  // sin 0.057 degrees

private:
    std::vector<std::vector<glm::vec3>> mPositions;
    std::vector<AlphaSurface> mAlpha;  // per object: masked and blended ones only
    std::vector<Light> mLights;
    std::vector<bool> mOn;  // per light: on and casting shadows
    BlendShadows mBlend;
    float mScale = 1.0f;
    glm::vec3 mOrigin{0.0f};
    std::unique_ptr<Tracer> mTracer;  // last: it points into the members above
};

}  // namespace gnomon::truth
