// The scene's shadow casters as a BVH (bvh/Bvh.h) in two RGBA32F textures that the main pass
// reads with texelFetch (shaders/bvh_trace.glsl), for --shadow-rays: no storage buffers, so
// WebGL2 runs it too. Positions are the renderer's own (the scene as RelativeScene moved
// it). Built once per set of casters: a frame whose GPU scene kept its revision reads
// nothing, and a new revision that moved no caster (a receiver's animation, a material)
// only compares each caster's mesh and transform.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "gl/Objects.h"
#include "gnomon/Options.h"
#include "gnomon/Scene.h"
#include "render/DrawnTriangles.h"
#include "render/GpuScene.h"
#include "render/RayMasks.h"

namespace gnomon::render {

#include "bvh_layout.glsl"  // NOLINT(bugprone-suspicious-include): shared with GLSL

class RayScene {
public:
    // Makes the textures hold `scene`'s casters at `seconds`. `revision` and `geometry`: the
    // GPU scene's revision and geometry hash (GpuScene), which change with any caster.
    // Masked and blended casters as RayMasks.h says. Throws gnomon::Error
    // when the casters do not fit the driver's textures.
    void update(const Scene& scene, double seconds, std::uint64_t revision, std::uint64_t geometry,
                const ShadowOptions& options);
    // Updated from `gpuScene` and returned when `options` trace shadow rays; else null.
    // `built`: 1 when the hierarchy was built for it, else 0.
    const RayScene* forFrame(const Scene& scene, const RenderOptions& options,
                             const GpuScene& gpuScene, int& built);
    const gl::Texture& nodes() const { return mNodes; }
    const gl::Texture& triangles() const { return mTriangles; }
    // The start table (OpenGL 4.5, --shadow-rays all): for each triangle the main pass draws
    // (DrawnTriangles' numbers, four to an RGBA32F texel in rows of kBvhRowTexels), its
    // triangle in the hierarchy, -1 for none; one texel where there is no table.
    const gl::Texture& starts() const { return mStarts; }
    // Masked and blended casters' cut-outs (RayMasks.h).
    const RayMasks& masks() const { return mMasks; }
    // How many times the hierarchy was built (what tests check the caching by).
    std::uint64_t builds() const { return mBuilds; }
    std::size_t triangleCount() const { return mTriangleCount; }
    // The radius of every object's points, casters or not: the scale of the reference's
    // rounding margin (truth::ShadowRays::lead), which the shader's margin follows.
    float scale() const { return mScale; }

private:
    void build(const Scene& scene, double seconds);
    // mStarts for `drawn` when the hierarchy or the numbering changed.
    void updateStarts(const DrawnTriangles& drawn);
    // mScale for `scene` at `seconds`, when an object's mesh or transform changed or, with
    // `newGeometry`, a mesh's points may have.
    void updateScale(const Scene& scene, double seconds, bool newGeometry);

    bool mValid = false;
    std::uint64_t mRevision = 0;
    BlendShadows mBlend = BlendShadows::Opaque;
    // What the textures were built from: the geometry hash, and per caster its object and
    // mesh index, its cut-out's texture and threshold, its transform's 16 floats and, cut out,
    // its texture transform's 9.
    std::uint64_t mGeometry = 0;
    std::vector<float> mKey, mScratch;
    std::vector<RayCaster> mCasters;  // per scene object
    gl::Texture mNodes, mTriangles, mStarts;
    // What mStarts was made for: the objects' first numbers and the hierarchy's build.
    std::vector<std::uint32_t> mStartKey;
    std::uint64_t mStartsBuild = 0;
    // Per triangle in the hierarchy's order: its object, mesh and number in the mesh.
    std::vector<std::array<std::uint32_t, 3>> mOrder;
    RayMasks mMasks;
    std::uint64_t mBuilds = 0;
    std::size_t mTriangleCount = 0;
    std::vector<float> mScaleKey, mScaleScratch;  // every object's mesh and transform
    float mScale = 1.0f;
};

}  // namespace gnomon::render
