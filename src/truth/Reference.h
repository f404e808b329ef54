// Ray-traced ground truth (no GL): a tracer (truth/Tracer.h; Embree 3 natively) holds the
// scene's world-space triangles; for each pixel of the view the surface the camera sees is
// traced from the same camera (through the pixel's centre, where rasterisation samples too),
// and a shadow ray per light gives the exact hard-shadow answer. Soft references: the
// fraction of N rays to points on the light's surface (a disc of lightRadius for spot, point
// and area lights, a cone of lightAngle for directional ones: the emitters PCSS models). Rows
// are split over all cores, in one go (traceReference) or a few at a time (ReferenceTrace).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "gnomon/Options.h"
#include "gnomon/Scene.h"
#include "truth/Tracer.h"

namespace gnomon::truth {

class ShadowRays;

struct ReferenceOptions {
    int softSamples = 0;  // rays per pixel and light for the soft reference; 0: hard only
    // > 0: also mark the shadowed cells whose occluder lies within this distance of the
    // surface along the shadow ray (Reference::nearOccluder): the contacts.
    float contactRange = 0.0f;
    int threads = 0;                            // 0: every core
    std::atomic<int>* rowsDone = nullptr;       // if set: counts rows traced (progress)
    const std::atomic<bool>* cancel = nullptr;  // if set and true: stop early, throw Error
    TracerKind tracer = defaultTracer();        // the rays' tracer (truth/Tracer.h)
};

// Per pixel (rows top first, as images), and per pixel x light at [pixel * lights + light].
struct Reference {
    int width = 0, height = 0, lights = 0;
    std::vector<int> object;        // object index the camera sees, -1: nothing
    std::vector<float> pixelWorld;  // world size of the pixel's footprint at the surface
    // Where a receiving surface is seen: its point (relative to rays->origin()) and geometric
    // normal (towards the camera).
    std::vector<glm::vec3> surfacePoint, surfaceNormal;
    // 1 where the light's shadow can show: the light is on and casts shadows, the object
    // receives them, and the light reaches the surface (in front of it, inside a spot's
    // cone, on the lit side of an area light's plane).
    std::vector<std::uint8_t> applies;
    // 1 lit, 0 occluded (where applies); between where light passes dithered blended
    // casters (1 - alpha each, --blend-shadows dithered).
    std::vector<float> hard;
    // --blend-shadows coloured only (else empty): the product of the transmittance of the
    // blended casters the hard ray passed (truth/AlphaRays.h); the light arriving is
    // hard x tint.
    std::vector<glm::vec3> tint;
    // Cosine between the surface's geometric normal and the direction to the light (where
    // applies): how far a map texel stretches along the surface, 1 / cosine. 0 where the
    // surface faces away from the light (its attached shadow, where applies is 0).
    std::vector<float> lightCosine;
    std::vector<float> soft;  // fraction of the light's surface visible (softSamples > 0)
    // ReferenceOptions::contactRange > 0 only (else empty): 1 where the hard ray is occluded
    // within that distance of the surface (a contact shadow's reach), 0 elsewhere.
    std::vector<std::uint8_t> nearOccluder;
    // The scene as traced, for more shadow rays later (truth/ShadowRays.h): valid while the
    // Scene it was traced from lives.
    std::shared_ptr<const ShadowRays> rays;

    std::size_t at(int x, int y, int light) const {
        return (std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(lights) +
               std::size_t(light);
    }
};

// Traces `scene` at options.time as the renderer would draw it at options.width x height.
// Throws gnomon::Error (Gl kind is never used; InvalidInput for a scene the tracer rejects).
Reference traceReference(const Scene& scene, const RenderOptions& options,
                         const ReferenceOptions& referenceOptions);

// traceReference a few rows at a time, for callers that must return between slices (a web
// page has no threads: its score and tune trace between frames). The view's setup (the scene
// in the tracer, the camera's axes) is made once; each pixel writes only its own cells, so
// the reference is the same bit for bit however its rows are split into slices or shared
// among threads.
class ReferenceTrace {
public:
    // Validates the scene and puts it in the tracer, the slow part for a large scene. The
    // trace points into `scene`, which must outlive it unchanged (Reference::rays as well).
    // Throws gnomon::Error as traceReference does.
    ReferenceTrace(const Scene& scene, const RenderOptions& options,
                   const ReferenceOptions& referenceOptions);
    ~ReferenceTrace();
    ReferenceTrace(ReferenceTrace&&) noexcept;
    ReferenceTrace& operator=(ReferenceTrace&&) noexcept;

    // Traces rows not traced yet, at least one, taking no new row once `deadline` has passed
    // (on referenceOptions.threads threads), and says whether every row is now traced. Throws
    // gnomon::Error when the tracer fails or referenceOptions.cancel is set.
    bool traceRows(std::chrono::steady_clock::time_point deadline);
    int rowsDone() const;  // any thread may ask while another traces
    int rows() const;
    // The reference, once traceRows has returned true; the trace is spent.
    Reference finish();

private:
    struct State;
    std::unique_ptr<State> mState;
};

}  // namespace gnomon::truth
