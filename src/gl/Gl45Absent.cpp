// The web build only: the OpenGL 4.5 calls of Gl45Only.h, each throwing a sentence that
// names it. gl::Caps keeps the wrappers off these paths in a browser; reaching one is a bug.
#include <string>

#include "gl/Gl.h"
#include "gnomon/Error.h"

namespace {
[[noreturn]] void absent(const char* call) {
    throw gnomon::Error(gnomon::ErrorKind::Gl,
                        std::string(call) + " is OpenGL 4.5's; WebGL2 has no such call");
}
}  // namespace

extern "C" {
void glBindImageTexture(GLuint, GLuint, GLint, GLboolean, GLint, GLenum, GLenum) {
    absent("glBindImageTexture");
}
void glBindTextureUnit(GLuint, GLuint) {
    absent("glBindTextureUnit");
}
void glBlitNamedFramebuffer(GLuint, GLuint, GLint, GLint, GLint, GLint, GLint, GLint, GLint, GLint,
                            GLbitfield, GLenum) {
    absent("glBlitNamedFramebuffer");
}
GLenum glCheckNamedFramebufferStatus(GLuint, GLenum) {
    absent("glCheckNamedFramebufferStatus");
}
void glClearNamedFramebufferfv(GLuint, GLenum, GLint, const GLfloat*) {
    absent("glClearNamedFramebufferfv");
}
void glClearNamedFramebufferuiv(GLuint, GLenum, GLint, const GLuint*) {
    absent("glClearNamedFramebufferuiv");
}
void glClearTexImage(GLuint, GLint, GLenum, GLenum, const void*) {
    absent("glClearTexImage");
}
void glClearTexSubImage(GLuint, GLint, GLint, GLint, GLint, GLsizei, GLsizei, GLsizei, GLenum,
                        GLenum, const void*) {
    absent("glClearTexSubImage");
}
void glCreateBuffers(GLsizei, GLuint*) {
    absent("glCreateBuffers");
}
void glCreateFramebuffers(GLsizei, GLuint*) {
    absent("glCreateFramebuffers");
}
void glCreateQueries(GLenum, GLsizei, GLuint*) {
    absent("glCreateQueries");
}
void glCreateSamplers(GLsizei, GLuint*) {
    absent("glCreateSamplers");
}
void glCreateTextures(GLenum, GLsizei, GLuint*) {
    absent("glCreateTextures");
}
void glCreateVertexArrays(GLsizei, GLuint*) {
    absent("glCreateVertexArrays");
}
void glDrawElementsInstancedBaseVertexBaseInstance(GLenum, GLsizei, GLenum, const void*, GLsizei,
                                                   GLint, GLuint) {
    absent("glDrawElementsInstancedBaseVertexBaseInstance");
}
void glEnableVertexArrayAttrib(GLuint, GLuint) {
    absent("glEnableVertexArrayAttrib");
}
void glGenerateTextureMipmap(GLuint) {
    absent("glGenerateTextureMipmap");
}
void glGetQueryObjecti64v(GLuint, GLenum, GLint64*) {
    absent("glGetQueryObjecti64v");
}
void glGetTextureParameteriv(GLuint, GLenum, GLint*) {
    absent("glGetTextureParameteriv");
}
void glGetTextureSubImage(GLuint, GLint, GLint, GLint, GLint, GLsizei, GLsizei, GLsizei, GLenum,
                          GLenum, GLsizei, void*) {
    absent("glGetTextureSubImage");
}
void glMemoryBarrier(GLbitfield) {
    absent("glMemoryBarrier");
}
void glMultiDrawElementsIndirect(GLenum, GLenum, const void*, GLsizei, GLsizei) {
    absent("glMultiDrawElementsIndirect");
}
void glNamedBufferStorage(GLuint, GLsizeiptr, const void*, GLbitfield) {
    absent("glNamedBufferStorage");
}
void glNamedBufferSubData(GLuint, GLintptr, GLsizeiptr, const void*) {
    absent("glNamedBufferSubData");
}
void glNamedFramebufferDrawBuffer(GLuint, GLenum) {
    absent("glNamedFramebufferDrawBuffer");
}
void glNamedFramebufferParameteri(GLuint, GLenum, GLint) {
    absent("glNamedFramebufferParameteri");
}
void glNamedFramebufferDrawBuffers(GLuint, GLsizei, const GLenum*) {
    absent("glNamedFramebufferDrawBuffers");
}
void glNamedFramebufferReadBuffer(GLuint, GLenum) {
    absent("glNamedFramebufferReadBuffer");
}
void glNamedFramebufferTexture(GLuint, GLenum, GLuint, GLint) {
    absent("glNamedFramebufferTexture");
}
void glNamedFramebufferTextureLayer(GLuint, GLenum, GLuint, GLint, GLint) {
    absent("glNamedFramebufferTextureLayer");
}
void glObjectLabel(GLenum, GLuint, GLsizei, const GLchar*) {
    absent("glObjectLabel");
}
void glTextureBuffer(GLuint, GLenum, GLuint) {
    absent("glTextureBuffer");
}
void glTextureParameteri(GLuint, GLenum, GLint) {
    absent("glTextureParameteri");
}
void glTextureStorage2D(GLuint, GLsizei, GLenum, GLsizei, GLsizei) {
    absent("glTextureStorage2D");
}
void glTextureStorage3D(GLuint, GLsizei, GLenum, GLsizei, GLsizei, GLsizei) {
    absent("glTextureStorage3D");
}
void glTextureSubImage2D(GLuint, GLint, GLint, GLint, GLsizei, GLsizei, GLenum, GLenum,
                         const void*) {
    absent("glTextureSubImage2D");
}
void glTextureView(GLuint, GLenum, GLuint, GLenum, GLuint, GLuint, GLuint, GLuint) {
    absent("glTextureView");
}
void glVertexArrayAttribBinding(GLuint, GLuint, GLuint) {
    absent("glVertexArrayAttribBinding");
}
void glVertexArrayAttribFormat(GLuint, GLuint, GLint, GLenum, GLboolean, GLuint) {
    absent("glVertexArrayAttribFormat");
}
void glVertexArrayAttribIFormat(GLuint, GLuint, GLint, GLenum, GLuint) {
    absent("glVertexArrayAttribIFormat");
}
void glVertexArrayBindingDivisor(GLuint, GLuint, GLuint) {
    absent("glVertexArrayBindingDivisor");
}
void glVertexArrayElementBuffer(GLuint, GLuint) {
    absent("glVertexArrayElementBuffer");
}
void glVertexArrayVertexBuffer(GLuint, GLuint, GLuint, GLintptr, GLsizei) {
    absent("glVertexArrayVertexBuffer");
}
}
