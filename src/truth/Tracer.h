// The ray tracer the reference stands on, as a small interface: the nearest surface along a
// view ray, and the light a shadow ray lets through. Embree 3 is behind it natively
// (makeEmbreeTracer); the project's own BVH (makeBvhTracer, bvh/Bvh.h) stands in where
// Embree cannot go.
// Every backend answers masked and blended surfaces by the same rules (truth/AlphaRays.h).
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "gnomon/Options.h"
#include "gnomon/Scene.h"
#include "truth/AlphaRays.h"

namespace gnomon::truth {

// What a tracer is built from: each object's triangles in the rays' coordinates (positions
// indexed by its mesh's indices), with the alpha rule of its material.
struct TracerInput {
    const Scene* scene = nullptr;
    const std::vector<std::vector<glm::vec3>>* positions = nullptr;  // per object
    const std::vector<AlphaSurface>* alpha = nullptr;  // per object: material null if opaque
    BlendShadows blend = BlendShadows::Dithered;       // what blended casters do to light
};

// The surface a ray met: the object, its triangle, the barycentrics (u, v) of the hit
// (the point is (1 - u - v) p0 + u p1 + v p2) and the distance along the ray.
struct TraceHit {
    int object = -1;  // -1: nothing hit
    unsigned triangle = 0;
    float u = 0.0f, v = 0.0f;
    float t = 0.0f;
    glm::vec3 geometricNormal{0.0f};  // not normalised, either side
    bool hit() const { return object >= 0; }
};

class Tracer {
public:
    virtual ~Tracer() = default;
    // The nearest surface of any object along origin + t dir, tnear < t < tfar, as a view
    // ray sees: through cut-away texels of masked surfaces and through blended surfaces.
    virtual TraceHit nearest(const glm::vec3& origin, const glm::vec3& dir, float tnear,
                             float tfar) const = 0;
    // The share of light the casters let through along origin + t dir, tnear < t < tfar: 0
    // when something opaque is in the way, else the product of what blended casters pass
    // (TracerInput::blend); `tint` (if set) gets the coloured rule's product.
    virtual float transmitted(const glm::vec3& origin, const glm::vec3& dir, float tnear,
                              float tfar, glm::vec3* tint) const = 0;
    // Throws gnomon::Error when the backend reported a failure since the last call.
    virtual void check(const char* what) const = 0;
};

// Which tracer the reference stands on (ShadowRays, ReferenceOptions): a library-level
// choice, Embree unless a caller asks for the BVH.
enum class TracerKind { Embree, Bvh };
const char* toString(TracerKind kind);
// Embree where the build has it, else the project's BVH (the web build).
TracerKind defaultTracer();

// Embree 3 (two BVHs: every object for view rays, the casters for shadow rays). Throws
// gnomon::Error (InvalidInput) when Embree has no device or rejects the scene.
std::unique_ptr<Tracer> makeEmbreeTracer(const TracerInput& input);

// The project's own BVH (bvh/Bvh.h; no Embree): one hierarchy, casters flagged. Throws
// gnomon::Error (InvalidInput) for a scene of more than 2^23 triangles (kBvhMaxTriangles).
std::unique_ptr<Tracer> makeBvhTracer(const TracerInput& input);

}  // namespace gnomon::truth
