#include "truth/Reference.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <thread>

#include <embree3/rtcore.h>

#include "gnomon/Error.h"
#include "scene/SceneUtil.h"
#include "shadow/ShadowMath.h"
#include "truth/AlphaRays.h"

namespace gnomon::truth {

namespace {

// A surface the light meets at under 0.06 degrees counts as edge-on: in its own attached
// shadow, as one facing away is. A flat face there gets under 0.1 % of the light (under half
// an 8-bit step at full intensity), so no picture shows which it is; the light's map holds
// it in no texel of its own, and which side of it the light lies on is decided by the
// rounding of its vertices and of the light's direction (a wall under a sun whose azimuth is
// a multiple of 90 degrees: cos 90 degrees is 4e-8 in float). The same angle where the
// lookups call a plane edge-on (shaders/receiver_plane.glsl) and move off it: counted as lit
// or shadowed, such faces were scored on what a picture cannot show (tutorial-room under a
// sun at 180,30: 7 % false shadow with no cut; a face of the Fox's neck 0.05 degrees from
// edge-on, shadowed by the neck beside it, 2.9 % of a view's leak away from edges with a
// cut at 0.01 degrees).
constexpr float kEdgeOnCosine = 1e-3f;  // sin 0.057 degrees

struct DeviceDeleter {
    void operator()(RTCDevice d) const { rtcReleaseDevice(d); }
};
struct SceneDeleter {
    void operator()(RTCScene s) const { rtcReleaseScene(s); }
};
using Device = std::unique_ptr<RTCDeviceTy, DeviceDeleter>;
using EmbreeScene = std::unique_ptr<RTCSceneTy, SceneDeleter>;

void check(RTCDevice device, const char* what) {
    const RTCError e = rtcGetDeviceError(device);
    if (e != RTC_ERROR_NONE) {
        throw Error(ErrorKind::InvalidInput, std::string("ground truth: Embree failed to ") + what +
                                                 " (error " + std::to_string(int(e)) + ")");
    }
}

// The scene's triangles in world space, per object, as both the renderer and Embree see them.
struct World {
    std::vector<std::vector<glm::vec3>> positions;  // per object, world space
    std::vector<const Mesh*> meshes;
    float scale = 1.0f;  // the scene's size, for ray offsets
};

RTCScene buildScene(RTCDevice device, const Scene& scene, const World& world,
                    const std::vector<AlphaSurface>& alpha, bool castersOnly) {
    RTCScene s = rtcNewScene(device);
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const Object& obj = scene.objects[o];
        if (castersOnly && !obj.castsShadows) continue;
        const Mesh& mesh = *world.meshes[o];
        const std::size_t triangles = mesh.indices.size() / 3;
        if (triangles == 0 || mesh.positions.empty()) continue;
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                              RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                              mesh.positions.size()));
        auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles));
        if (!v || !idx) {
            rtcReleaseGeometry(g);
            rtcReleaseScene(s);
            check(device, "allocate geometry");
            throw Error(ErrorKind::InvalidInput, "ground truth: out of memory for geometry");
        }
        const std::vector<glm::vec3>& p = world.positions[o];
        for (std::size_t i = 0; i < p.size(); ++i) {
            v[3 * i] = p[i].x;
            v[3 * i + 1] = p[i].y;
            v[3 * i + 2] = p[i].z;
        }
        std::copy(mesh.indices.begin(), mesh.indices.begin() + std::ptrdiff_t(3 * triangles), idx);
        if (alpha[o].material) {  // masked or blended: every hit asks its alpha
            rtcSetGeometryUserData(g, const_cast<AlphaSurface*>(&alpha[o]));
            rtcSetGeometryIntersectFilterFunction(g, &alphaFilter);
            rtcSetGeometryOccludedFilterFunction(g, &alphaFilter);
        }
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(s, g, unsigned(o));
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(s);
    check(device, "build the scene's BVH");
    return s;
}

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

