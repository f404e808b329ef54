// Indexed triangle draws of a static command list. OpenGL 4.5 keeps the commands in an
// indirect buffer and draws a run of them with one glMultiDrawElementsIndirect, each
// command's base instance picking its record for the shaders (instanced attributes).
// Indices are global (no base vertex is used), so the commands also make sense where ES 3.0
// (WebGL2) has neither indirect draws nor base instances.
#pragma once

#include <cstddef>
#include <vector>

#include "gl/Objects.h"

namespace gnomon::gl {

// glMultiDrawElementsIndirect's record.
struct DrawCommand {
    GLuint count, instanceCount, firstIndex;
    GLint baseVertex;     // always 0: indices are global
    GLuint baseInstance;  // its record (OpenGL 4.5: render::GpuScene), ES: the object index
};

class DrawCommands {
public:
    // Takes `commands` (swapping it with the previous list) when it differs from what is
    // held; true when it did and the GPU's copy was replaced.
    bool assign(std::vector<DrawCommand>& commands);
    // Before draw(): the commands bound for indirect draws.
    void bind() const;
    // Commands [first, first + count), unsigned 32-bit indices, triangles.
    void draw(std::size_t first, std::size_t count) const;
    // Command `k` on its own (drawElements).
    void drawOne(std::size_t k) const;
    bool empty() const { return !mHeld; }

private:
    bool mHeld = false;
    Buffer mBuffer;  // OpenGL 4.5 only; ES draws from mData one command at a time
    std::vector<DrawCommand> mData;
};

// One command on its own (32-bit indices, triangles). On ES the object index goes to the
// program in use as uDrawBase (gl::kDrawBaseLocation).
void drawElements(const DrawCommand& command);

}  // namespace gnomon::gl
