#include "render/RayMarks.h"

#include <algorithm>
#include <string>
#include <vector>

#include "gl/Caps.h"
#include "gl/Program.h"
#include "gl/State.h"
#include "gnomon/Error.h"
#include "scene/CameraMath.h"

namespace gnomon::render {

namespace {

// Integer texels are read with texelFetch only; an integer texture filtered LINEAR (the
// default) would be incomplete, and read as 0.
void nearest(gl::Texture& t) {
    t.setParameter(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    t.setParameter(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

gl::Texture integers(const std::string& label, int width, int height) {
    gl::Texture t = gl::Texture::plain2D(label, GL_R32UI, std::max(width, 1), std::max(height, 1));
    nearest(t);
    return t;
}

// Unit `unit` reads `t` with no sampler object (texelFetch).
void bindRaw(int unit, const gl::Texture& t) {
    gl::bindTexture(unit, t);
    glBindSampler(GLuint(unit), 0);
}

// A texture the driver would not make: one line naming it, what it needs and what to do.
void require(const gl::Texture& t, const char* what, long long bytes) {
    if (t.allocated()) return;
    throw Error(ErrorKind::Gl, std::string("--shadow-rays uncertain: ") + what + " need " +
                                   std::to_string(bytes >> 20) +
                                   " MiB, which the OpenGL driver refused; render a smaller "
                                   "image, or trace every lookup (--shadow-rays all)");
}

}  // namespace

PixelRayCamera pixelRayCamera(const Camera& camera, int width, int height) {
    const PixelRayTerms t = pixelRayTerms(camera, width, height);
    PixelRayCamera c;
    c.eye = camera.eye;
    c.right = t.right;
    c.up = t.up;
    c.ahead = t.ahead;
    c.lens = t.ortho ? glm::vec4(camera.right - camera.left, camera.right + camera.left,
                                 camera.top - camera.bottom, camera.top + camera.bottom)
                     : glm::vec4(t.tanHalf, t.viewAspect, 0.0f, 0.0f);
    c.frame = glm::vec4(float(width), float(height), t.pixelAtUnit, t.ortho ? 1.0f : 0.0f);
    return c;
}

void setPixelRayUniforms(const PixelRayCamera& c) {
    gl::uniform(18, c.eye);
    gl::uniform(19, c.right);
    gl::uniform(20, c.up);
    gl::uniform(21, c.ahead);
    gl::uniform(22, c.lens);
    gl::uniform(23, c.frame);
}

void RayMarks::allocate(const gl::Texture& colour, const gl::Texture& depth) {
    mWidth = colour.width();
    mHeight = colour.height();
    mColour = mFrameDepth = 0;  // set once all is made: a refusal leaves nothing half made
    mLastCount = -1;            // a count of another size's pixels says nothing here
    mCounting = false;
    mSide = 4;  // answers lie in blocks of 4x4 (ray_answers.glsl)
    mLevelCount = 2;
    while (mSide < std::max(mWidth, mHeight)) {
        mSide *= 2;
        ++mLevelCount;
    }
    mList = gl::activeCaps().api == gl::Api::Gl45;
    mDepth = gl::Texture::plain2D("shadow-ray marks", GL_DEPTH_COMPONENT32F, mWidth, mHeight);
    mJobs = gl::Texture::plain2D("shadow-ray jobs", GL_RGBA32UI, mWidth, mHeight);
    require(mJobs, "the ray jobs of the output's pixels", 16LL * mWidth * mHeight);
    nearest(mJobs);
    // The jobs' rows (rayAnswerTexel) from row mAnswerRow, a multiple of 4 (a job's block of
    // 4x4 is one llvmpipe shades at once): under the list's count (OpenGL 4.5), or under the
    // pyramid (rows 0 to P / 2), where the rays' pass writes their answers.
    const long long pixels = static_cast<long long>(mWidth) * mHeight;
    mResultRows = 4 * int((pixels + 4 * mSide - 1) / (4 * mSide));
    mAnswerRow = mList ? 4 : mSide / 2;
    const int rows = mAnswerRow + mResultRows;
    const long long numbering = 4LL * mSide * rows;
    mPyramidRead = integers(mList ? "shadow-ray list" : "shadow-ray pyramid", mSide, rows);
    require(mPyramidRead, "the numbering of the marked pixels", (mList ? 1 : 4) * numbering);
    mTrace = gl::Framebuffer("shadow-ray answers");
    if (mList) {
        // The answers go to their pixels as image stores: the pass draws into no texture.
        mAnswers = integers("shadow-ray answers", mWidth, mHeight);
        require(mAnswers, "the rays' answers", 4LL * mWidth * mHeight);
        mTrace.emptyOfSize(mSide, rows);
    } else {
        // The same size as the pyramid's: WebGL draws into no framebuffer whose attachments
        // differ.
        mPyramid = integers("shadow-ray pyramid and answers", mSide, rows);
        require(mPyramid, "the numbering of the marked pixels", 4 * numbering);
        allocateLevels(numbering);
        mTrace.attach(GL_COLOR_ATTACHMENT0, mPyramid);
        mTrace.drawColour0();
    }
    mTrace.checkComplete();
    allocateDraws(colour, depth);
}

// The pyramid's levels (ES 3.0): copies for each level to read the last from, and their
// framebuffers, all cleared to 0 (number()). `bytes`: one texture's size.
void RayMarks::allocateLevels(long long bytes) {
    for (gl::Texture& copy : mCopies) {
        copy = integers("shadow-ray pyramid level", mSide, mAnswerRow + mResultRows);
        require(copy, "the numbering of the marked pixels", 4 * bytes);
    }
    for (std::size_t k = 0; k < 2; ++k) {
        mLevels[k] = gl::Framebuffer("shadow-ray pyramid");
        mLevels[k].attach(GL_COLOR_ATTACHMENT0, mPyramid);
        mLevels[k].attach(GL_COLOR_ATTACHMENT1, mPyramidRead);
        mLevels[k].attach(GL_COLOR_ATTACHMENT2, mCopies[k]);
        mLevels[k].drawBuffers({GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2});
        mLevels[k].checkComplete();
    }
    // The levels' passes draw only the texels over the image (number()): every other texel
    // reads 0, as cleared here once. A clear obeys the scissor test, which a tile may have on.
    const gl::ScissorPause whole;
    for (gl::Framebuffer& levels : mLevels) {
        for (int buffer = 0; buffer < 3; ++buffer)
            levels.clearUnsignedZero(buffer);
    }
}

// The first draw's target, the marks' and the second draw's.
void RayMarks::allocateDraws(const gl::Texture& colour, const gl::Texture& depth) {
    mFirst = gl::Framebuffer("shadow-ray first draw");
    mFirst.attach(GL_COLOR_ATTACHMENT0, colour);
    mFirst.attach(GL_COLOR_ATTACHMENT1, mJobs);
    mFirst.attach(GL_DEPTH_ATTACHMENT, depth);
    mFirst.drawBuffers({GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1});
    mFirst.checkComplete();
    mMarks = gl::Framebuffer("shadow-ray marks");
    mMarks.depthOnly();
    mMarks.attach(GL_DEPTH_ATTACHMENT, mDepth);
    mMarks.checkComplete();
    mTarget = gl::Framebuffer("shadow-ray pixels");
    mTarget.attach(GL_COLOR_ATTACHMENT0, colour);
    mTarget.attach(GL_DEPTH_ATTACHMENT, mDepth);
    mTarget.drawColour0();
    mTarget.checkComplete();
    mColour = colour.id();
    mFrameDepth = depth.id();
}

void RayMarks::prepare(const gl::Texture& colour, const gl::Texture& depth) {
    if (colour.id() != mColour || depth.id() != mFrameDepth || colour.width() != mWidth ||
        colour.height() != mHeight) {
        allocate(colour, depth);
    }
}

// The share of the pixels marked from which the rays' own pass pays on llvmpipe: below it, the
// jobs' stores and the numbering's passes cost more than the second draw's idle lanes (near
// it the two cost about the same: docs/techniques/shadow-maps.md).
constexpr double kCompactShare = 0.01;

bool RayMarks::compacts() {
    if (gl::activeCaps().api != gl::Api::Gl45) return true;
    if (mCounting && mCount.available()) {
        mLastCount = int(mCount.result());
        mCounting = false;
    }
    return mLastCount < 0 || mLastCount >= kCompactShare * double(mWidth) * double(mHeight);
}

void RayMarks::beginCount() {
    if (gl::activeCaps().api != gl::Api::Gl45) return;
    if (!mCount) mCount = gl::Query("shadow-ray marked pixels", GL_SAMPLES_PASSED);
    if (mCount) glBeginQuery(GL_SAMPLES_PASSED, mCount.id());
}

void RayMarks::endCount() {
    if (!mCount) return;
    glEndQuery(GL_SAMPLES_PASSED);
    mCounting = true;
}

void RayMarks::bindFirstDraw() {
    glBindFramebuffer(GL_FRAMEBUFFER, mFirst.id());
}

void RayMarks::buildPrograms(const RayTraceInputs& in) {
    if (!mMarkProgram) {
        mMarkProgram =
            gl::buildProgram("shadow-ray marks", {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                                  {GL_FRAGMENT_SHADER, "ray_marks.frag.glsl"}});
        mEmpty = gl::VertexArray("shadow-ray passes (no attributes)");
    }
    if (mList && !mListProgram) {
        mListProgram = gl::buildProgram("shadow-ray list",
                                        {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                         {GL_FRAGMENT_SHADER, "ray_list.frag.glsl"}},
                                        {"AT_NEAR"});
    }
    if (!mList && !mLevelOne) {
        mLevelOne = gl::buildProgram("shadow-ray pyramid (marks)",
                                     {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                      {GL_FRAGMENT_SHADER, "ray_pyramid.frag.glsl"}},
                                     {"LEVEL_ONE"});
        mLevelAbove = gl::buildProgram("shadow-ray pyramid (counts)",
                                       {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                        {GL_FRAGMENT_SHADER, "ray_pyramid.frag.glsl"}});
    }
    if (!mTraceProgram || mTraceLights != in.maxLights || mTraceCutouts != in.cutouts) {
        std::vector<std::string> defines = {"MAX_LIGHTS " + std::to_string(in.maxLights),
                                            "ORDER_SLOTS " + std::to_string(in.orderSlots)};
        if (in.cutouts) defines.push_back("BVH_CUTOUTS");
        mTraceProgram = gl::buildProgram("shadow rays of the marked pixels",
                                         {{GL_VERTEX_SHADER, "ray_trace.vert.glsl"},
                                          {GL_FRAGMENT_SHADER, "ray_trace.frag.glsl"}},
                                         defines);
        mTraceLights = in.maxLights;
        mTraceCutouts = in.cutouts;
    }
}

// The marks' depth target: the marked pixels' depth, 0 elsewhere (ray_marks.frag.glsl).
void RayMarks::mark(const gl::Texture& colour, const gl::Texture& depth) {
    glBindFramebuffer(GL_FRAMEBUFFER, mMarks.id());
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    gl::use(mMarkProgram);
    bindRaw(14, colour);
    bindRaw(15, depth);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

// OpenGL 4.5: the marked pixels listed (ray_list.frag.glsl), over the marks' depth, its count
// first set to 0.
void RayMarks::list() {
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    gl::use(mListProgram);
    mPyramidRead.clearUnsignedZero(0, 0, 1, 1);
    gl::imageStoresRead();
    gl::bindImage(0, mPyramidRead, GL_R32UI, GL_READ_WRITE);
    gl::uniform(17, glm::ivec2(mSide, mLevelCount));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    gl::imageStoresRead();
    gl::unbindImage(0, GL_R32UI);
}

// The pyramid, a level a pass, each into its columns of mPyramid, of mPyramidRead (which the
// rays' pass reads while it writes its answers under the pyramid in mPyramid) and of a copy,
// read by the next level from the other copy. A pass draws only the texels over the image
// (the rest stay as allocate() cleared them): on llvmpipe a pass costs little more than its
// fragments, and a level a pass measured faster than several levels summed in one.
// `marked`: x0, y0, x1, y1 of the pixels this draw marked.
void RayMarks::number(const gl::Texture& colour, glm::ivec4 marked) {
    for (int level = 1; level <= mLevelCount; ++level) {
        const int pass = level - 1;
        glBindFramebuffer(GL_FRAMEBUFFER, mLevels[pass & 1].id());
        const int round = (1 << level) - 1;
        glViewport(mSide - (mSide >> (level - 1)), 0, (mWidth + round) >> level,
                   (mHeight + round) >> level);
        gl::use(level == 1 ? mLevelOne : mLevelAbove);
        bindRaw(14, level == 1 ? colour : mCopies[(pass - 1) & 1]);
        gl::uniform(0, glm::ivec2(level, mSide));
        gl::uniform(1, marked);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
}

glm::ivec2 RayMarks::trace(const gl::Texture& colour, const gl::Texture& depth,
                           const RayTraceInputs& in, bool compact) {
    buildPrograms(in);
    glBindVertexArray(mEmpty.id());
    mark(colour, depth);
    if (!compact) {
        glBindFramebuffer(GL_FRAMEBUFFER, mTarget.id());
        return glm::ivec2(0);
    }

    if (mList) list();  // under a tile's scissor: only the pixels this draw marked
    const glm::ivec2 numbering(mSide, mLevelCount);
    {
        const gl::ScissorPause whole;  // the numbering and the rays' pass cover their textures
        const GLint* b = whole.box();
        if (!mList) {
            number(colour, whole.wasOn() ? glm::ivec4(b[0], b[1], b[0] + b[2], b[1] + b[3])
                                         : glm::ivec4(0, 0, mWidth, mHeight));
        }
        traceJobs(in, numbering);
    }
    glViewport(0, 0, mWidth, mHeight);
    glBindFramebuffer(GL_FRAMEBUFFER, mTarget.id());
    bindRaw(14, mList ? mAnswers : mPyramid);
    return mList ? glm::ivec2(0) : numbering;
}

// The rays' pass: a fragment per numbered job, its answer under the pyramid (and, on OpenGL
// 4.5, at its pixel in mAnswers).
void RayMarks::traceJobs(const RayTraceInputs& in, glm::ivec2 numbering) {
    glBindFramebuffer(GL_FRAMEBUFFER, mTrace.id());
    glViewport(0, mAnswerRow, mSide, mResultRows);
    gl::use(mTraceProgram);
    bindRaw(14, mPyramidRead);
    bindRaw(15, mJobs);
    gl::uniform(1, mResultRows);
    gl::uniform(5, in.eye);
    gl::uniform(16, in.rayScale);
    gl::uniform(17, numbering);
    setPixelRayUniforms(in.pixelRays);
    if (mList) gl::bindImage(1, mAnswers, GL_R32UI);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    if (mList) {
        gl::imageStoresRead();
        gl::unbindImage(1, GL_R32UI);
    }
}

}  // namespace gnomon::render
