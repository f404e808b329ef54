// The GL object wrappers gnomon uses: buffers, vertex arrays, textures, samplers,
// framebuffers (completeness reported in words), shaders/programs and queries.
// All creation is DSA; every object gets a debug label so captures and KHR_debug read well.
#pragma once

#include <array>
#include <cstddef>
#include <string>

#include "gl/Object.h"
#include "gl/ShaderSource.h"
#include "gnomon/Image.h"

namespace gnomon::gl {

struct BufferDeleter {
    static void destroy(GLuint n) { glDeleteBuffers(1, &n); }
};
struct VertexArrayDeleter {
    static void destroy(GLuint n) { glDeleteVertexArrays(1, &n); }
};
struct TextureDeleter {
    static void destroy(GLuint n) { glDeleteTextures(1, &n); }
};
struct SamplerDeleter {
    static void destroy(GLuint n) { glDeleteSamplers(1, &n); }
};
struct FramebufferDeleter {
    static void destroy(GLuint n) { glDeleteFramebuffers(1, &n); }
};
struct ProgramDeleter {
    static void destroy(GLuint n) { glDeleteProgram(n); }
};
struct ShaderDeleter {
    static void destroy(GLuint n) { glDeleteShader(n); }
};
struct QueryDeleter {
    static void destroy(GLuint n) { glDeleteQueries(1, &n); }
};

class Buffer : public Object<BufferDeleter> {
public:
    Buffer() = default;
    // Immutable storage of `bytes` (data may be null); flags as glNamedBufferStorage.
    Buffer(const std::string& label, std::size_t bytes, const void* data, GLbitfield flags);
    std::size_t size() const { return mSize; }
    void update(std::size_t offset, std::size_t bytes, const void* data);

private:
    std::size_t mSize = 0;
};

class VertexArray : public Object<VertexArrayDeleter> {
public:
    VertexArray() = default;
    explicit VertexArray(const std::string& label);
};

class Texture : public Object<TextureDeleter> {
public:
    Texture() = default;
    // 2D texture array with `layers` layers of width x height, one mip level.
    static Texture array2D(const std::string& label, GLenum internalFormat, int width, int height,
                           int layers);
    // Cube-map array of `cubes` cubes (6 layers each) of size x size, one mip level.
    static Texture cubeArray(const std::string& label, GLenum internalFormat, int size, int cubes);
    // 2D texture, one mip level.
    static Texture plain2D(const std::string& label, GLenum internalFormat, int width, int height);
    // 2D sRGB colour image (RGBA8 rows from `rgba`, first row at t = 0) with a full mip chain,
    // wrap modes and filters set on the texture itself.
    static Texture image2D(const std::string& label, int width, int height, const void* rgba,
                           GLint wrapS, GLint wrapT, bool nearest);
    // An image to show as it is (a UI's overlay): RGBA8 (grey and RGB widened, alpha 255
    // where absent), bytes not decoded when sampled, one level, NEAREST, first row at t = 0.
    static Texture display2D(const std::string& label, const Image& image);
    // A 2D-array view of `source`'s layers (a cube-map array's faces as stored), sharing its
    // storage.
    static Texture layersView(const std::string& label, const Texture& source);
    // A buffer texture over the whole of `buffer`, its bytes read as texels of `format`
    // (texelFetch on a samplerBuffer).
    static Texture bufferView(const std::string& label, const Buffer& buffer, GLenum format);
    // A 2D view of `source`'s first level in a compatible format (SRGB8_ALPHA8 as RGBA8:
    // the stored bytes, undecoded), sharing its storage; NEAREST filtering.
    static Texture view2D(const std::string& label, const Texture& source, GLenum viewFormat);
    // False when the driver refused the storage (out of memory, or beyond its limits): the
    // object exists but has no images. Checked by the texture itself, not the error queue.
    bool allocated() const;
    int width() const { return mWidth; }
    int height() const { return mHeight; }
    int layers() const { return mLayers; }  // array layers; cube arrays: 6 per cube
    GLenum format() const { return mFormat; }

private:
    Texture(GLuint name, GLenum format, int w, int h, int layers)
        : Object(name), mWidth(w), mHeight(h), mLayers(layers), mFormat(format) {}
    int mWidth = 0, mHeight = 0, mLayers = 0;
    GLenum mFormat = 0;
};

class Sampler : public Object<SamplerDeleter> {
public:
    Sampler() = default;
    explicit Sampler(const std::string& label);
    Sampler& set(GLenum parameter, GLint value);
    Sampler& setBorder(float r, float g, float b, float a);
    // `filter` (minifying and magnifying), clamped to the edge, no comparison.
    static Sampler clamped(const std::string& label, GLint filter);
    // NEAREST, clamped to the edge, no comparison: a depth texture's stored values as they are.
    static Sampler storedDepth(const std::string& label) { return clamped(label, GL_NEAREST); }
};

class Framebuffer : public Object<FramebufferDeleter> {
public:
    Framebuffer() = default;
    explicit Framebuffer(const std::string& label);
    // Throws gnomon::Error naming the completeness status in words.
    void checkComplete() const;

private:
    std::string mLabel;
};

// The status returned by glCheckNamedFramebufferStatus, in words.
std::string framebufferStatusText(GLenum status);

// A linked program, in the dialect it was built for. Its shaders give their uniforms fixed
// locations (gl/Program.h): OpenGL 4.5 keeps them; GLSL ES has none, so there the program
// holds the location the link gave each (-1: inactive).
class Program : public Object<ProgramDeleter> {
public:
    Program() { mLocations.fill(-1); }
    explicit Program(GLuint name, Api api = Api::Gl45) : Object(name), mApi(api) {
        mLocations.fill(-1);
    }
    Api api() const { return mApi; }
    // The location of the uniform the shaders declare at `fixed` (0 to kFixedLocations - 1).
    GLint location(int fixed) const {
        return mApi == Api::Gl45 ? fixed : mLocations[std::size_t(fixed)];
    }
    const std::array<GLint, kFixedLocations>& locations() const { return mLocations; }
    void setLocation(int fixed, GLint location) { mLocations[std::size_t(fixed)] = location; }
    GLint uniform(const char* name) const { return glGetUniformLocation(id(), name); }

private:
    Api mApi = Api::Gl45;
    std::array<GLint, kFixedLocations> mLocations;
};

class Query : public Object<QueryDeleter> {
public:
    Query() = default;
    // Empty (false) when the driver refuses `target` although it advertises it (llvmpipe in a
    // GLX context does so for pipeline statistics).
    Query(const std::string& label, GLenum target);
};

}  // namespace gnomon::gl
