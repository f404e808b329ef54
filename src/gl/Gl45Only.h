// The web build only (WebGL2 has none of these): the OpenGL 4.5 entry points and enums that
// src/gl's wrappers use on their OpenGL 4.5 path, which gl::Caps never takes in a browser.
// Gl45Absent.cpp defines the calls to throw a sentence naming the call, so a wrong capability
// shows as an error, never as a silent wrong picture.
#pragma once

#include <GLES3/gl3.h>

#define GL_BUFFER 0x82E0
#define GL_PROGRAM 0x82E2
#define GL_QUERY 0x82E3
#define GL_SAMPLER 0x82E6
#define GL_VERTEX_ARRAY 0x8074
#define GL_DEPTH_CLAMP 0x864F
#define GL_DRAW_INDIRECT_BUFFER 0x8F3F
#define GL_DYNAMIC_STORAGE_BIT 0x0100
#define GL_FRAGMENT_SHADER_INVOCATIONS_ARB 0x82F4
#define GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER 0x8CDB
#define GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS 0x8DA8
#define GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER 0x8CDC
#define GL_FRAMEBUFFER_SRGB 0x8DB9
#define GL_FRAMEBUFFER_DEFAULT_WIDTH 0x9310
#define GL_FRAMEBUFFER_DEFAULT_HEIGHT 0x9311
#define GL_MAX_TEXTURE_BUFFER_SIZE 0x8C2B
#define GL_RGBA16 0x805B
#define GL_SAMPLES_PASSED 0x8914
#define GL_TEXTURE_BORDER_COLOR 0x1004
#define GL_TEXTURE_BUFFER 0x8C2A
#define GL_TEXTURE_CUBE_MAP_ARRAY 0x9009
#define GL_TEXTURE_CUBE_MAP_SEAMLESS 0x884F
#define GL_TEXTURE_UPDATE_BARRIER_BIT 0x00000100
#define GL_TEXTURE_FETCH_BARRIER_BIT 0x00000008
#define GL_SHADER_IMAGE_ACCESS_BARRIER_BIT 0x00000020
#define GL_WRITE_ONLY 0x88B9
#define GL_READ_WRITE 0x88BA

extern "C" {
void glBindImageTexture(GLuint, GLuint, GLint, GLboolean, GLint, GLenum, GLenum);
void glBindTextureUnit(GLuint, GLuint);
void glBlitNamedFramebuffer(GLuint, GLuint, GLint, GLint, GLint, GLint, GLint, GLint, GLint, GLint,
                            GLbitfield, GLenum);
GLenum glCheckNamedFramebufferStatus(GLuint, GLenum);
void glClearNamedFramebufferfv(GLuint, GLenum, GLint, const GLfloat*);
void glClearNamedFramebufferuiv(GLuint, GLenum, GLint, const GLuint*);
void glClearTexImage(GLuint, GLint, GLenum, GLenum, const void*);
void glClearTexSubImage(GLuint, GLint, GLint, GLint, GLint, GLsizei, GLsizei, GLsizei, GLenum,
                        GLenum, const void*);
void glCreateBuffers(GLsizei, GLuint*);
void glCreateFramebuffers(GLsizei, GLuint*);
void glCreateQueries(GLenum, GLsizei, GLuint*);
void glCreateSamplers(GLsizei, GLuint*);
void glCreateTextures(GLenum, GLsizei, GLuint*);
void glCreateVertexArrays(GLsizei, GLuint*);
void glDrawElementsInstancedBaseVertexBaseInstance(GLenum, GLsizei, GLenum, const void*, GLsizei,
                                                   GLint, GLuint);
void glEnableVertexArrayAttrib(GLuint, GLuint);
void glGenerateTextureMipmap(GLuint);
void glGetQueryObjecti64v(GLuint, GLenum, GLint64*);
void glGetTextureParameteriv(GLuint, GLenum, GLint*);
void glGetTextureSubImage(GLuint, GLint, GLint, GLint, GLint, GLsizei, GLsizei, GLsizei, GLenum,
                          GLenum, GLsizei, void*);
void glMemoryBarrier(GLbitfield);
void glMultiDrawElementsIndirect(GLenum, GLenum, const void*, GLsizei, GLsizei);
void glNamedBufferStorage(GLuint, GLsizeiptr, const void*, GLbitfield);
void glNamedBufferSubData(GLuint, GLintptr, GLsizeiptr, const void*);
void glNamedFramebufferDrawBuffer(GLuint, GLenum);
void glNamedFramebufferParameteri(GLuint, GLenum, GLint);
void glNamedFramebufferDrawBuffers(GLuint, GLsizei, const GLenum*);
void glNamedFramebufferReadBuffer(GLuint, GLenum);
void glNamedFramebufferTexture(GLuint, GLenum, GLuint, GLint);
void glNamedFramebufferTextureLayer(GLuint, GLenum, GLuint, GLint, GLint);
void glObjectLabel(GLenum, GLuint, GLsizei, const GLchar*);
void glTextureBuffer(GLuint, GLenum, GLuint);
void glTextureParameteri(GLuint, GLenum, GLint);
void glTextureStorage2D(GLuint, GLsizei, GLenum, GLsizei, GLsizei);
void glTextureStorage3D(GLuint, GLsizei, GLenum, GLsizei, GLsizei, GLsizei);
void glTextureSubImage2D(GLuint, GLint, GLint, GLint, GLsizei, GLsizei, GLenum, GLenum,
                         const void*);
void glTextureView(GLuint, GLenum, GLuint, GLenum, GLuint, GLuint, GLuint, GLuint);
void glVertexArrayAttribBinding(GLuint, GLuint, GLuint);
void glVertexArrayAttribFormat(GLuint, GLuint, GLint, GLenum, GLboolean, GLuint);
void glVertexArrayAttribIFormat(GLuint, GLuint, GLint, GLenum, GLuint);
void glVertexArrayBindingDivisor(GLuint, GLuint, GLuint);
void glVertexArrayElementBuffer(GLuint, GLuint);
void glVertexArrayVertexBuffer(GLuint, GLuint, GLuint, GLintptr, GLsizei);
}
