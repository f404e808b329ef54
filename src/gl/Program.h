// Compiling and linking GLSL programs from embedded files, in the dialect of the context's
// capabilities (gl::activeCaps() when built); and using them. Failures throw gnomon::Error
// with the driver's log rewritten to name the .glsl file and line (see ShaderSource.h).
//
// Shaders give their uniforms fixed locations (`layout(location = N)`), and C++ sets them by
// those numbers: gl::use(program), then gl::uniform(N, value). On OpenGL 4.5 N is passed to
// GL as it is. GLSL ES has no uniform locations: the assembler removes them and the program
// maps each N to the location its link chose (-1 where that uniform is inactive, which GL
// ignores).
#pragma once

#include <glm/glm.hpp>
#include <span>
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

// glUseProgram, remembering the program's dialect and locations for gl::uniform.
void use(const Program& program);

// The uniform the program last given to gl::use (on this thread) declares at location
// `location`, set as glUniform* sets it.
void uniform(int location, int value);
void uniform(int location, float value);
void uniform(int location, glm::ivec2 value);
void uniform(int location, const glm::ivec4& value);
void uniform(int location, glm::vec2 value);
void uniform(int location, const glm::vec3& value);
void uniform(int location, const glm::vec4& value);
void uniform(int location, const glm::mat4& value);
// Arrays, from their first element: of ints, of mat4s, and of float (`components` 1) to vec4
// (4) values given component after component.
void uniform(int location, std::span<const int> values);
void uniform(int location, std::span<const glm::mat4> values);
void uniform(int location, std::span<const float> values, int components);

}  // namespace gnomon::gl
