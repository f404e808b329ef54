#include "gl/Objects.h"

#include <algorithm>

#include "gl/Caps.h"
#include "gnomon/Error.h"

namespace gnomon::gl {

void setLabel(GLenum identifier, GLuint name, const std::string& label) {
    if (!label.empty() && activeCaps().debugLabels) {
        glObjectLabel(identifier, name, GLsizei(label.size()), label.c_str());
    }
}

Buffer::Buffer(const std::string& label, std::size_t bytes, const void* data, GLbitfield flags) {
    GLuint n = 0;
    glCreateBuffers(1, &n);
    static_cast<Object&>(*this) = Object(n);
    mSize = bytes;
    // Zero-size storage is an error in GL; keep one byte so empty scenes stay valid.
    glNamedBufferStorage(n, GLsizeiptr(bytes > 0 ? bytes : 1), bytes > 0 ? data : nullptr, flags);
    setLabel(GL_BUFFER, n, label);
}

void Buffer::update(std::size_t offset, std::size_t bytes, const void* data) {
    if (bytes > 0) glNamedBufferSubData(id(), GLintptr(offset), GLsizeiptr(bytes), data);
}

VertexArray::VertexArray(const std::string& label) {
    GLuint n = 0;
    glCreateVertexArrays(1, &n);
    static_cast<Object&>(*this) = Object(n);
    setLabel(GL_VERTEX_ARRAY, n, label);
}

Texture Texture::array2D(const std::string& label, GLenum internalFormat, int width, int height,
                         int layers) {
    GLuint n = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &n);
    glTextureStorage3D(n, 1, internalFormat, width, height, layers);
    setLabel(GL_TEXTURE, n, label);
    return Texture(n, internalFormat, width, height, layers);
}

bool Texture::allocated() const {
    GLint immutable = GL_FALSE;
    if (id() != 0) glGetTextureParameteriv(id(), GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
    return immutable == GL_TRUE;
}

Texture Texture::cubeArray(const std::string& label, GLenum internalFormat, int size, int cubes) {
    GLuint n = 0;
    glCreateTextures(GL_TEXTURE_CUBE_MAP_ARRAY, 1, &n);
    glTextureStorage3D(n, 1, internalFormat, size, size, 6 * cubes);
    setLabel(GL_TEXTURE, n, label);
    return Texture(n, internalFormat, size, size, 6 * cubes);
}

Texture Texture::layersView(const std::string& label, const Texture& source) {
    GLuint n = 0;
    glGenTextures(1, &n);  // a view needs a name that has no texture object yet
    glTextureView(n, GL_TEXTURE_2D_ARRAY, source.id(), source.format(), 0, 1, 0,
                  GLuint(source.layers()));
    setLabel(GL_TEXTURE, n, label);
    return Texture(n, source.format(), source.width(), source.height(), source.layers());
}

Texture Texture::bufferView(const std::string& label, const Buffer& buffer, GLenum format) {
    GLuint n = 0;
    glCreateTextures(GL_TEXTURE_BUFFER, 1, &n);
    glTextureBuffer(n, format, buffer.id());
    setLabel(GL_TEXTURE, n, label);
    return Texture(n, format, 0, 0, 0);
}

Texture Texture::view2D(const std::string& label, const Texture& source, GLenum viewFormat) {
    GLuint n = 0;
    glGenTextures(1, &n);  // a view needs a name that has no texture object yet
    glTextureView(n, GL_TEXTURE_2D, source.id(), viewFormat, 0, 1, 0, 1);
    setLabel(GL_TEXTURE, n, label);
    glTextureParameteri(n, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(n, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return Texture(n, viewFormat, source.width(), source.height(), 1);
}

Texture Texture::plain2D(const std::string& label, GLenum internalFormat, int width, int height) {
    GLuint n = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &n);
    glTextureStorage2D(n, 1, internalFormat, width, height);
    setLabel(GL_TEXTURE, n, label);
    return Texture(n, internalFormat, width, height, 1);
}

Texture Texture::image2D(const std::string& label, int width, int height, const void* rgba,
                         GLint wrapS, GLint wrapT, bool nearest) {
    int levels = 1;
    while ((std::max(width, height) >> levels) > 0)
        ++levels;
    GLuint n = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &n);
    Texture t(n, GL_SRGB8_ALPHA8, width, height, 1);  // owns n from here on
    glTextureStorage2D(n, levels, GL_SRGB8_ALPHA8, width, height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(n, 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glGenerateTextureMipmap(n);
    glTextureParameteri(n, GL_TEXTURE_WRAP_S, wrapS);
    glTextureParameteri(n, GL_TEXTURE_WRAP_T, wrapT);
    glTextureParameteri(n, GL_TEXTURE_MIN_FILTER,
                        nearest ? GL_NEAREST_MIPMAP_NEAREST : GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(n, GL_TEXTURE_MAG_FILTER, nearest ? GL_NEAREST : GL_LINEAR);
    setLabel(GL_TEXTURE, n, label);
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
    GLuint n = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &n);
    Texture t(n, GL_RGBA8, image.width, image.height, 1);  // owns n from here on
    glTextureStorage2D(n, 1, GL_RGBA8, image.width, image.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(n, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        rgba.pixels.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureParameteri(n, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(n, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    setLabel(GL_TEXTURE, n, label);
    return t;
}

Sampler::Sampler(const std::string& label) {
    GLuint n = 0;
    glCreateSamplers(1, &n);
    static_cast<Object&>(*this) = Object(n);
    setLabel(GL_SAMPLER, n, label);
}

Sampler Sampler::clamped(const std::string& label, GLint filter) {
    Sampler s(label);
    s.set(GL_TEXTURE_MIN_FILTER, filter)
        .set(GL_TEXTURE_MAG_FILTER, filter)
        .set(GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE)
        .set(GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE)
        .set(GL_TEXTURE_COMPARE_MODE, GL_NONE);
    return s;
}

Sampler& Sampler::set(GLenum parameter, GLint value) {
    glSamplerParameteri(id(), parameter, value);
    return *this;
}

Sampler& Sampler::setBorder(float r, float g, float b, float a) {
    const float colour[4] = {r, g, b, a};
    glSamplerParameterfv(id(), GL_TEXTURE_BORDER_COLOR, colour);
    return *this;
}

Framebuffer::Framebuffer(const std::string& label) : mLabel(label) {
    GLuint n = 0;
    glCreateFramebuffers(1, &n);
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
    const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        throw Error(ErrorKind::Gl, "framebuffer '" + mLabel +
                                       "' is not complete: " + framebufferStatusText(status));
    }
}

Query::Query(const std::string& label, GLenum target) {
    GLuint n = 0;
    glCreateQueries(target, 1, &n);
    static_cast<Object&>(*this) = Object(n);
    if (n != 0) setLabel(GL_QUERY, n, label);  // 0: the driver refused the target
}

}  // namespace gnomon::gl
