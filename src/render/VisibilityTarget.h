// What `gnomon score` reads of a frame: per light and pixel the shadow visibility, the world
// size of the map texel it came from and whether a shadow ray decided it (RGBA32F: x, y, w; a
// layer per scene light), per pixel the scene object whose shadows those are (R32F, 1 + its
// index, 0 none), and with coloured shadows the transmittance the lookup found (RGBA32F, the
// same layers). The main pass's visibility pass writes them as images; on OpenGL ES 3.0
// (WebGL2), which has no image stores, it draws each light's layer in a pass of its own through
// layerTarget(), the object in the visibility layers' third channel, no object texture.
#pragma once

#include <vector>

#include "gl/Objects.h"
#include "gnomon/Renderer.h"

namespace gnomon::render {

class VisibilityTarget {
public:
    // Sized for `lights` layers of width x height, every pixel unset (lit, no map, no object,
    // untinted);
    // the tint layers only `withTint`.
    // `depth`: the frame's depth, which the ES passes test against.
    void clear(int width, int height, int lights, bool withTint, const gl::Texture& depth);
    // ES: light `light`'s layer as fragment outputs 1 (visibility) and 2 (tint).
    const gl::Framebuffer& layerTarget(int light) const {
        return mLayerTargets[std::size_t(light)];
    }
    int layers() const { return mVisibility.layers(); }
    const gl::Texture& visibility() const { return mVisibility; }
    const gl::Texture* tint() const { return mWithTint ? &mTint : nullptr; }
    const gl::Texture& objects() const { return mObjects; }
    // The layers as ShadowVisibility's interleaved, top-down values; with `drawn` false
    // (nothing was drawn: the shadow-map debug view) every pixel reads lit.
    void read(int width, int height, int lights, bool drawn, ShadowVisibility& out) const;

private:
    void makeLayerTargets(const gl::Texture& depth);
    gl::Texture mVisibility, mTint, mObjects;
    std::vector<gl::Framebuffer> mLayerTargets;  // ES only
    GLuint mTargetsDepth = 0;                    // the depth they were made with
    bool mTargetsTint = false;                   // and whether with tint layers
    bool mWithTint = false;
};

}  // namespace gnomon::render
