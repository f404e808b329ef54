// gl::Texture: creation, parameters, clears and readback, on OpenGL 4.5 with direct state
// access and on ES 3.0 by binding the texture to edit it (Objects.h).
#include <algorithm>
#include <cstring>
#include <vector>

#include "gl/Caps.h"
#include "gl/Objects.h"
#include "gnomon/Error.h"

namespace gnomon::gl {
namespace {

bool dsa() {
    return activeCaps().directStateAccess;
}

[[noreturn]] void notOnEs(const std::string& what) {
    throw Error(ErrorKind::Gl, what + " is not available in OpenGL ES 3.0 / WebGL2");
}

void storage(GLuint n, GLenum target, int levels, GLenum format, int w, int h, int layers) {
    if (target == GL_TEXTURE_2D) {
        if (dsa()) {
            glTextureStorage2D(n, levels, format, w, h);
        } else {
            glTexStorage2D(target, levels, format, w, h);
        }
    } else if (dsa()) {
        glTextureStorage3D(n, levels, format, w, h, layers);
    } else {
        glTexStorage3D(target, levels, format, w, h, layers);
    }
}

// RGBA8 rows into level 0 of a bound (ES) or named (4.5) 2D texture.
void upload2D(GLuint n, int w, int h, const void* rgba) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (dsa()) {
        glTextureSubImage2D(n, 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

// ES: a framebuffer for one clear, the caller's draw framebuffer and depth mask kept.
template <typename Attach>
void clearThrough(Attach attach, GLenum buffer, const float* value) {
    GLint previous = 0;
    GLboolean depthMask = GL_TRUE;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
    GLuint fb = 0;
    glGenFramebuffers(1, &fb);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb);
    glDepthMask(GL_TRUE);
    attach();
    glClearBufferfv(buffer, 0, value);
    glDepthMask(depthMask);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(previous));
    glDeleteFramebuffers(1, &fb);
}

}  // namespace

GLuint Texture::create(GLenum target) {
    GLuint n = 0;
    if (dsa()) {
        glCreateTextures(target, 1, &n);
    } else {
        glGenTextures(1, &n);
        glBindTexture(target, n);  // ES makes the object at its first binding
    }
    return n;
}

Texture Texture::array2D(const std::string& label, GLenum internalFormat, int width, int height,
                         int layers) {
    Texture t(create(GL_TEXTURE_2D_ARRAY), GL_TEXTURE_2D_ARRAY, internalFormat, width, height,
              layers);
    storage(t.id(), GL_TEXTURE_2D_ARRAY, 1, internalFormat, width, height, layers);
    setLabel(GL_TEXTURE, t.id(), label);
    return t;
}

Texture Texture::cubeArray(const std::string& label, GLenum internalFormat, int size, int cubes) {
    // Without cube-map arrays: a 2D array, face f of cube c at layer 6c + f, as stored.
    const GLenum target =
        activeCaps().cubeMapArrays ? GL_TEXTURE_CUBE_MAP_ARRAY : GL_TEXTURE_2D_ARRAY;
    Texture t(create(target), target, internalFormat, size, size, 6 * cubes);
    storage(t.id(), target, 1, internalFormat, size, size, 6 * cubes);
    setLabel(GL_TEXTURE, t.id(), label);
    return t;
}

bool Texture::allocated() const {
    GLint immutable = GL_FALSE;
    if (id() == 0) return false;
    if (dsa()) {
        glGetTextureParameteriv(id(), GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
    } else {
        glBindTexture(mTarget, id());
        glGetTexParameteriv(mTarget, GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
    }
    return immutable == GL_TRUE;
}

void Texture::setParameter(GLenum parameter, GLint value) {
    if (dsa()) {
        glTextureParameteri(id(), parameter, value);
    } else {
        glBindTexture(mTarget, id());
        glTexParameteri(mTarget, parameter, value);
    }
}

void Texture::setDepthCompare() {
    setParameter(GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    setParameter(GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    setParameter(GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    setParameter(GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void Texture::read(int x, int y, int layer, int width, int height, GLenum format, GLenum type,
                   std::size_t bytes, void* out) const {
    if (activeCaps().textureReadback) {
        glGetTextureSubImage(id(), 0, x, y, layer, width, height, 1, format, type, GLsizei(bytes),
                             out);
        return;
    }
    // ES reads colour through a framebuffer, as RGBA (the one pair every driver must take
    // for normalised and float formats); the channels asked for are kept.
    const int channels = format == GL_RED ? 1 : format == GL_RG ? 2 : format == GL_RGBA ? 4 : 0;
    const std::size_t size = type == GL_FLOAT ? 4 : type == GL_UNSIGNED_BYTE ? 1 : 0;
    const std::size_t texels = std::size_t(width) * std::size_t(height);
    if (channels == 0 || size == 0) notOnEs("reading depth or this format back");
    if (bytes < texels * std::size_t(channels) * size) {
        throw Error(ErrorKind::Gl, "texture readback: the buffer is too small");
    }
    std::vector<unsigned char> rgba(texels * 4 * size);
    GLint previous = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous);
    GLuint fb = 0;
    glGenFramebuffers(1, &fb);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb);
    if (mTarget == GL_TEXTURE_2D) {
        glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, id(), 0);
    } else {
        glFramebufferTextureLayer(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, id(), 0, layer);
    }
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(x, y, width, height, GL_RGBA, type, rgba.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(previous));
    glDeleteFramebuffers(1, &fb);
    auto* to = static_cast<unsigned char*>(out);
    for (std::size_t t = 0; t < texels; ++t)
        std::memcpy(to + t * std::size_t(channels) * size, rgba.data() + t * 4 * size,
                    std::size_t(channels) * size);
}

void Texture::clear(GLenum format, const float* value) {
    if (activeCaps().clearTexture) {
        glClearTexImage(id(), 0, format, GL_FLOAT, value);
        return;
    }
    const bool depth = format == GL_DEPTH_COMPONENT;
    const GLenum attachment = depth ? GL_DEPTH_ATTACHMENT : GL_COLOR_ATTACHMENT0;
    // glClearBufferfv reads four values for colour: the given channels, then 0 0 0 1.
    const int given = format == GL_RED ? 1 : format == GL_RG ? 2 : format == GL_RGB ? 3 : 4;
    float rgba[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    for (int c = 0; c < (depth ? 1 : given); ++c)
        rgba[c] = value[c];
    for (int layer = 0; layer < std::max(mLayers, 1); ++layer) {
        clearThrough(
            [&] {
                if (mTarget == GL_TEXTURE_2D) {
                    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, attachment, GL_TEXTURE_2D, id(), 0);
                } else {
                    glFramebufferTextureLayer(GL_DRAW_FRAMEBUFFER, attachment, id(), 0, layer);
                }
            },
            depth ? GL_DEPTH : GL_COLOR, rgba);
    }
}

void Texture::clearCubeDepth(int cube, float depth) {
    if (!activeCaps().clearTexture) notOnEs("clearing part of a texture");
    glClearTexSubImage(id(), 0, 0, 0, 6 * cube, mWidth, mHeight, 6, GL_DEPTH_COMPONENT, GL_FLOAT,
                       &depth);
}

void Texture::clearUnsignedZero(int x, int y, int width, int height, int layer) {
    if (!activeCaps().clearTexture) notOnEs("clearing part of a texture");
    const GLuint zero[4] = {0, 0, 0, 0};
    glClearTexSubImage(id(), 0, x, y, layer, width, height, 1, GL_RGBA_INTEGER, GL_UNSIGNED_INT,
                       zero);
}

Texture Texture::layersView(const std::string& label, const Texture& source) {
    if (!activeCaps().textureViews) notOnEs("a texture view");
    GLuint n = 0;
    glGenTextures(1, &n);  // a view needs a name that has no texture object yet
    glTextureView(n, GL_TEXTURE_2D_ARRAY, source.id(), source.format(), 0, 1, 0,
                  GLuint(source.layers()));
    setLabel(GL_TEXTURE, n, label);
    return Texture(n, GL_TEXTURE_2D_ARRAY, source.format(), source.width(), source.height(),
                   source.layers());
}

Texture Texture::bufferView(const std::string& label, const Buffer& buffer, GLenum format) {
    if (!activeCaps().textureBuffers) notOnEs("a buffer texture");
    GLuint n = 0;
    glCreateTextures(GL_TEXTURE_BUFFER, 1, &n);
    glTextureBuffer(n, format, buffer.id());
    setLabel(GL_TEXTURE, n, label);
    return Texture(n, GL_TEXTURE_BUFFER, format, 0, 0, 0);
}

Texture Texture::view2D(const std::string& label, const Texture& source, GLenum viewFormat) {
    if (!activeCaps().textureViews) notOnEs("a texture view");
    GLuint n = 0;
    glGenTextures(1, &n);  // a view needs a name that has no texture object yet
    glTextureView(n, GL_TEXTURE_2D, source.id(), viewFormat, 0, 1, 0, 1);
    setLabel(GL_TEXTURE, n, label);
    Texture t(n, GL_TEXTURE_2D, viewFormat, source.width(), source.height(), 1);
    t.setParameter(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    t.setParameter(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}

Texture Texture::plain2D(const std::string& label, GLenum internalFormat, int width, int height) {
    Texture t(create(GL_TEXTURE_2D), GL_TEXTURE_2D, internalFormat, width, height, 1);
    storage(t.id(), GL_TEXTURE_2D, 1, internalFormat, width, height, 1);
    setLabel(GL_TEXTURE, t.id(), label);
    return t;
}

Texture Texture::image2D(const std::string& label, int width, int height, const void* rgba,
                         GLint wrapS, GLint wrapT, bool nearest) {
    int levels = 1;
    while ((std::max(width, height) >> levels) > 0)
        ++levels;
    Texture t(create(GL_TEXTURE_2D), GL_TEXTURE_2D, GL_SRGB8_ALPHA8, width, height, 1);
    storage(t.id(), GL_TEXTURE_2D, levels, GL_SRGB8_ALPHA8, width, height, 1);
    upload2D(t.id(), width, height, rgba);
    if (dsa()) {
        glGenerateTextureMipmap(t.id());
    } else {
        glGenerateMipmap(GL_TEXTURE_2D);
    }
    t.setParameter(GL_TEXTURE_WRAP_S, wrapS);
    t.setParameter(GL_TEXTURE_WRAP_T, wrapT);
    t.setParameter(GL_TEXTURE_MIN_FILTER,
                   nearest ? GL_NEAREST_MIPMAP_NEAREST : GL_LINEAR_MIPMAP_LINEAR);
    t.setParameter(GL_TEXTURE_MAG_FILTER, nearest ? GL_NEAREST : GL_LINEAR);
    setLabel(GL_TEXTURE, t.id(), label);
    return t;
}

Texture Texture::display2D(const std::string& label, const Image& image) {
    Image rgba(image.width, image.height, 4);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* in = image.at(x, y);
            std::uint8_t* out = rgba.at(x, y);
            for (int c = 0; c < 3; ++c)
                out[c] = in[std::min(c, image.channels - 1)];
            out[3] = image.channels == 4 ? in[3] : 255;
        }
    }
    Texture t(create(GL_TEXTURE_2D), GL_TEXTURE_2D, GL_RGBA8, image.width, image.height, 1);
    storage(t.id(), GL_TEXTURE_2D, 1, GL_RGBA8, image.width, image.height, 1);
    upload2D(t.id(), image.width, image.height, rgba.pixels.data());
    t.setParameter(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    t.setParameter(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    setLabel(GL_TEXTURE, t.id(), label);
    return t;
}

Texture Texture::texelRows(const std::string& label, const float* rgba, std::size_t texels,
                           int rowTexels) {
    const int rows = int(
        std::max<std::size_t>(1, (texels + std::size_t(rowTexels) - 1) / std::size_t(rowTexels)));
    std::vector<float> padded(std::size_t(rowTexels) * std::size_t(rows) * 4, 0.0f);
    if (texels > 0) std::memcpy(padded.data(), rgba, texels * 4 * sizeof(float));
    Texture t(create(GL_TEXTURE_2D), GL_TEXTURE_2D, GL_RGBA32F, rowTexels, rows, 1);
    storage(t.id(), GL_TEXTURE_2D, 1, GL_RGBA32F, rowTexels, rows, 1);
    if (dsa()) {
        glTextureSubImage2D(t.id(), 0, 0, 0, rowTexels, rows, GL_RGBA, GL_FLOAT, padded.data());
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, rowTexels, rows, GL_RGBA, GL_FLOAT, padded.data());
    }
    t.setParameter(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    t.setParameter(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    setLabel(GL_TEXTURE, t.id(), label);
    return t;
}

void Texture::writeTexelRows(const float* rgba, std::size_t texels) {
    const std::size_t w = std::size_t(mWidth), full = texels / w, rest = texels % w;
    auto write = [&](int y, std::size_t width, std::size_t rows, const float* from) {
        if (width == 0 || rows == 0) return;
        if (dsa()) {
            glTextureSubImage2D(id(), 0, 0, y, GLsizei(width), GLsizei(rows), GL_RGBA, GL_FLOAT,
                                from);
        } else {
            glBindTexture(GL_TEXTURE_2D, id());
            glTexSubImage2D(GL_TEXTURE_2D, 0, 0, y, GLsizei(width), GLsizei(rows), GL_RGBA,
                            GL_FLOAT, from);
        }
    };
    write(0, w, full, rgba);
    write(int(full), rest, 1, rgba + full * w * 4);
}

Texture Texture::integers2D(const std::string& label, const std::int32_t* rgba, int width,
                            int height) {
    Texture t(create(GL_TEXTURE_2D), GL_TEXTURE_2D, GL_RGBA32I, width, height, 1);
    storage(t.id(), GL_TEXTURE_2D, 1, GL_RGBA32I, width, height, 1);
    t.writeIntegers2D(rgba);
    t.setParameter(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    t.setParameter(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    setLabel(GL_TEXTURE, t.id(), label);
    return t;
}

void Texture::writeIntegers2D(const std::int32_t* rgba) {
    if (dsa()) {
        glTextureSubImage2D(id(), 0, 0, 0, mWidth, mHeight, GL_RGBA_INTEGER, GL_INT, rgba);
    } else {
        glBindTexture(GL_TEXTURE_2D, id());
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, mWidth, mHeight, GL_RGBA_INTEGER, GL_INT, rgba);
    }
}

void bindTexture(int unit, const Texture& texture) {
    if (dsa()) {
        glBindTextureUnit(GLuint(unit), texture.id());
        return;
    }
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    if (texture) {
        glBindTexture(texture.target(), texture.id());
    } else {
        for (GLenum target :
             {GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP})
            glBindTexture(target, 0);
    }
}

void bindTexture2D(int unit, GLuint texture) {
    if (dsa()) {
        glBindTextureUnit(GLuint(unit), texture);
        return;
    }
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, texture);
}

}  // namespace gnomon::gl
