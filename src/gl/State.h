// Pipeline switches that differ between OpenGL 4.5 and ES 3.0 (WebGL2), and image stores,
// which only OpenGL 4.5 has here. Everything else the passes set (depth test, blending,
// viewport, scissor, polygon offset, masks) is the same call on both and stays in the passes.
#pragma once

#include "gl/Objects.h"

namespace gnomon::gl {

// Depth clamping (pancaked shadow casters); on ES only with EXT_depth_clamp (Caps::depthClamp),
// otherwise a no-op the caller has planned for.
void setDepthClamp(bool on);
// Linear-to-sRGB encoding of writes to sRGB targets. ES always encodes, so this switch
// exists only on OpenGL 4.5 (Caps::srgbWriteControl).
void setSrgbWrites(bool on);
// `texture` (level 0, every layer) as image unit `unit`, texels of `format`; `access`
// GL_READ_WRITE for image atomics.
void bindImage(int unit, const Texture& texture, GLenum format, GLenum access = GL_WRITE_ONLY);
void unbindImage(int unit, GLenum format);
// Image stores made so far are seen by texture reads and readbacks that follow.
void imageStoresDone();
// ... and also by the image loads, atomics and texture clears of later passes.
void imageStoresRead();

// Turns the scissor test off for its lifetime, and on again after if it was on: a clear or a
// pass over a whole texture inside a screen tile's scissor.
class ScissorPause {
public:
    ScissorPause();
    ~ScissorPause();
    ScissorPause(const ScissorPause&) = delete;
    ScissorPause& operator=(const ScissorPause&) = delete;
    bool wasOn() const { return mOn; }
    // The scissor's box as it was (x, y, width, height); meaningful where wasOn().
    const GLint* box() const { return mBox; }

private:
    bool mOn = false;
    GLint mBox[4] = {0, 0, 0, 0};
};

// Waits until the GPU has done every command given so far (pass timing). glFinish natively; a
// browser's WebGL finish() does not wait, so in the page a one-texel read of a target of its
// own, which the browser answers only once the commands before it are done.
class Finisher {
public:
    Finisher();
    void wait();

private:
    Texture mTexel;
    Framebuffer mTarget;
};

}  // namespace gnomon::gl
