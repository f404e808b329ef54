// The reference's tracer on Embree 3: two BVHs, every object (view rays) and the casters
// (shadow rays); masked and blended surfaces answer through a filter that applies
// truth/AlphaRays.h's rule on every hit.
#include <algorithm>
#include <string>

#include <embree3/rtcore.h>

#include "gnomon/Error.h"
#include "truth/Tracer.h"

namespace gnomon::truth {

TracerKind defaultTracer() {
    return TracerKind::Embree;
}

namespace {

// Rays carry this context so the filter knows what they trace.
struct AlphaContext {
    RTCIntersectContext base;  // first: Embree hands filters a pointer to it
    AlphaState state;
};

void alphaFilter(const RTCFilterFunctionNArguments* args) {
    const auto& surface = *static_cast<const AlphaSurface*>(args->geometryUserPtr);
    auto& ctx = *reinterpret_cast<AlphaContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned object = RTCHitN_geomID(args->hit, args->N, i);
        const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        const float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
        if (!alphaStops(surface, object, prim, u, v, ctx.state)) args->valid[i] = 0;
    }
}

// An Embree ray from `origin` along `dir` over [tnear, tfar], every geometry mask.
RTCRay rayAlong(const glm::vec3& origin, const glm::vec3& dir, float tnear, float tfar) {
    RTCRay ray{};
    ray.org_x = origin.x;
    ray.org_y = origin.y;
    ray.org_z = origin.z;
    ray.dir_x = dir.x;
    ray.dir_y = dir.y;
    ray.dir_z = dir.z;
    ray.tnear = tnear;
    ray.tfar = tfar;
    ray.mask = 0xffffffffu;
    return ray;
}

void checkDevice(RTCDevice device, const char* what) {
    const RTCError e = rtcGetDeviceError(device);
    if (e != RTC_ERROR_NONE) {
        throw Error(ErrorKind::InvalidInput, std::string("ground truth: Embree failed to ") + what +
                                                 " (error " + std::to_string(int(e)) + ")");
    }
}

RTCScene buildScene(RTCDevice device, const TracerInput& in, bool castersOnly) {
    const Scene& scene = *in.scene;
    RTCScene s = rtcNewScene(device);
    // Robust traversal: a ray through the edge two triangles share meets one of them, never
    // slips between them to a surface behind (a pixel's ray of the reference did, on a lamp).
    rtcSetSceneFlags(s, RTC_SCENE_FLAG_ROBUST);
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const Object& obj = scene.objects[o];
        if (castersOnly && !obj.castsShadows) continue;
        const Mesh& mesh = scene.meshes[obj.mesh];
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
            checkDevice(device, "allocate geometry");
            throw Error(ErrorKind::InvalidInput, "ground truth: out of memory for geometry");
        }
        const std::vector<glm::vec3>& p = (*in.positions)[o];
        for (std::size_t i = 0; i < p.size(); ++i) {
            v[3 * i] = p[i].x;
            v[3 * i + 1] = p[i].y;
            v[3 * i + 2] = p[i].z;
        }
        std::copy(mesh.indices.begin(), mesh.indices.begin() + std::ptrdiff_t(3 * triangles), idx);
        const AlphaSurface& alpha = (*in.alpha)[o];
        if (alpha.material) {  // masked or blended: every hit asks its alpha
            rtcSetGeometryUserData(g, const_cast<AlphaSurface*>(&alpha));
            rtcSetGeometryIntersectFilterFunction(g, &alphaFilter);
            rtcSetGeometryOccludedFilterFunction(g, &alphaFilter);
        }
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(s, g, unsigned(o));
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(s);
    checkDevice(device, "build the scene's BVH");
    return s;
}

class EmbreeTracer final : public Tracer {
public:
    explicit EmbreeTracer(const TracerInput& in) : mBlend(in.blend) {
        mDevice = rtcNewDevice(nullptr);
        if (!mDevice) throw Error(ErrorKind::InvalidInput, "ground truth: Embree found no device");
        try {
            mAll = buildScene(mDevice, in, false);
            mCasters = buildScene(mDevice, in, true);
        } catch (...) {
            if (mAll) rtcReleaseScene(mAll);
            rtcReleaseDevice(mDevice);
            throw;
        }
    }
    ~EmbreeTracer() override {
        rtcReleaseScene(mCasters);
        rtcReleaseScene(mAll);
        rtcReleaseDevice(mDevice);
    }
    EmbreeTracer(const EmbreeTracer&) = delete;
    EmbreeTracer& operator=(const EmbreeTracer&) = delete;

    TraceHit nearest(const glm::vec3& origin, const glm::vec3& dir, float tnear,
                     float tfar) const override {
        AlphaContext context;
        rtcInitIntersectContext(&context.base);
        context.state.viewRay = true;
        RTCRayHit rh{};
        rh.ray = rayAlong(origin, dir, tnear, tfar);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(mAll, &context.base, &rh);
        TraceHit hit;
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
        hit.object = int(rh.hit.geomID);
        hit.triangle = rh.hit.primID;
        hit.u = rh.hit.u;
        hit.v = rh.hit.v;
        hit.t = rh.ray.tfar;
        hit.geometricNormal = glm::vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
        return hit;
    }

    float transmitted(const glm::vec3& origin, const glm::vec3& dir, float tnear, float tfar,
                      glm::vec3* tint) const override {
        AlphaContext context;
        rtcInitIntersectContext(&context.base);
        context.state.blend = mBlend;
        RTCRay ray = rayAlong(origin, dir, tnear, tfar);
        rtcOccluded1(mCasters, &context.base, &ray);
        if (tint) *tint = context.state.tint;
        // Embree sets tfar to -inf on a hit.
        return ray.tfar < 0.0f ? 0.0f : context.state.transmission;
    }

    void check(const char* what) const override { checkDevice(mDevice, what); }

private:
    RTCDevice mDevice = nullptr;
    RTCScene mAll = nullptr, mCasters = nullptr;
    BlendShadows mBlend;
};

}  // namespace

std::unique_ptr<Tracer> makeEmbreeTracer(const TracerInput& input) {
    return std::make_unique<EmbreeTracer>(input);
}

}  // namespace gnomon::truth