// The share of light that arrives along the ray: 0 when something opaque is in the way, the
// product of dithered blended surfaces' 1 - alpha otherwise; `tint` (if set) gets the
// product of coloured blended surfaces' transmittance.
float transmitted(RTCScene scene, BlendShadows blend, const glm::vec3& origin, const glm::vec3& dir,
                  float far, glm::vec3* tint = nullptr) {
    AlphaContext context;
    rtcInitIntersectContext(&context.base);
    context.blend = blend;
    RTCRay ray{};
    ray.org_x = origin.x;
    ray.org_y = origin.y;
    ray.org_z = origin.z;
    ray.dir_x = dir.x;
    ray.dir_y = dir.y;
    ray.dir_z = dir.z;
    ray.tnear = 0.0f;
    ray.tfar = far;
    ray.mask = 0xffffffffu;
    rtcOccluded1(scene, &context.base, &ray);
    if (tint) *tint = context.tint;
    return ray.tfar < 0.0f ? 0.0f : context.transmission;  // Embree sets tfar to -inf on a hit
}

// Runs `row(y)` for rows 0..height-1 on the threads `o` asks for (0: every core), each
// taking the next row; stops taking rows once `o.cancel` is set, counts rows in `o.rowsDone`.
template <typename Row>
void forEachRow(int height, const ReferenceOptions& o, const Row& row) {
    const int threads =
        o.threads > 0 ? o.threads : std::max(1, int(std::thread::hardware_concurrency()));
    std::atomic<int> nextRow{0};
    auto worker = [&] {
        for (int y = nextRow++; y < height; y = nextRow++) {
            if (o.cancel && o.cancel->load()) return;
            row(y);
            if (o.rowsDone) ++*o.rowsDone;
        }
    };
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i)
        pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool)
        t.join();
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
    ref.applies.assign(cells, 0);
    ref.hard.assign(cells, 1.0f);
    ref.lightCosine.assign(cells, 1.0f);
    if (samples > 0) ref.soft.assign(cells, 1.0f);
    if (coloured) ref.tint.assign(cells, glm::vec3(1.0f));
    if (contacts) ref.nearOccluder.assign(cells, 0);
    return ref;
}

// Every object's positions in world space at `seconds`, and the scene's size.
World buildWorld(const Scene& scene, double seconds) {
    World world;
    Aabb bounds;
    for (const Object& obj : scene.objects) {
        const Mesh& mesh = scene.meshes[obj.mesh];
        const glm::mat4 m = obj.worldFromModelAt(seconds);
        std::vector<glm::vec3> p(mesh.positions.size());
        for (std::size_t i = 0; i < p.size(); ++i) {
            p[i] = glm::vec3(m * glm::vec4(mesh.positions[i], 1.0f));
            bounds.extend(p[i]);
        }
        world.positions.push_back(std::move(p));
        world.meshes.push_back(&mesh);
    }
    world.scale = bounds.empty() ? 1.0f : std::max(bounds.radius(), 1e-6f);
    return world;
}

// Each shadowing light's visibility at one surface point, into the reference's cells.
struct LightTracer {
    const Scene& scene;
    Reference& ref;
    RTCScene casters;
    BlendShadows blend;
    int samples;         // soft-shadow rays per light (0: hard shadows only)
    float contactRange;  // > 0: mark occluders this near (Reference::nearOccluder)
    float tanAngle;      // directional lights' angular radius, as a tangent
    float radius;        // other lights' emitter radius
    const std::vector<bool>& on;

