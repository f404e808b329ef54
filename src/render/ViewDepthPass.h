// The view's depth, drawn before the shadow maps so fitted directional lights can cover what
// the view really sees (sample distribution shadow maps, Lauritzen, Salvi and Lefohn, I3D
// 2011). Depth only, at the output's size: opaque and alpha-masked items as the main pass
// draws them (same culling, masked texels cut); blended ones hide nothing and are skipped.
// Its vertices are placed by the main pass's own expressions (shaders/view_clip.glsl), so
// the main pass can start from this depth and shade each pixel once.
// A second pass reduces it to a grid of at most kGridLimit cells a side, each the nearest
// and farthest depth of its block of pixels (nothing between two samples is lost: a grazing
// floor's farthest pixel before the horizon is its block's farthest depth). The grid is
// read back and turned into world points on the CPU, where each light and cascade takes the
// box of the points it needs. Kept while the camera, the size and the scene are unchanged.
#pragma once

#include <cstdint>
#include <vector>

#include "gl/Objects.h"
#include "render/GpuScene.h"
#include "shadow/LightTiles.h"
#include "shadow/ViewSamples.h"

namespace gnomon::render {

class ViewDepthPass {
public:
    // Cells along the grid's longer side.
    static constexpr int kGridLimit = 128;

    // The samples of `camera`'s view of `scene` for an output of width x height (drawn
    // again only when the scene's revision, the camera or the size changed).
    const shadow::ViewSamples& sample(const GpuScene& scene, const Camera& camera, int width,
                                      int height);
    // Drop the kept samples: the next sample() draws.
    void invalidate() { mValid = false; }
    // Is the depth drawn for `camera`'s view of `scene` at width x height, as it is now?
    bool holds(const GpuScene& scene, const Camera& camera, int width, int height) const;
    // The view's depth at the output's size, as the last sample() drew it (contact shadows),
    // and the framebuffer it is attached to (the main pass copies it to start from).
    const gl::Texture& depth() const { return mDepth; }
    const gl::Framebuffer& target() const { return mTarget; }
    // The reduced depth the last sample() read back: per cell, nearest and farthest.
    shadow::DepthCells cells() const { return {&mRead, mGrid}; }
    // Triangles the last sample() drew: 0 when it kept the samples it had.
    std::uint64_t trianglesDrawn() const { return mTrianglesDrawn; }

private:
    const gl::Program& program(bool alphaTested);
    void allocate(const shadow::SampleGrid& grid);
    void draw(const GpuScene& scene);
    void reduce();

    gl::Program mPrograms[2], mReduce;
    gl::Texture mDepth;  // the view's depth at the output's size
    gl::Framebuffer mTarget;
    gl::Texture mRanges;  // RG32F: (nearest, farthest) per cell
    gl::Framebuffer mRangeTarget;
    gl::VertexArray mEmpty;  // the reduction's full-screen triangle has no attributes
    std::vector<glm::vec2> mRead;
    std::vector<std::uint32_t> mItems;  // the items drawn: reused every frame
    std::uint64_t mTrianglesDrawn = 0;
    shadow::ViewSamples mSamples;
    // What mSamples were taken from.
    bool mValid = false;
    std::uint64_t mRevision = 0;
    glm::mat4 mViewFromWorld{0.0f}, mClipFromView{0.0f};
    shadow::SampleGrid mGrid{{0, 0}, 0, {0, 0}};
};

}  // namespace gnomon::render
