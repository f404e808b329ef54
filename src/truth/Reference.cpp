#include "truth/Reference.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <thread>

#include "gnomon/Error.h"
#include "scene/CameraMath.h"
#include "scene/SceneUtil.h"
#include "truth/ShadowRays.h"

namespace gnomon::truth {

namespace {

// A point of a unit disc: sample i of n on a sunflower spiral, turned by `turn` radians.
glm::vec2 discSample(int i, int n, float turn) {
    const float r = std::sqrt((float(i) + 0.5f) / float(n));
    const float a = float(i) * 2.39996323f + turn;  // the golden angle
    return {r * std::cos(a), r * std::sin(a)};
}

// Two unit vectors perpendicular to `w` and to each other.
void basis(const glm::vec3& w, glm::vec3& u, glm::vec3& v) {
    const glm::vec3 a = std::fabs(w.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    u = glm::normalize(glm::cross(w, a));
    v = glm::cross(w, u);
}

// Per-pixel rotation of the sample pattern (a hash of the pixel), so the soft reference's
// error is noise, not banding.
float pixelTurn(int x, int y) {
    std::uint32_t h = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return float(h & 0xffffu) / 65536.0f * 6.2831853f;
}

// A reference with nothing hit yet: every cell lit.
Reference emptyReference(int width, int height, int lights, int samples, bool coloured,
                         bool contacts) {
    Reference ref;
    ref.width = width;
    ref.height = height;
    ref.lights = lights;
    const std::size_t pixels = std::size_t(ref.width) * std::size_t(ref.height);
    const std::size_t cells = pixels * std::size_t(ref.lights);
    ref.object.assign(pixels, -1);
    ref.pixelWorld.assign(pixels, 0.0f);
    ref.surfacePoint.assign(pixels, glm::vec3(0.0f));
    ref.surfaceNormal.assign(pixels, glm::vec3(0.0f));
    ref.applies.assign(cells, 0);
    ref.hard.assign(cells, 1.0f);
    ref.lightCosine.assign(cells, 1.0f);
    if (samples > 0) ref.soft.assign(cells, 1.0f);
    if (coloured) ref.tint.assign(cells, glm::vec3(1.0f));
    if (contacts) ref.nearOccluder.assign(cells, 0);
    return ref;
}

// Each shadowing light's visibility at one surface point, into the reference's cells.
struct LightTracer {
    const Scene& scene;
    Reference& ref;
    const ShadowRays& rays;
    int samples;         // soft-shadow rays per light (0: hard shadows only)
    float contactRange;  // > 0: mark occluders this near (Reference::nearOccluder)
    float tanAngle;      // directional lights' angular radius, as a tangent
    float radius;        // other lights' emitter radius

    // `point` seen at `pixel` (normal n, facing the camera); `turn` rotates the soft-shadow
    // disc per pixel.
    void trace(std::size_t pixel, const Material& mat, const glm::vec3& point, const glm::vec3& n,
               float turn) const {
        for (std::size_t l = 0; l < scene.lights.size(); ++l) {
            glm::vec3 toLight;
            float distance = 0.0f;
            if (!rays.towardsLight(l, point, toLight, distance)) continue;
            const Light& light = scene.lights[l];
            const glm::vec3 ld = ShadowRays::directionOf(light);
            const std::size_t cell = pixel * std::size_t(ref.lights) + l;
            if (!mat.unlit && !(glm::dot(n, toLight) > ShadowRays::kEdgeOnCosine)) {
                ref.lightCosine[cell] = 0.0f;  // faces away: in its own attached shadow
                continue;
            }
            ref.applies[cell] = 1;
            ref.lightCosine[cell] = mat.unlit ? 1.0f : glm::dot(n, toLight);
            const float near = rays.lead(point, n, toLight);
            ref.hard[cell] = rays.transmitted(point, toLight, near, distance,
                                              ref.tint.empty() ? nullptr : &ref.tint[cell]);
            if (contactRange > 0.0f && ref.hard[cell] < 0.5f) {
                ref.nearOccluder[cell] =
                    rays.transmitted(point, toLight, near, std::min(distance, contactRange)) < 0.5f;
            }
            if (samples == 0) continue;
            float visible = 0.0f;
            glm::vec3 u, v;
            if (light.type == LightType::Directional) {
                basis(toLight, u, v);
                for (int i = 0; i < samples; ++i) {
                    const glm::vec2 s = discSample(i, samples, turn) * tanAngle;
                    const glm::vec3 d = glm::normalize(toLight + s.x * u + s.y * v);
                    visible += sampleLight(point, n, d, distance);
                }
            } else {
                // A disc of `radius`: around the light facing the point (spot, point), or
                // in the area light's plane around the point's foot.
                const glm::vec3 centre =
                    light.type == LightType::Area ? point - ld * distance : rays.light(l).position;
                basis(light.type == LightType::Area ? ld : toLight, u, v);
                for (int i = 0; i < samples; ++i) {
                    const glm::vec2 s = discSample(i, samples, turn) * radius;
                    const glm::vec3 q = centre + s.x * u + s.y * v;
                    const glm::vec3 d = q - point;
                    const float len = glm::length(d);
                    if (len > 0.0f) visible += sampleLight(point, n, d / len, len * 0.99999f);
                }
            }
            ref.soft[cell] = visible / float(samples);
        }
    }

    // One soft-shadow ray: a part of the light below the surface's horizon sends it nothing.
    float sampleLight(const glm::vec3& point, const glm::vec3& n, const glm::vec3& d,
                      float far) const {
        if (!(glm::dot(n, d) > ShadowRays::kEdgeOnCosine)) return 0.0f;
        return rays.transmitted(point, d, rays.lead(point, n, d), far);
    }
};

}  // namespace

// The view's setup, made once, and the rows traced so far.
struct ReferenceTrace::State {
    State(const Scene& scene, const RenderOptions& options, const ReferenceOptions& ro);
    void tracePixel(int x, int y);

