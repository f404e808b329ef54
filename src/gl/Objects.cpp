#include "gl/Objects.h"

#include <algorithm>

#include "gl/Caps.h"
#include "gnomon/Error.h"

namespace gnomon::gl {
namespace {
bool dsa() {
    return activeCaps().directStateAccess;
}
}  // namespace

void setLabel(GLenum identifier, GLuint name, const std::string& label) {
    if (!label.empty() && activeCaps().debugLabels) {
        glObjectLabel(identifier, name, GLsizei(label.size()), label.c_str());
    }
}

Buffer::Buffer(const std::string& label, std::size_t bytes, const void* data, GLbitfield flags,
               Use use) {
    GLuint n = 0;
    mSize = bytes;
    mEditTarget = use == Use::Indices ? GL_ELEMENT_ARRAY_BUFFER : GL_ARRAY_BUFFER;
    // Zero-size storage is an error in GL; keep one byte so empty scenes stay valid.
    const GLsizeiptr stored = GLsizeiptr(bytes > 0 ? bytes : 1);
    if (dsa()) {
        glCreateBuffers(1, &n);
        static_cast<Object&>(*this) = Object(n);
        glNamedBufferStorage(n, stored, bytes > 0 ? data : nullptr, flags);
    } else {
        glGenBuffers(1, &n);
        static_cast<Object&>(*this) = Object(n);
        // An element buffer binds to the bound vertex array: bind none first.
        if (use == Use::Indices) glBindVertexArray(0);
        glBindBuffer(mEditTarget, n);
        glBufferData(mEditTarget, stored, bytes > 0 ? data : nullptr,
                     (flags & GL_DYNAMIC_STORAGE_BIT) ? GL_DYNAMIC_DRAW : GL_STATIC_DRAW);
    }
    setLabel(GL_BUFFER, n, label);
}

void Buffer::update(std::size_t offset, std::size_t bytes, const void* data) {
    if (bytes == 0) return;
    if (dsa()) {
        glNamedBufferSubData(id(), GLintptr(offset), GLsizeiptr(bytes), data);
        return;
    }
    if (mEditTarget == GL_ELEMENT_ARRAY_BUFFER) glBindVertexArray(0);
    glBindBuffer(mEditTarget, id());
    glBufferSubData(mEditTarget, GLintptr(offset), GLsizeiptr(bytes), data);
}

VertexArray::VertexArray(const std::string& label) {
    GLuint n = 0;
    if (dsa()) {
        glCreateVertexArrays(1, &n);
    } else {
        glGenVertexArrays(1, &n);
        glBindVertexArray(n);  // ES makes the object at its first binding
    }
    static_cast<Object&>(*this) = Object(n);
    setLabel(GL_VERTEX_ARRAY, n, label);
}

void VertexArray::vertexBuffer(int binding, const Buffer& buffer, std::size_t offset, int stride) {
    if (dsa()) {
        glVertexArrayVertexBuffer(id(), GLuint(binding), buffer.id(), GLintptr(offset), stride);
        return;
    }
    mBindings[binding].buffer = buffer.id();
    mBindings[binding].offset = offset;
    mBindings[binding].stride = stride;
    for (int a = 0; a < 8; ++a) {
        if (mAttributes[a].used && mAttributes[a].binding == binding) specify(a);
    }
}

void VertexArray::attribute(int index, int binding, int components, GLenum type,
                            std::size_t offset) {
    if (dsa()) {
        glEnableVertexArrayAttrib(id(), GLuint(index));
        glVertexArrayAttribFormat(id(), GLuint(index), components, type, GL_FALSE, GLuint(offset));
        glVertexArrayAttribBinding(id(), GLuint(index), GLuint(binding));
        return;
    }
    mAttributes[index] = {true, false, binding, components, type, offset};
    specify(index);
}

void VertexArray::integerAttribute(int index, int binding, int components, GLenum type,
                                   std::size_t offset) {
    if (dsa()) {
        glEnableVertexArrayAttrib(id(), GLuint(index));
        glVertexArrayAttribIFormat(id(), GLuint(index), components, type, GLuint(offset));
        glVertexArrayAttribBinding(id(), GLuint(index), GLuint(binding));
        return;
    }
    mAttributes[index] = {true, true, binding, components, type, offset};
    specify(index);
}

void VertexArray::divisor(int binding, int divisor) {
    if (dsa()) {
        glVertexArrayBindingDivisor(id(), GLuint(binding), GLuint(divisor));
        return;
    }
    mBindings[binding].divisor = divisor;
    for (int a = 0; a < 8; ++a) {
        if (mAttributes[a].used && mAttributes[a].binding == binding) specify(a);
    }
}

void VertexArray::elements(const Buffer& indices) {
    if (dsa()) {
        glVertexArrayElementBuffer(id(), indices.id());
        return;
    }
    glBindVertexArray(id());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices.id());
}

void VertexArray::specify(int index) {
    const Attribute& a = mAttributes[index];
    const Binding& b = mBindings[a.binding];
    if (b.buffer == 0) return;  // specified when its buffer arrives
    glBindVertexArray(id());
    glBindBuffer(GL_ARRAY_BUFFER, b.buffer);
    glEnableVertexAttribArray(GLuint(index));
    const void* at = reinterpret_cast<const void*>(b.offset + a.offset);
    if (a.integer) {
        glVertexAttribIPointer(GLuint(index), a.components, a.type, b.stride, at);
    } else {
        glVertexAttribPointer(GLuint(index), a.components, a.type, GL_FALSE, b.stride, at);
    }
    glVertexAttribDivisor(GLuint(index), GLuint(b.divisor));
}

Sampler::Sampler(const std::string& label) {
    GLuint n = 0;
    if (dsa()) {
        glCreateSamplers(1, &n);
    } else {
        glGenSamplers(1, &n);
    }
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

Query::Query(const std::string& label, GLenum target) {
    GLuint n = 0;
    if (dsa()) {
        glCreateQueries(target, 1, &n);
    } else {
        glGenQueries(1, &n);  // made at its first glBeginQuery
    }
    static_cast<Object&>(*this) = Object(n);
    if (n != 0) setLabel(GL_QUERY, n, label);  // 0: the driver refused the target
}

bool Query::available() const {
    GLuint ready = GL_FALSE;
    glGetQueryObjectuiv(id(), GL_QUERY_RESULT_AVAILABLE, &ready);
    return ready == GL_TRUE;
}

std::uint64_t Query::result() const {
    if (dsa()) {
        GLint64 value = 0;
        glGetQueryObjecti64v(id(), GL_QUERY_RESULT, &value);
        return std::uint64_t(value);
    }
    GLuint value = 0;  // ES 3.0 has 32-bit results only
    glGetQueryObjectuiv(id(), GL_QUERY_RESULT, &value);
    return value;
}

}  // namespace gnomon::gl
