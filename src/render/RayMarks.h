// Shadow rays only where the maps were unsure, in a pass of their own (--shadow-rays
// uncertain). The main pass first draws every opaque surface with the maps' answers and alpha
// 0 where some lookup was unsure (main.frag.glsl's SHADOW_RAYS_MARK); mark() turns those
// pixels into a depth target holding their depth and 0 elsewhere; the opaque surfaces drawn
// again into target() (depth LEQUAL, no writes) are shaded only there, rays and all. On a CPU
// driver an `if` only masks lanes, so ray code in the first draw cost every pixel the set-up
// and first steps of a traversal whether it traced or not; a failed depth test skips whole
// blocks of pixels before their shader runs.
#pragma once

#include "gl/Objects.h"

namespace gnomon::render {

class RayMarks {
public:
    // Marks the pixels whose alpha in `colour` is 0 with their depth from `depth` (the frame's
    // target, both `colour`'s size), and leaves target() bound. Uses texture units 14 and 15
    // and its own vertex array: the caller binds its own again.
    void mark(const gl::Texture& colour, const gl::Texture& depth);
    // `colour` with the marks' depth, for the second draw.
    const gl::Framebuffer& target() const { return mTarget; }

private:
    void allocate(const gl::Texture& colour);

    gl::Program mProgram;
    gl::VertexArray mEmpty;
    gl::Texture mDepth;
    gl::Framebuffer mMarks, mTarget;  // the marks' depth alone; `colour` with it
    GLuint mColour = 0;               // the colour texture mTarget holds
    int mWidth = 0, mHeight = 0;
};

}  // namespace gnomon::render
