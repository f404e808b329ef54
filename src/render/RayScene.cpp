#include "render/RayScene.h"

#include <algorithm>
#include <string>

#include "bvh/Bvh.h"
#include "core/Aabb.h"
#include "gl/Caps.h"
#include "gnomon/Error.h"

namespace gnomon::render {

void RayScene::update(const Scene& scene, double seconds, std::uint64_t revision,
                      std::uint64_t geometry, const ShadowOptions& options) {
    if (mValid && revision == mRevision && options.blendShadows == mBlend) return;
    mRevision = revision;
    mBlend = options.blendShadows;
    // The casters as rays meet them (RayMasks.h), and what they are now: object, mesh, the
    // texture and alpha that cut them out, the transform and the texture's.
    mScratch.clear();
    mCasters.assign(scene.objects.size(), RayCaster{});
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const Object& obj = scene.objects[o];
        const RayCaster c = rayCaster(scene, obj, options);
        mCasters[o] = c;
        if (!c.casts) continue;
        const glm::mat4 m = obj.worldFromModelAt(seconds);
        mScratch.insert(mScratch.end(), {float(o), float(obj.mesh), float(c.texture), c.threshold});
        mScratch.insert(mScratch.end(), &m[0][0], &m[0][0] + 16);
        if (c.filtered) {
            const glm::mat3& uv = scene.materials[obj.material].uvTransform;
            mScratch.insert(mScratch.end(), &uv[0][0], &uv[0][0] + 9);
        }
    }
    updateScale(scene, seconds, !mValid || geometry != mGeometry);
    if (mValid && geometry == mGeometry && mScratch == mKey) return;
    mValid = true;
    mGeometry = geometry;
    std::swap(mKey, mScratch);
    build(scene, seconds);
}

void RayScene::updateScale(const Scene& scene, double seconds, bool newGeometry) {
    mScaleScratch.clear();
    for (const Object& obj : scene.objects) {
        const glm::mat4 m = obj.worldFromModelAt(seconds);
        mScaleScratch.push_back(float(obj.mesh));
        mScaleScratch.insert(mScaleScratch.end(), &m[0][0], &m[0][0] + 16);
    }
    if (!newGeometry && !mScaleKey.empty() && mScaleScratch == mScaleKey) return;
    std::swap(mScaleKey, mScaleScratch);
    Aabb bounds;
    for (const Object& obj : scene.objects) {
        const glm::mat4 m = obj.worldFromModelAt(seconds);
        for (const glm::vec3& p : scene.meshes[obj.mesh].positions)
            bounds.extend(glm::vec3(m * glm::vec4(p, 1.0f)));
    }
    mScale = bounds.empty() ? 1.0f : std::max(bounds.radius(), 1e-6f);
}

const RayScene* RayScene::forFrame(const Scene& scene, const RenderOptions& options,
                                   const GpuScene& gpuScene, int& built) {
    built = 0;
    if (!tracesShadowRays(options.shadow)) return nullptr;
    const std::uint64_t before = mBuilds;
    update(scene, options.time, gpuScene.revision(), gpuScene.geometryHash(), options.shadow);
    built = int(mBuilds - before);
    // With rays on OpenGL 4.5 the main pass names the triangle it drew (main.frag.glsl's
    // RAYS_FROM_DRAWN).
    if (gl::activeCaps().drawIndirect && options.shadow.shadowRays != ShadowRayMode::Off)
        updateStarts(gpuScene.drawnTriangles());
    return this;
}

