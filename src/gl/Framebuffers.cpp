// gl::Framebuffer: attachments, clears, blits and completeness, on OpenGL 4.5 with direct
// state access and on ES 3.0 through the draw/read framebuffer bindings, which are put back
// as they were after each edit (a pass may edit one framebuffer while another is bound).
#include <cstdio>

#include "gl/Caps.h"
#include "gl/Objects.h"
#include "gnomon/Error.h"

namespace gnomon::gl {
namespace {

bool dsa() {
    return activeCaps().directStateAccess;
}

// ES: `name` bound as the draw (and with `read`, the read) framebuffer for one edit.
class EditBinding {
public:
    explicit EditBinding(GLuint name, bool read = false) : mRead(read) {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &mDraw);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, name);
        if (mRead) {
            glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &mReadBinding);
            glBindFramebuffer(GL_READ_FRAMEBUFFER, name);
        }
    }
    ~EditBinding() {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(mDraw));
        if (mRead) glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(mReadBinding));
    }
    EditBinding(const EditBinding&) = delete;
    EditBinding& operator=(const EditBinding&) = delete;

private:
    bool mRead;
    GLint mDraw = 0, mReadBinding = 0;
};

}  // namespace

Framebuffer::Framebuffer(const std::string& label) : mLabel(label) {
    GLuint n = 0;
    if (dsa()) {
        glCreateFramebuffers(1, &n);
    } else {
        glGenFramebuffers(1, &n);
        EditBinding edit(n);  // ES makes the object at its first binding
    }
    static_cast<Object&>(*this) = Object(n);
    setLabel(GL_FRAMEBUFFER, n, label);
}

std::string framebufferStatusText(GLenum status) {
    switch (status) {
        case GL_FRAMEBUFFER_COMPLETE:
            return "complete";
        case GL_FRAMEBUFFER_UNDEFINED:
            return "undefined (no default framebuffer)";
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
            return "incomplete attachment (an attached image is not renderable or has no size)";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
            return "missing attachment (nothing is attached)";
        case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER:
            return "incomplete draw buffer (a draw buffer names an empty attachment)";
        case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER:
            return "incomplete read buffer (the read buffer names an empty attachment)";
        case GL_FRAMEBUFFER_UNSUPPORTED:
            return "unsupported (this combination of formats is not supported by the driver)";
        case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
            return "incomplete multisample (attachments differ in sample count)";
        case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
            return "incomplete layer targets (layered and non-layered attachments mixed)";
        default:
            return "unknown status 0x" + [&] {
                char buf[16];
                std::snprintf(buf, sizeof buf, "%04X", status);
                return std::string(buf);
            }();
    }
}

void Framebuffer::checkComplete() const {
    GLenum status = 0;
    if (dsa()) {
        status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
    } else {
        EditBinding edit(id());
        status = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER);
    }
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        throw Error(ErrorKind::Gl, "framebuffer '" + mLabel +
                                       "' is not complete: " + framebufferStatusText(status));
    }
}

void Framebuffer::attach(GLenum attachment, const Texture& texture) {
    if (dsa()) {
        glNamedFramebufferTexture(id(), attachment, texture.id(), 0);
        return;
    }
    if (texture.target() != GL_TEXTURE_2D) {
        throw Error(ErrorKind::Gl, "framebuffer '" + mLabel +
                                       "': layered rendering is not available in OpenGL ES 3.0");
    }
    EditBinding edit(id());
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, attachment, GL_TEXTURE_2D, texture.id(), 0);
}

void Framebuffer::attachLayer(GLenum attachment, const Texture& texture, int layer) {
    if (dsa()) {
        glNamedFramebufferTextureLayer(id(), attachment, texture.id(), 0, layer);
        return;
    }
    EditBinding edit(id());
    glFramebufferTextureLayer(GL_DRAW_FRAMEBUFFER, attachment, texture.id(), 0, layer);
}

void Framebuffer::depthOnly() {
    if (dsa()) {
        glNamedFramebufferDrawBuffer(id(), GL_NONE);
        glNamedFramebufferReadBuffer(id(), GL_NONE);
        return;
    }
    EditBinding edit(id(), true);
    const GLenum none = GL_NONE;
    glDrawBuffers(1, &none);
    glReadBuffer(GL_NONE);
}

void Framebuffer::drawColour0() {
    if (dsa()) {
        glNamedFramebufferDrawBuffer(id(), GL_COLOR_ATTACHMENT0);
        return;
    }
    EditBinding edit(id());
    const GLenum colour0 = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &colour0);
}

void Framebuffer::emptyOfSize(int width, int height) {
    if (!dsa()) {
        throw Error(ErrorKind::Gl,
                    "framebuffer '" + mLabel + "': one without attachments needs OpenGL 4.5");
    }
    glNamedFramebufferParameteri(id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, width);
    glNamedFramebufferParameteri(id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, height);
    glNamedFramebufferDrawBuffer(id(), GL_NONE);
}

void Framebuffer::drawBuffers(const std::vector<GLenum>& buffers) {
    if (dsa()) {
        glNamedFramebufferDrawBuffers(id(), GLsizei(buffers.size()), buffers.data());
        return;
    }
    EditBinding edit(id());
    glDrawBuffers(GLsizei(buffers.size()), buffers.data());
}

void Framebuffer::clearDepth(float depth) {
    if (dsa()) {
        glClearNamedFramebufferfv(id(), GL_DEPTH, 0, &depth);
        return;
    }
    EditBinding edit(id());
    glClearBufferfv(GL_DEPTH, 0, &depth);
}

void Framebuffer::clearColour(const float rgba[4]) {
    if (dsa()) {
        glClearNamedFramebufferfv(id(), GL_COLOR, 0, rgba);
        return;
    }
    EditBinding edit(id());
    glClearBufferfv(GL_COLOR, 0, rgba);
}

void Framebuffer::clearUnsignedZero(int buffer) {
    const GLuint zero[4] = {0, 0, 0, 0};
    if (dsa()) {
        glClearNamedFramebufferuiv(id(), GL_COLOR, buffer, zero);
        return;
    }
    EditBinding edit(id());
    glClearBufferuiv(GL_COLOR, buffer, zero);
}

void Framebuffer::blitDepthFrom(const Framebuffer& source, int width, int height) {
    if (dsa()) {
        glBlitNamedFramebuffer(source.id(), id(), 0, 0, width, height, 0, 0, width, height,
                               GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        return;
    }
    EditBinding edit(id(), true);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, source.id());
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
}

}  // namespace gnomon::gl
