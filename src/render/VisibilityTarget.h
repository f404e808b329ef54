// What `gnomon score` reads of a frame: per light and pixel the shadow visibility and the
// world size of the map texel it came from (RG32F, a layer per scene light), per pixel the
// scene object whose shadows those are (R32F, 1 + its index, 0 none), and with
// coloured shadows the transmittance the lookup found (RGBA32F, the same layers). The main
// pass's visibility pass writes them as images.
#pragma once

#include "gl/Objects.h"
#include "gnomon/Renderer.h"

namespace gnomon::render {

class VisibilityTarget {
public:
    // Sized for `lights` layers of width x height, every pixel unset (lit, no map, no object,
    // untinted);
    // the tint layers only `withTint`.
    void clear(int width, int height, int lights, bool withTint);
    const gl::Texture& visibility() const { return mVisibility; }
    const gl::Texture* tint() const { return mWithTint ? &mTint : nullptr; }
    const gl::Texture& objects() const { return mObjects; }
    // The layers as ShadowVisibility's interleaved, top-down values; with `drawn` false
    // (nothing was drawn: the shadow-map debug view) every pixel reads lit.
    void read(int width, int height, int lights, bool drawn, ShadowVisibility& out) const;

private:
    gl::Texture mVisibility, mTint, mObjects;
    bool mWithTint = false;
};

}  // namespace gnomon::render