void RayScene::updateStarts(const DrawnTriangles& drawn) {
    const std::size_t objects = mCasters.size();
    // Made again only when the hierarchy was rebuilt or the drawn numbering changed.
    bool same = mStarts && mStartsBuild == mBuilds && mStartKey.size() == objects;
    for (std::size_t o = 0; same && o < objects; ++o)
        same = mStartKey[o] == drawn.objectFirst(o);
    if (same) return;
    mStartsBuild = mBuilds;
    mStartKey.resize(objects);
    for (std::size_t o = 0; o < objects; ++o)
        mStartKey[o] = drawn.objectFirst(o);
    // Four numbers a texel, two texels at least; a table the driver's textures cannot hold
    // is none, one texel (the shader then finds each start by a ray, as WebGL2 does).
    std::size_t texels = std::max<std::size_t>((drawn.total() + 3) / 4, 2);
    if (mOrder.empty() || drawn.objects() != objects ||
        texels > std::size_t(kBvhRowTexels) * std::size_t(gl::activeCaps().maxTextureSize)) {
        texels = 1;
    }
    std::vector<float> table(4 * texels, -1.0f);
    for (std::size_t i = 0; texels > 1 && i < mOrder.size(); ++i) {
        const auto [o, mesh, t] = mOrder[i];
        const std::vector<std::uint32_t>& places = drawn.places(mesh);
        if (t < places.size() && places[t] != kNoPlace)
            table[drawn.objectFirst(o) + places[t]] = float(i);
    }
    mStarts = gl::Texture::texelRows("shadow-ray starts", table.data(), texels,
                                     texels < 2 ? 1 : kBvhRowTexels);
}

void RayScene::build(const Scene& scene, double seconds) {
    std::vector<bvh::BvhTriangle> triangles;
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const RayCaster& c = mCasters[o];
        if (!c.casts) continue;
        const Object& obj = scene.objects[o];
        const Mesh& mesh = scene.meshes[obj.mesh];
        const glm::mat4 m = obj.worldFromModelAt(seconds);
        std::vector<glm::vec3> p(mesh.positions.size());
        for (std::size_t i = 0; i < p.size(); ++i)
            p[i] = glm::vec3(m * glm::vec4(mesh.positions[i], 1.0f));
        const std::vector<std::uint32_t>& idx = mesh.indices;
        const std::uint32_t flags =
            bvh::BvhTriangle::kCaster | (c.filtered ? bvh::BvhTriangle::kFiltered : 0u);
        for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
            triangles.push_back(
                {p[idx[t]], float(o), p[idx[t + 1]], float(t / 3), p[idx[t + 2]], float(flags)});
        }
    }
    // Rows of kBvhRowTexels texels (bvh_layout.glsl): three a triangle, two a node (under
    // twice as many nodes as triangles).
    const int maxSize = gl::activeCaps().maxTextureSize;
    const int row = kBvhRowTexels;
    const std::size_t limit = std::size_t(row) * std::size_t(maxSize) / 4;
    if (triangles.size() > std::min(limit, bvh::kBvhMaxTriangles)) {
        throw Error(ErrorKind::InvalidInput,
                    "shadow-rays: the scene's casters have " + std::to_string(triangles.size()) +
                        " triangles; this OpenGL driver's textures hold at most " +
                        std::to_string(std::min(limit, bvh::kBvhMaxTriangles)));
    }
    const bvh::Bvh hierarchy(std::move(triangles));
    const std::vector<bvh::BvhNode>& nodes = hierarchy.nodes();
    const std::vector<bvh::BvhTriangle>& tris = hierarchy.triangles();
    mTriangleCount = tris.size();
    mOrder.clear();
    for (const bvh::BvhTriangle& t : tris) {
        const std::uint32_t o = std::uint32_t(t.object);
        mOrder.push_back({o, std::uint32_t(scene.objects[o].mesh), std::uint32_t(t.primitive)});
    }
    if (nodes.empty()) {  // one texel: bvh_trace.glsl reads a row under 2 wide as no hierarchy
        const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        mNodes = gl::Texture::texelRows("shadow-ray nodes", none, 1, 1);
        mTriangles = gl::Texture::texelRows("shadow-ray triangles", none, 1, 1);
    } else {
        mNodes = gl::Texture::texelRows("shadow-ray nodes", &nodes[0].lo.x, nodes.size() * 2, row);
        mTriangles =
            gl::Texture::texelRows("shadow-ray triangles", &tris[0].p0.x, tris.size() * 3, row);
    }
    mMasks.build(scene, mCasters, tris, row);
    ++mBuilds;
}

}  // namespace gnomon::render