    // `point` seen at `pixel` (normal n, facing the camera), rays leaving from `origin`;
    // `turn` rotates the soft-shadow disc per pixel.
    void trace(std::size_t pixel, const Material& mat, const glm::vec3& point,
               const glm::vec3& origin, const glm::vec3& n, float turn) const {
        for (std::size_t l = 0; l < scene.lights.size(); ++l) {
            if (!on[l]) continue;
            const Light& light = scene.lights[l];
            const glm::vec3 ld = glm::length(light.direction) > 0.0f
                                     ? glm::normalize(light.direction)
                                     : glm::vec3(0, -1, 0);
            glm::vec3 toLight;
            float distance = std::numeric_limits<float>::infinity();
            switch (light.type) {
                case LightType::Directional:
                    toLight = -ld;
                    break;
                case LightType::Area: {
                    toLight = -ld;
                    distance = glm::dot(point - light.position, ld);
                    if (!(distance > 0.0f)) continue;  // behind the light's plane
                    break;
                }
                case LightType::Spot:
                case LightType::Point: {
                    const glm::vec3 d = light.position - origin;
                    distance = glm::length(d);
                    if (!(distance > 0.0f)) continue;
                    if (light.range > 0.0f && distance >= light.range) continue;  // unlit
                    toLight = d / distance;
                    if (light.type == LightType::Spot &&
                        !(glm::dot(-toLight, ld) >
                          std::cos(glm::radians(light.outerConeDegrees)))) {
                        continue;  // outside the cone: no light to shadow
                    }
                    break;
                }
            }
            const std::size_t cell = pixel * std::size_t(ref.lights) + l;
            if (!mat.unlit && !(glm::dot(n, toLight) > kEdgeOnCosine)) {
                ref.lightCosine[cell] = 0.0f;  // faces away: in its own attached shadow
                continue;
            }
            ref.applies[cell] = 1;
            ref.lightCosine[cell] = mat.unlit ? 1.0f : glm::dot(n, toLight);
            ref.hard[cell] = transmitted(casters, blend, origin, toLight, distance,
                                         ref.tint.empty() ? nullptr : &ref.tint[cell]);
            if (contactRange > 0.0f && ref.hard[cell] < 0.5f) {
                ref.nearOccluder[cell] = transmitted(casters, blend, origin, toLight,
                                                     std::min(distance, contactRange)) < 0.5f;
            }
            if (samples == 0) continue;
            float visible = 0.0f;
            glm::vec3 u, v;
            if (light.type == LightType::Directional) {
                basis(toLight, u, v);
                for (int i = 0; i < samples; ++i) {
                    const glm::vec2 s = discSample(i, samples, turn) * tanAngle;
                    const glm::vec3 d = glm::normalize(toLight + s.x * u + s.y * v);
                    visible += transmitted(casters, blend, origin, d, distance);
                }
            } else {
                // A disc of `radius`: around the light facing the point (spot, point), or
                // in the area light's plane around the point's foot.
                const glm::vec3 centre =
                    light.type == LightType::Area ? point - ld * distance : light.position;
                basis(light.type == LightType::Area ? ld : toLight, u, v);
                for (int i = 0; i < samples; ++i) {
                    const glm::vec2 s = discSample(i, samples, turn) * radius;
                    const glm::vec3 q = centre + s.x * u + s.y * v;
                    const glm::vec3 d = q - origin;
                    const float len = glm::length(d);
                    if (len > 0.0f)
                        visible += transmitted(casters, blend, origin, d / len, len * 0.99999f);
                }
            }
            ref.soft[cell] = visible / float(samples);
        }
    }
};

}  // namespace

