// The casters' outlines as each 2D shadow map's light sees them, for --shadow-rays uncertain.
// A map stores what covers its texels' centres, so a caster thinner than a texel (a fence's
// slat, a lip standing a fraction of a texel above a face) can be missing from it while the
// lookup looks sure. Drawn as lines (CasterEdges: the edges between a triangle that faces the
// light and one that does not, and open borders), a caster marks every texel its outline
// crosses with the line's point there: its depth and its offset from the texel's centre, the
// nearest line kept (an image's atomic maximum: no depth buffer, no colour target to clear). The
// main pass (shadow_lookup.glsl's edgeAbovePlane) sends a lookup the map finds lit to a ray where
// an outline within its four texels lies nearer the light than the receiver's own plane at that
// point. OpenGL 4.5 only: WebGL2's sixteen texture units are taken.
#pragma once

#include <cstdint>
#include <vector>

#include "gl/Objects.h"
#include "render/CasterEdges.h"
#include "render/GpuScene.h"
#include "shadow/FramePlan.h"

namespace gnomon::render {

class EdgeMaps {
public:
    // Whether this driver draws them (OpenGL 4.5).
    static bool supported();
    // Whether a frame with `options` draws them: uncertain rays traced, outlines on, supported.
    static bool wanted(const ShadowOptions& options);
    // The outlines of `scene`'s meshes, made again when its geometry changed (`gpu`'s hash),
    // and its objects' places at `seconds`, read again when they changed (`gpu`'s revision).
    void sync(const Scene& scene, const GpuScene& gpu, double seconds);
    // Makes the edge maps match the 2D maps' array (size x size texels, `layers` layers).
    void allocate(int size, int layers);
    void release();
    // Clears `light`'s square and draws its casters' outlines into it, through `clipFromWorld`,
    // with the depth state the map was drawn with. Leaves the outlines' vertex array bound.
    void draw(const GpuScene& scene, const shadow::FramePlan& plan,
              const shadow::ShadowedLight& light, const glm::mat4& clipFromWorld);
    // R32UI: the nearest line's 1 - depth as 24 bits (rounded up: never farther than the
    // line), above its point's offset from the texel's centre, 4 bits an axis in eighths of a
    // texel from -1 (edge.frag.glsl); 0: no line.
    const gl::Texture& maps() const { return mEdges; }
    bool allocated() const { return bool(mEdges); }
    std::size_t bytes() const;

private:
    CasterEdges mLines;
    gl::Program mProgram;
    gl::Texture mEdges;
    gl::Framebuffer mTarget;               // no attachments: the lines store to mEdges
    std::vector<gl::Framebuffer> mClears;  // per layer, mEdges' layer as a colour target
    struct ObjectLines {
        std::uint32_t mesh = 0;
        glm::mat4 worldFromModel{1.0f};
    };
    std::vector<ObjectLines> mObjects;  // per object
    std::uint64_t mRevision = ~0ull;
    std::vector<std::uint32_t> mDrawnFor;  // per object, the last draw() that drew it
    std::uint32_t mDraws = 0;
};

}  // namespace gnomon::render