    const Scene& scene;
    const ReferenceOptions ro;
    const int width, height;
    const std::shared_ptr<const ShadowRays> rays;
    Reference ref;
    const LightTracer lightTracer;  // writes into `ref`, traces through `rays`
    // View rays in the rays' coordinates (ShadowRays::origin), from the camera moved there as
    // the renderer moves it (render/RelativeScene.h): the same view to the last bit.
    Camera camera;
    PixelRayTerms terms;  // each pixel's ray's terms (pixelRayTerms), from `camera`
    std::atomic<int> nextRow{0}, rowsDone{0};
};

namespace {
const Scene& validated(const Scene& scene) {
    if (auto problems = scene.validate(); !problems.empty()) {
        throw Error(ErrorKind::InvalidInput, "ground truth: " + problems.front());
    }
    return scene;
}
}  // namespace

ReferenceTrace::State::State(const Scene& s, const RenderOptions& options,
                             const ReferenceOptions& o)
    : scene(validated(s)),
      ro(o),
      width(options.width),
      height(options.height),
      rays(std::make_shared<const ShadowRays>(scene, options, o.tracer)),
      ref(emptyReference(
          options.width, options.height, int(scene.lights.size()), std::max(o.softSamples, 0),
          options.shadow.blendShadows == BlendShadows::Coloured, o.contactRange > 0.0f)),
      lightTracer{scene,
                  ref,
                  *rays,
                  std::max(o.softSamples, 0),
                  std::max(o.contactRange, 0.0f),
                  std::tan(glm::radians(options.shadow.lightAngle)),
                  options.shadow.lightRadius},
      camera(scene.camera) {
    makeRelative(camera, rays->origin());
    terms = pixelRayTerms(camera, width, height);
}

void ReferenceTrace::State::tracePixel(int x, int y) {
    const float nx = (float(x) + 0.5f) / float(width) * 2.0f - 1.0f;
    const float ny = 1.0f - (float(y) + 0.5f) / float(height) * 2.0f;
    const glm::vec3 eye = camera.eye;
    // Between the near and far planes, as the raster clips.
    glm::vec3 from = eye, dir = terms.ahead;
    float tnear = camera.near, tfar = camera.far;
    if (terms.ortho) {
        from +=
            terms.right *
                (0.5f * (nx * (camera.right - camera.left) + camera.right + camera.left)) +
            terms.up * (0.5f * (ny * (camera.top - camera.bottom) + camera.top + camera.bottom));
    } else {
        const glm::vec3 d = terms.ahead + terms.right * (nx * terms.tanHalf * terms.viewAspect) +
                            terms.up * (ny * terms.tanHalf);
        const float length = glm::length(d);
        dir = d / length;
        tnear *= length;  // the planes lie at view depths near and far: t = depth x length
        tfar *= length;
    }
    const Tracer& tracer = rays->tracer();
    // Single-sided surfaces seen from behind are culled by the main pass: look past them.
    for (int attempt = 0; attempt < 64; ++attempt) {
        const TraceHit hit = tracer.nearest(from, dir, tnear, tfar);
        if (!hit.hit()) return;
        const int o = hit.object;
        const Object& obj = scene.objects[std::size_t(o)];
        const Mesh& mesh = scene.meshes[obj.mesh];
        const std::vector<glm::vec3>& p = rays->positions(std::size_t(o));
        const std::uint32_t* t = &mesh.indices[3 * std::size_t(hit.triangle)];
        glm::vec3 n = glm::cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]);  // CCW = front
        const float nl = glm::length(n);
        if (!(nl > 0.0f)) {
            tnear = hit.t * (1.0f + 1e-6f) + 1e-7f * rays->scale();
            continue;
        }
        n /= nl;
        const Material& mat = scene.materials[obj.material];
        if (glm::dot(n, dir) > 0.0f) {
            if (!mat.doubleSided) {
                tnear = hit.t * (1.0f + 1e-6f) + 1e-7f * rays->scale();
                continue;
            }
            n = -n;  // the side the camera sees
        }
        // The point from its triangle's corners rather than from + dir * t: its rounding
        // is then that of the scene's coordinates, not of the camera's distance, so the
        // shadow rays' margin (ShadowRays::lead) can stay small however far the camera.
        const float u = hit.u, v = hit.v;
        const glm::vec3 point = (1.0f - u - v) * p[t[0]] + u * p[t[1]] + v * p[t[2]];
        const std::size_t pixel = std::size_t(y) * std::size_t(width) + std::size_t(x);
        ref.object[pixel] = o;
        ref.pixelWorld[pixel] =
            terms.pixelAtUnit *
            (terms.ortho ? 1.0f : std::max(glm::dot(point - eye, terms.ahead), 0.0f));
        if (!obj.receivesShadows) return;
        ref.surfacePoint[pixel] = point;
        ref.surfaceNormal[pixel] = n;
        lightTracer.trace(pixel, mat, point, n, pixelTurn(x, y));
        return;
    }
}

