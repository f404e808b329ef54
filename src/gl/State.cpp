#include "gl/State.h"

#include "gl/Caps.h"
#include "gnomon/Error.h"

namespace gnomon::gl {
namespace {
void requireImages() {
    if (!activeCaps().imageStore) {
        throw Error(ErrorKind::Gl,
                    "image stores (gnomon score's visibility, the shadow rays' list) are not "
                    "available in OpenGL ES 3.0 / WebGL2");
    }
}
}  // namespace

void setDepthClamp(bool on) {
    if (!activeCaps().depthClamp) return;
    // GL_DEPTH_CLAMP and ES's GL_DEPTH_CLAMP_EXT are the same enum.
    on ? glEnable(GL_DEPTH_CLAMP) : glDisable(GL_DEPTH_CLAMP);
}

void setSrgbWrites(bool on) {
    if (!activeCaps().srgbWriteControl) return;
    on ? glEnable(GL_FRAMEBUFFER_SRGB) : glDisable(GL_FRAMEBUFFER_SRGB);
}

ScissorPause::ScissorPause() : mOn(glIsEnabled(GL_SCISSOR_TEST) == GL_TRUE) {
    if (!mOn) return;
    glGetIntegerv(GL_SCISSOR_BOX, mBox);
    glDisable(GL_SCISSOR_TEST);
}

ScissorPause::~ScissorPause() {
    if (mOn) glEnable(GL_SCISSOR_TEST);
}

void bindImage(int unit, const Texture& texture, GLenum format, GLenum access) {
    requireImages();
    const GLboolean layered = texture.target() == GL_TEXTURE_2D ? GL_FALSE : GL_TRUE;
    glBindImageTexture(GLuint(unit), texture.id(), 0, layered, 0, access, format);
}

void unbindImage(int unit, GLenum format) {
    requireImages();
    glBindImageTexture(GLuint(unit), 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
}

void imageStoresDone() {
    requireImages();
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
}

void imageStoresRead() {
    requireImages();
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT);
}

#ifdef __EMSCRIPTEN__
Finisher::Finisher()
    : mTexel(Texture::plain2D("finisher texel", GL_RGBA8, 1, 1)), mTarget("finisher target") {
    mTarget.attach(GL_COLOR_ATTACHMENT0, mTexel);
}

void Finisher::wait() {
    GLint read = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, mTarget.id());
    std::uint8_t texel[4];
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(read));
}
#else
Finisher::Finisher() = default;

void Finisher::wait() {
    glFinish();
}
#endif

}  // namespace gnomon::gl