Reference traceReference(const Scene& scene, const RenderOptions& options,
                         const ReferenceOptions& referenceOptions) {
    if (auto problems = scene.validate(); !problems.empty()) {
        throw Error(ErrorKind::InvalidInput, "ground truth: " + problems.front());
    }
    const World world = buildWorld(scene, options.time);
    std::vector<AlphaSurface> alpha(scene.objects.size());
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const Material& m = scene.materials[scene.objects[o].material];
        if (m.alphaMode == AlphaMode::Opaque) continue;
        alpha[o] = {
            world.meshes[o], &m,
            m.baseColourTexture >= 0 ? &scene.textures[std::size_t(m.baseColourTexture)] : nullptr};
    }
    const BlendShadows blend = options.shadow.blendShadows;

    Device device(rtcNewDevice(nullptr));
    if (!device) throw Error(ErrorKind::InvalidInput, "ground truth: Embree found no device");
    const EmbreeScene all(buildScene(device.get(), scene, world, alpha, false));
    const EmbreeScene casters(buildScene(device.get(), scene, world, alpha, true));

    const int samples = std::max(referenceOptions.softSamples, 0);
    const float contactRange = std::max(referenceOptions.contactRange, 0.0f);
    Reference ref = emptyReference(options.width, options.height, int(scene.lights.size()), samples,
                                   blend == BlendShadows::Coloured, contactRange > 0.0f);

    const float aspect = float(options.width) / float(options.height);
    const glm::mat4 viewFromWorld = shadow::viewFromWorld(scene.camera);
    const glm::mat4 worldFromClip =
        glm::inverse(shadow::clipFromView(scene.camera, aspect) * viewFromWorld);
    const glm::vec3 eye = scene.camera.eye;
    const glm::vec3 forward = glm::normalize(scene.camera.centre - scene.camera.eye);
    const bool ortho = scene.camera.projection == Projection::Orthographic;
    const float pixelAtUnit = ortho
                                  ? (scene.camera.top - scene.camera.bottom) / float(options.height)
                                  : 2.0f * std::tan(0.5f * glm::radians(scene.camera.fovyDegrees)) /
                                        float(options.height);
    const float epsilon = 2e-5f * world.scale;
    const float tanAngle = std::tan(glm::radians(options.shadow.lightAngle));
    const float radius = options.shadow.lightRadius;

    std::vector<bool> on(scene.lights.size());
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        on[i] =
            options.shadow.enabled && scene.lights[i].castsShadows && lightIsOn(scene, options, i);
    }

    const LightTracer lightTracer{scene,        ref,      casters.get(), blend, samples,
                                  contactRange, tanAngle, radius,        on};
    auto tracePixel = [&](int x, int y) {
        const float nx = (float(x) + 0.5f) / float(options.width) * 2.0f - 1.0f;
        const float ny = 1.0f - (float(y) + 0.5f) / float(options.height) * 2.0f;
        const glm::vec4 a = worldFromClip * glm::vec4(nx, ny, -1.0f, 1.0f);
        const glm::vec4 b = worldFromClip * glm::vec4(nx, ny, 1.0f, 1.0f);
        const glm::vec3 from = glm::vec3(a) / a.w, to = glm::vec3(b) / b.w;
        const glm::vec3 dir = glm::normalize(to - from);
        float tnear = 0.0f;
        const float tfar = glm::length(to - from);
        AlphaContext context;
        rtcInitIntersectContext(&context.base);
        context.viewRay = true;
        // Single-sided surfaces seen from behind are culled by the main pass: look past them.
        for (int attempt = 0; attempt < 64; ++attempt) {
            RTCRayHit rh{};
            rh.ray.org_x = from.x;
            rh.ray.org_y = from.y;
            rh.ray.org_z = from.z;
            rh.ray.dir_x = dir.x;
            rh.ray.dir_y = dir.y;
            rh.ray.dir_z = dir.z;
            rh.ray.tnear = tnear;
            rh.ray.tfar = tfar;
            rh.ray.mask = 0xffffffffu;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(all.get(), &context.base, &rh);
            if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return;
            const int o = int(rh.hit.geomID);
            const Mesh& mesh = *world.meshes[std::size_t(o)];
            const std::vector<glm::vec3>& p = world.positions[std::size_t(o)];
            const std::uint32_t* t = &mesh.indices[3 * std::size_t(rh.hit.primID)];
            glm::vec3 n = glm::cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]);  // CCW = front
            const float nl = glm::length(n);
            if (!(nl > 0.0f)) {
                tnear = rh.ray.tfar * (1.0f + 1e-6f) + 1e-7f * world.scale;
                continue;
            }
            n /= nl;
            const Object& obj = scene.objects[std::size_t(o)];
            const Material& mat = scene.materials[obj.material];
            if (glm::dot(n, dir) > 0.0f) {
                if (!mat.doubleSided) {
                    tnear = rh.ray.tfar * (1.0f + 1e-6f) + 1e-7f * world.scale;
                    continue;
                }
                n = -n;  // the side the camera sees
            }
            const glm::vec3 point = from + dir * rh.ray.tfar;
            const std::size_t pixel = std::size_t(y) * std::size_t(options.width) + std::size_t(x);
            ref.object[pixel] = o;
            ref.pixelWorld[pixel] =
                pixelAtUnit * (ortho ? 1.0f : std::max(glm::dot(point - eye, forward), 0.0f));
            if (!obj.receivesShadows) return;
            const glm::vec3 origin = point + n * (epsilon + 1e-6f * glm::length(point));
            const float turn = pixelTurn(x, y);
            lightTracer.trace(pixel, mat, point, origin, n, turn);
            return;
        }
    };

    forEachRow(options.height, referenceOptions, [&](int y) {
        for (int x = 0; x < options.width; ++x)
            tracePixel(x, y);
    });
    check(device.get(), "trace rays");
    if (referenceOptions.cancel && referenceOptions.cancel->load()) {
        throw Error(ErrorKind::InvalidInput, "ray-traced reference cancelled");
    }
    return ref;
}

}  // namespace gnomon::truth
