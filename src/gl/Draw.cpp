#include "gl/Draw.h"

#include <algorithm>
#include <cstring>

namespace gnomon::gl {

bool DrawCommands::assign(std::vector<DrawCommand>& commands) {
    if (mBuffer && commands.size() == mData.size() &&
        std::memcmp(commands.data(), mData.data(), mData.size() * sizeof(DrawCommand)) == 0) {
        return false;
    }
    mData.swap(commands);
    mBuffer = Buffer("draw commands", std::max<std::size_t>(mData.size(), 1) * sizeof(DrawCommand),
                     mData.empty() ? nullptr : mData.data(), 0);
    return true;
}

void DrawCommands::bind() const {
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, mBuffer.id());
}

void DrawCommands::draw(std::size_t first, std::size_t count) const {
    glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT,
                                reinterpret_cast<const void*>(first * sizeof(DrawCommand)),
                                GLsizei(count), 0);
}

void drawElements(const DrawCommand& c) {
    glDrawElementsInstancedBaseVertexBaseInstance(
        GL_TRIANGLES, GLsizei(c.count), GL_UNSIGNED_INT,
        reinterpret_cast<const void*>(std::size_t(c.firstIndex) * sizeof(GLuint)),
        GLsizei(c.instanceCount), c.baseVertex, c.baseInstance);
}

}  // namespace gnomon::gl
