// Shadow rays only where the maps were unsure, in passes of their own (--shadow-rays
// uncertain). The main pass first draws every opaque surface with the maps' answers: alpha 0
// where some lookup was unsure and, into bindFirstDraw()'s target, beside the colour that
// pixel's ray job (its point, normal and the lights to trace: shadow_rays.glsl's
// WRITE_RAY_JOB). Then trace() turns the marked pixels into a depth target holding their
// depth and 0 elsewhere, numbers them (OpenGL 4.5: a pass over the marked pixels alone appends
// them to a list; ES 3.0: a histogram pyramid; shaders/ray_pyramid.glsl) and traces their jobs
// in a pass of one fragment per marked pixel (ray_trace.frag.glsl); the opaque surfaces drawn
// again into target() (depth LEQUAL, no writes) are shaded only there, with those rays'
// answers (SHADOW_RAYS_RESOLVE). A frame with few marked pixels skips the jobs and the pass,
// and its second draw traces them itself (compacts()). On a CPU driver an `if` only masks
// lanes: ray code in the first draw cost every pixel the set-up and first steps of a traversal
// whether it traced or not, and rays traced in the second draw ran one marked pixel to a
// vector whose other lanes waited; a failed depth test skips whole blocks of pixels before
// their shader runs.
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "gl/Objects.h"
#include "gnomon/Scene.h"

namespace gnomon::render {

// The camera as the reference casts each pixel's ray (truth::Reference; shadow_rays.glsl's
// pixelRay, uniforms 18 to 23): its eye, the view's axes (rows of viewFromWorld), its lens
// (perspective: tan(fovy / 2) and aspect; orthographic: right - left, right + left, top -
// bottom, top + bottom) and the frame (width, height, a pixel's size at depth 1, orthographic).
struct PixelRayCamera {
    glm::vec3 eye{0.0f}, right{1.0f, 0.0f, 0.0f}, up{0.0f, 1.0f, 0.0f}, ahead{0.0f, 0.0f, -1.0f};
    glm::vec4 lens{1.0f, 1.0f, 0.0f, 0.0f};
    glm::vec4 frame{1.0f, 1.0f, 0.0f, 0.0f};
};
PixelRayCamera pixelRayCamera(const Camera& camera, int width, int height);
void setPixelRayUniforms(const PixelRayCamera& c);

// What the rays' pass shares with the main pass: its eye, rays' margin and pixel rays
// (shadow_rays.glsl) and the size of its light records' blocks (lights.glsl).
struct RayTraceInputs {
    glm::vec3 eye{0.0f};
    float rayScale = 0.0f;
    int maxLights = 0, orderSlots = 0;
    PixelRayCamera pixelRays;
    bool cutouts = false;  // some caster's texture decides (RayMasks::any)
};

class RayMarks {
public:
    // Makes the textures for a frame drawn into `colour` and `depth` (the same size), if they
    // are not made yet. Before any other binding the frame needs: on OpenGL ES a texture is
    // made and edited through the active unit's binding.
    void prepare(const gl::Texture& colour, const gl::Texture& depth);
    // Whether this frame's rays run in their own pass (trace(), from the jobs the first draw
    // writes beside its colour) or in the second draw, where the pixels lie. The pass pays a
    // fixed cost (the jobs' stores beside every pixel, the numbering's passes) that only many
    // marked pixels win back, as one marked pixel to a vector of lanes costs the second draw
    // nearly a vector's time: on OpenGL 4.5 the count of an earlier frame's second draw
    // decides (none yet: the pass); OpenGL ES 3.0, which counts no samples, always takes the
    // pass. After prepare().
    bool compacts();
    // Binds the first draw's target when compacts(): `colour` and `depth` with the ray jobs
    // beside them (draw buffer 1).
    void bindFirstDraw();
    // After the first draw: marks the pixels whose alpha in `colour` is 0 with their depth from
    // `depth`, and leaves target() bound. With `compact`, also numbers them, traces their jobs
    // and binds the answers on texture unit 14: on OpenGL 4.5 at their pixels (returns 0); on
    // ES 3.0 under the numbering, and returns its size (P, log2 P) for the second draw's
    // programs (ray_pyramid.glsl). Without `compact`, returns 0;
    // unit 15 is left to the caller to bind again (the scene's object records). The light records,
    // casters and their masks stay bound as the main pass left them; the viewport is put back on
    // `colour`, the scissor as it was (a screen tile's: only its pixels are marked).
    glm::ivec2 trace(const gl::Texture& colour, const gl::Texture& depth, const RayTraceInputs& in,
                     bool compact);
    // Around the second draw: counts the samples it shades, its marked pixels (OpenGL 4.5).
    void beginCount();
    void endCount();
    // `colour` with the marks' depth, for the second draw.
    const gl::Framebuffer& target() const { return mTarget; }

private:
    void allocate(const gl::Texture& colour, const gl::Texture& depth);
    void allocateLevels(long long bytes);
    void allocateDraws(const gl::Texture& colour, const gl::Texture& depth);
    void buildPrograms(const RayTraceInputs& in);
    void mark(const gl::Texture& colour, const gl::Texture& depth);
    void number(const gl::Texture& colour, glm::ivec4 marked);
    void list();
    void traceJobs(const RayTraceInputs& in, glm::ivec2 numbering);

    gl::Program mMarkProgram, mLevelOne, mLevelAbove, mListProgram, mTraceProgram;
    int mTraceLights = 0;        // the MAX_LIGHTS mTraceProgram was built for
    bool mTraceCutouts = false;  // whether it was built with BVH_CUTOUTS
    gl::VertexArray mEmpty;
    gl::Texture mDepth;    // the marks' depth
    gl::Texture mJobs;     // a texel of RGBA32UI per pixel (shadow_rays.glsl WRITE_RAY_JOB)
    gl::Texture mPyramid;  // ES 3.0: every level side by side (ray_pyramid.glsl), answers under
    gl::Texture
        mPyramidRead;      // the levels again, for the rays' pass to read (OpenGL 4.5: the list)
    gl::Texture mAnswers;  // OpenGL 4.5: the rays' answers at their pixels
    bool mList = false;    // OpenGL 4.5: list() numbers the marked pixels
    std::array<gl::Texture, 2> mCopies;  // the last level drawn, for the next one to read
    int mResultRows = 1;                 // rows of jobs (rayAnswerTexel)
    int mAnswerRow = 4;                  // the first of them: 4 (the list) or P / 2 (pyramid)
    gl::Framebuffer mFirst, mMarks, mTarget, mTrace;
    std::array<gl::Framebuffer, 2> mLevels;  // the pyramid with either copy
    GLuint mColour = 0, mFrameDepth = 0;     // the textures mFirst and mTarget hold
    int mWidth = 0, mHeight = 0;
    int mSide = 2, mLevelCount = 1;  // P and log2 P
    gl::Query mCount;                // the second draw's samples (OpenGL 4.5)
    bool mCounting = false;          // mCount ended and not yet read
    int mLastCount = -1;             // the marked pixels mCount read last (-1: none yet)
};

}  // namespace gnomon::render
