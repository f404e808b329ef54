// The reference's tracer on the project's own BVH (bvh/Bvh.h): no Embree, so it goes
// where Embree cannot. One hierarchy holds every object, each triangle flagged as a caster
// or not: view rays see them all, shadow rays only casters, and a node with no caster under
// it is skipped whole. (Embree's backend keeps two BVHs instead; one here halves the memory
// and the build, and is one pair of arrays for a shader to read.) Masked and blended
// triangles are flagged as filtered: each of their hits goes through truth/AlphaRays.h's
// alphaStops, as Embree's filter functions send them.
#include <string>

#include "bvh/Bvh.h"
#include "gnomon/Error.h"
#include "truth/Tracer.h"

namespace gnomon::truth {

using bvh::Bvh;
using bvh::BvhHit;
using bvh::BvhTriangle;
using bvh::kBvhMaxTriangles;

namespace {

// What the filter needs: the surfaces (per object) and the ray's running state.
struct AlphaFilterContext {
    const std::vector<AlphaSurface>* alpha;
    AlphaState state;
};

bool alphaFilter(void* context, const BvhTriangle& triangle, const BvhHit& hit) {
    auto& ctx = *static_cast<AlphaFilterContext*>(context);
    const std::uint32_t object = triangle.objectIndex();
    return alphaStops((*ctx.alpha)[object], object, triangle.primitiveIndex(), hit.u, hit.v,
                      ctx.state);
}

std::vector<BvhTriangle> trianglesOf(const TracerInput& in) {
    const Scene& scene = *in.scene;
    std::size_t total = 0;
    for (const Object& obj : scene.objects)
        total += scene.meshes[obj.mesh].indices.size() / 3;
    if (total > kBvhMaxTriangles) {
        throw Error(ErrorKind::InvalidInput, "ground truth: the BVH tracer holds at most " +
                                                 std::to_string(kBvhMaxTriangles) +
                                                 " triangles, the scene has " +
                                                 std::to_string(total));
    }
    std::vector<BvhTriangle> out;
    out.reserve(total);
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const Object& obj = scene.objects[o];
        const Mesh& mesh = scene.meshes[obj.mesh];
        const std::vector<glm::vec3>& p = (*in.positions)[o];
        if (p.empty()) continue;
        const std::uint32_t flags = (obj.castsShadows ? BvhTriangle::kCaster : 0u) |
                                    ((*in.alpha)[o].material ? BvhTriangle::kFiltered : 0u);
        const std::size_t triangles = mesh.indices.size() / 3;
        for (std::size_t j = 0; j < triangles; ++j) {
            const std::uint32_t* t = &mesh.indices[3 * j];
            out.push_back({p[t[0]], float(o), p[t[1]], float(j), p[t[2]], float(flags)});
        }
    }
    return out;
}

class BvhTracer final : public Tracer {
public:
    explicit BvhTracer(const TracerInput& in)
        : mBvh(trianglesOf(in)), mAlpha(in.alpha), mBlend(in.blend) {}

    TraceHit nearest(const glm::vec3& origin, const glm::vec3& dir, float tnear,
                     float tfar) const override {
        AlphaFilterContext context{mAlpha, {}};
        context.state.viewRay = true;
        const BvhHit h = mBvh.nearest({origin, dir, tnear, tfar}, &alphaFilter, &context);
        TraceHit hit;
        if (!h.hit()) return hit;
        const BvhTriangle& tri = mBvh.triangles()[h.triangle];
        hit.object = int(tri.objectIndex());
        hit.triangle = tri.primitiveIndex();
        hit.u = h.u;
        hit.v = h.v;
        hit.t = h.t;
        hit.geometricNormal = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);  // as Embree's Ng
        return hit;
    }

    float transmitted(const glm::vec3& origin, const glm::vec3& dir, float tnear, float tfar,
                      glm::vec3* tint) const override {
        AlphaFilterContext context{mAlpha, {}};
        context.state.blend = mBlend;
        const bool blocked = mBvh.occluded({origin, dir, tnear, tfar}, &alphaFilter, &context);
        if (tint) *tint = context.state.tint;
        return blocked ? 0.0f : context.state.transmission;
    }

    // Nothing fails once built.
    void check(const char*) const override {}

private:
    Bvh mBvh;
    const std::vector<AlphaSurface>* mAlpha;
    BlendShadows mBlend;
};

}  // namespace

const char* toString(TracerKind kind) {
    return kind == TracerKind::Bvh ? "bvh" : "embree";
}

std::unique_ptr<Tracer> makeBvhTracer(const TracerInput& input) {
    return std::make_unique<BvhTracer>(input);
}

}  // namespace gnomon::truth
