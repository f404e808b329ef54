// The view's depth at a coarse grid, drawn before the shadow maps so fitted directional
// lights can cover what the view really sees (sample distribution shadow maps, Lauritzen,
// Salvi and Lefohn, I3D 2011). Depth only: opaque and alpha-masked items as the main pass
// draws them (same culling, masked texels cut); blended ones hide nothing and are skipped.
// The depth is read back and turned into world points on the CPU: at ≤ 256 samples a side
// that is a few hundred kilobytes, and the reduction then runs once per light and cascade
// without another pass. The samples are kept while the camera and the scene are unchanged.
#pragma once

#include <cstdint>
#include <vector>

#include "gl/Objects.h"
#include "render/GpuScene.h"
#include "shadow/ViewSamples.h"

namespace gnomon::render {

class ViewDepthPass {
public:
    // Samples along the grid's longer side.
    static constexpr int kGridLimit = 128;

    // The samples of `camera`'s view of `scene` for an output of width x height (drawn
    // again only when the scene's revision, the camera or the size changed).
    const shadow::ViewSamples& sample(const GpuScene& scene, const Camera& camera, int width,
                                      int height);
    // Drop the kept samples: the next sample() draws.
    void invalidate() { mValid = false; }

private:
    const gl::Program& program(bool alphaTested);
    void draw(const GpuScene& scene, const glm::mat4& clipFromWorld);

    gl::Program mPrograms[2];
    gl::Texture mDepth;
    gl::Framebuffer mTarget;
    std::vector<float> mRead;
    shadow::ViewSamples mSamples;
    // What mSamples were taken from.
    bool mValid = false;
    std::uint64_t mRevision = 0;
    glm::mat4 mClipFromWorld{0.0f};
    glm::ivec2 mGrid{0};
};

}  // namespace gnomon::render
