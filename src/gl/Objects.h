// The GL object wrappers gnomon uses: buffers, vertex arrays, textures, samplers,
// framebuffers (completeness reported in words), shaders/programs and queries, made and
// edited only here. On OpenGL 4.5 they use direct state access; on OpenGL ES 3.0 (WebGL2)
// they bind to edit (activeCaps(), Caps.h), so callers must bind again before drawing, as
// the passes do. Every object gets a debug label so captures and KHR_debug read well.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

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
    // WebGL fixes at a buffer's first binding whether it holds indices: say so up front.
    enum class Use { Data, Indices };
    Buffer() = default;
    // Immutable storage of `bytes` (data may be null); flags as glNamedBufferStorage.
    Buffer(const std::string& label, std::size_t bytes, const void* data, GLbitfield flags,
           Use use = Use::Data);
    std::size_t size() const { return mSize; }
    void update(std::size_t offset, std::size_t bytes, const void* data);
    // Where ES binds it to edit: GL_ELEMENT_ARRAY_BUFFER or GL_ARRAY_BUFFER.
    GLenum editTarget() const { return mEditTarget; }

private:
    std::size_t mSize = 0;
    GLenum mEditTarget = GL_ARRAY_BUFFER;
};

class VertexArray : public Object<VertexArrayDeleter> {
public:
    VertexArray() = default;
    explicit VertexArray(const std::string& label);
    // The layout, as OpenGL 4.5 separates it: buffers at binding points, attributes reading
    // from a binding point. ES 3.0 has no binding points: the wrapper keeps both and
    // specifies each attribute again whenever its binding or format changes.
    void vertexBuffer(int binding, const Buffer& buffer, std::size_t offset, int stride);
    void attribute(int index, int binding, int components, GLenum type, std::size_t offset);
    void integerAttribute(int index, int binding, int components, GLenum type, std::size_t offset);
    void divisor(int binding, int divisor);
    void elements(const Buffer& indices);

private:
    struct Binding {
        GLuint buffer = 0;
        std::size_t offset = 0;
        int stride = 0, divisor = 0;
    };
    struct Attribute {
        bool used = false, integer = false;
        int binding = 0, components = 0;
        GLenum type = 0;
        std::size_t offset = 0;
    };
    void specify(int index);  // ES: one attribute from its binding and format
    Binding mBindings[4];
    Attribute mAttributes[8];
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
    // Records of RGBA32F texels for texelFetch (no filtering): `texels` texels from `rgba`
    // in rows of `rowTexels`, texel k at (k mod rowTexels, k / rowTexels); the last row is
    // padded with zeros. Data a shader reads where buffer textures are missing (ES) or too
    // small.
    static Texture texelRows(const std::string& label, const float* rgba, std::size_t texels,
                             int rowTexels);
    // New contents for a texelRows texture: `texels` texels (at most its width x height).
    void writeTexelRows(const float* rgba, std::size_t texels);
    // RGBA32I texels for texelFetch (integer textures are never filtered): width x height
    // from `rgba`, the row at y = 0 first.
    static Texture integers2D(const std::string& label, const std::int32_t* rgba, int width,
                              int height);
    // New contents for an integers2D texture, all of its texels.
    void writeIntegers2D(const std::int32_t* rgba);
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
    void setParameter(GLenum parameter, GLint value);
    // Depth comparison (LEQUAL) for shadow samplers, clamped to the edge.
    void setDepthCompare();
    // Texels of one layer's rectangle of level 0 into `out` (`bytes` long), rows from the
    // bottom. OpenGL 4.5 only (ES reads through a framebuffer: Framebuffer::readColour).
    void read(int x, int y, int layer, int width, int height, GLenum format, GLenum type,
              std::size_t bytes, void* out) const;
    // Every texel of level 0 (all layers) set to `value` given as `format`/GL_FLOAT.
    void clear(GLenum format, const float* value);
    // The 6 faces of cube `cube` of a cube-map array set to `depth` (OpenGL 4.5; ES clears
    // through framebuffers).
    void clearCubeDepth(int cube, float depth);
    // A rectangle of level 0 (of layer `layer`) of an unsigned integer texture set to 0
    // (OpenGL 4.5).
    void clearUnsignedZero(int x, int y, int width, int height, int layer = 0);
    // GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY, GL_TEXTURE_CUBE_MAP_ARRAY or GL_TEXTURE_BUFFER;
    // cube-map arrays are GL_TEXTURE_2D_ARRAY of 6 layers per cube where the API lacks them.
    GLenum target() const { return mTarget; }
    int width() const { return mWidth; }
    int height() const { return mHeight; }
    int layers() const { return mLayers; }  // array layers; cube arrays: 6 per cube
    GLenum format() const { return mFormat; }

private:
    Texture(GLuint name, GLenum target, GLenum format, int w, int h, int layers)
        : Object(name), mWidth(w), mHeight(h), mLayers(layers), mFormat(format), mTarget(target) {}
    static GLuint create(GLenum target);
    int mWidth = 0, mHeight = 0, mLayers = 0;
    GLenum mFormat = 0, mTarget = 0;
};

// Texture unit `unit` samples `texture` (an empty one unbinds what the unit holds).
void bindTexture(int unit, const Texture& texture);
// A 2D texture known by name only (a material's).
void bindTexture2D(int unit, GLuint texture);

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
    // `texture`'s level 0 at `attachment` (GL_COLOR_ATTACHMENT0, GL_DEPTH_ATTACHMENT): a 2D
    // texture, or every layer of an array (layered rendering, OpenGL 4.5 only).
    void attach(GLenum attachment, const Texture& texture);
    void attachLayer(GLenum attachment, const Texture& texture, int layer);
    // No colour buffer drawn or read: depth only.
    void depthOnly();
    // Draws into colour attachment 0 only.
    void drawColour0();
    // No attachments: draws of width x height pixels whose fragments only store to images
    // (OpenGL 4.5; ES 3.0 has no such framebuffer).
    void emptyOfSize(int width, int height);
    // Fragment output i goes to buffers[i] (GL_COLOR_ATTACHMENTi or GL_NONE).
    void drawBuffers(const std::vector<GLenum>& buffers);
    void clearDepth(float depth);
    void clearColour(const float rgba[4]);
    // Draw buffer `buffer` (an unsigned-integer one) set to 0, under the scissor test if on.
    void clearUnsignedZero(int buffer);
    // The depth of `source`'s rectangle (0, 0, width, height) copied in.
    void blitDepthFrom(const Framebuffer& source, int width, int height);

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
    // The result of the query last ended, waiting for it.
    std::uint64_t result() const;
    // Whether that result is in, so that result() returns without waiting.
    bool available() const;
};

}  // namespace gnomon::gl
