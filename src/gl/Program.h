// Compiling and linking GLSL programs from embedded files. Failures throw gnomon::Error with
// the driver's log rewritten to name the .glsl file and line (see ShaderSource.h).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "gl/Objects.h"

namespace gnomon::gl {

struct Stage {
    GLenum type;       // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, ...
    std::string file;  // name under shaders/
};

Program buildProgram(const std::string& label, const std::vector<Stage>& stages,
                     const std::vector<std::string>& defines = {});

}  // namespace gnomon::gl
