#include "render/RayMarks.h"

#include "gl/Program.h"

namespace gnomon::render {

void RayMarks::allocate(const gl::Texture& colour) {
    mWidth = colour.width();
    mHeight = colour.height();
    mColour = colour.id();
    mDepth = gl::Texture::plain2D("shadow-ray marks", GL_DEPTH_COMPONENT32F, mWidth, mHeight);
    mMarks = gl::Framebuffer("shadow-ray marks");
    mMarks.depthOnly();
    mMarks.attach(GL_DEPTH_ATTACHMENT, mDepth);
    mMarks.checkComplete();
    mTarget = gl::Framebuffer("shadow-ray pixels");
    mTarget.attach(GL_COLOR_ATTACHMENT0, colour);
    mTarget.attach(GL_DEPTH_ATTACHMENT, mDepth);
    mTarget.drawColour0();
    mTarget.checkComplete();
}

void RayMarks::mark(const gl::Texture& colour, const gl::Texture& depth) {
    if (!mProgram) {
        mProgram =
            gl::buildProgram("shadow-ray marks", {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                                  {GL_FRAGMENT_SHADER, "ray_marks.frag.glsl"}});
        mEmpty = gl::VertexArray("shadow-ray marks (no attributes)");
    }
    if (colour.id() != mColour || colour.width() != mWidth || colour.height() != mHeight) {
        allocate(colour);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, mMarks.id());
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    gl::use(mProgram);
    gl::bindTexture(14, colour);
    gl::bindTexture(15, depth);
    glBindSampler(14, 0);
    glBindSampler(15, 0);
    glBindVertexArray(mEmpty.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, mTarget.id());
}

}  // namespace gnomon::render