ReferenceTrace::ReferenceTrace(const Scene& scene, const RenderOptions& options,
                               const ReferenceOptions& referenceOptions)
    : mState(std::make_unique<State>(scene, options, referenceOptions)) {}
ReferenceTrace::~ReferenceTrace() = default;
ReferenceTrace::ReferenceTrace(ReferenceTrace&&) noexcept = default;
ReferenceTrace& ReferenceTrace::operator=(ReferenceTrace&&) noexcept = default;

int ReferenceTrace::rowsDone() const {
    return mState->rowsDone.load();
}
int ReferenceTrace::rows() const {
    return mState->height;
}

// Each thread takes the next row until none is left, the deadline has passed (once a row
// was taken) or the trace is cancelled; rows taken are always finished.
bool ReferenceTrace::traceRows(std::chrono::steady_clock::time_point deadline) {
    State& s = *mState;
    const ReferenceOptions& o = s.ro;
    std::atomic<bool> taken{false};
    auto worker = [&] {
        for (;;) {
            if (o.cancel && o.cancel->load()) return;
            if (taken.load() && std::chrono::steady_clock::now() >= deadline) return;
            const int y = s.nextRow++;
            if (y >= s.height) return;
            taken = true;
            for (int x = 0; x < s.width; ++x)
                s.tracePixel(x, y);
            ++s.rowsDone;
            if (o.rowsDone) ++*o.rowsDone;
        }
    };
    const int left = s.height - std::min(s.nextRow.load(), s.height);
    const int threads = std::min(
        o.threads > 0 ? o.threads : std::max(1, int(std::thread::hardware_concurrency())), left);
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i)
        pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool)
        t.join();
    s.nextRow = std::min(s.nextRow.load(), s.height);  // workers overshoot by one each
    s.rays->check("trace rays");
    if (o.cancel && o.cancel->load()) {
        throw Error(ErrorKind::InvalidInput, "ray-traced reference cancelled");
    }
    return s.rowsDone.load() == s.height;
}

Reference ReferenceTrace::finish() {
    State& s = *mState;
    if (s.rowsDone.load() != s.height) {
        throw Error(ErrorKind::InvalidInput, "ground truth: the reference is not traced yet");
    }
    s.ref.rays = s.rays;
    return std::move(s.ref);
}

Reference traceReference(const Scene& scene, const RenderOptions& options,
                         const ReferenceOptions& referenceOptions) {
    ReferenceTrace trace(scene, options, referenceOptions);
    trace.traceRows(std::chrono::steady_clock::time_point::max());
    return trace.finish();
}

}  // namespace gnomon::truth
