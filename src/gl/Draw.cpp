#include "gl/Draw.h"

#include <algorithm>
#include <cstring>

#include "gl/Caps.h"
#include "gl/Program.h"
#include "gl/ShaderSource.h"

namespace gnomon::gl {

bool DrawCommands::assign(std::vector<DrawCommand>& commands) {
    if (mHeld && commands.size() == mData.size() &&
        std::memcmp(commands.data(), mData.data(), mData.size() * sizeof(DrawCommand)) == 0) {
        return false;
    }
    mData.swap(commands);
    mHeld = true;
    if (activeCaps().drawIndirect) {
        mBuffer =
            Buffer("draw commands", std::max<std::size_t>(mData.size(), 1) * sizeof(DrawCommand),
                   mData.empty() ? nullptr : mData.data(), 0);
    }
    return true;
}

void DrawCommands::bind() const {
    if (activeCaps().drawIndirect) glBindBuffer(GL_DRAW_INDIRECT_BUFFER, mBuffer.id());
}

void DrawCommands::draw(std::size_t first, std::size_t count) const {
    if (activeCaps().drawIndirect) {
        glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT,
                                    reinterpret_cast<const void*>(first * sizeof(DrawCommand)),
                                    GLsizei(count), 0);
        return;
    }
    for (std::size_t k = first; k < first + count; ++k)
        drawElements(mData[k]);
}

void DrawCommands::drawOne(std::size_t k) const {
    drawElements(mData[k]);
}

void drawElements(const DrawCommand& c) {
    if (c.count == 0) return;
    const void* offset = reinterpret_cast<const void*>(std::size_t(c.firstIndex) * sizeof(GLuint));
    if (activeCaps().drawIndirect) {
        glDrawElementsInstancedBaseVertexBaseInstance(
            GL_TRIANGLES, GLsizei(c.count), GL_UNSIGNED_INT, offset, GLsizei(c.instanceCount),
            c.baseVertex, c.baseInstance);
        return;
    }
    // ES: no base instance; the object index is a uniform of the program in use.
    uniform(kDrawBaseLocation, int(c.baseInstance));
    glDrawElementsInstanced(GL_TRIANGLES, GLsizei(c.count), GL_UNSIGNED_INT, offset,
                            GLsizei(c.instanceCount));
}

}  // namespace gnomon::gl
