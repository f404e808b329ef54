#include "gl/Program.h"

#include <algorithm>
#include <map>
#include <set>

#include "gl/ShaderSource.h"
#include "gnomon/Error.h"

namespace gnomon::gl {
namespace {

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log.c_str();
}

std::string programLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    return log.c_str();
}

// GLSL ES after linking: the uniforms' locations in the program's table, the samplers' texture
// units and the blocks' binding points, as the shaders' layouts (removed by the assembler)
// gave them. A location may name uniforms of exclusive #if branches: the active one counts.
void bindFixedSlots(Program& program, const std::string& label,
                    const std::vector<AssembledSource>& sources) {
    std::map<int, std::set<std::string>> atLocation;
    std::set<std::pair<int, std::string>> samplers, blocks;
    for (const AssembledSource& s : sources) {
        for (const FixedSlot& f : s.locations)
            atLocation[f.slot].insert(f.name);
        for (const FixedSlot& f : s.samplers)
            samplers.insert({f.slot, f.name});
        for (const FixedSlot& f : s.blocks)
            blocks.insert({f.slot, f.name});
    }
    std::map<std::string, int> activeAt;
    for (const auto& [fixed, names] : atLocation) {
        for (const std::string& name : names) {
            const GLint location = glGetUniformLocation(program.id(), name.c_str());
            if (location < 0) continue;
            if (program.location(fixed) >= 0 || activeAt.count(name) > 0) {
                throw Error(ErrorKind::Gl, "program '" + label + "': uniform " + name +
                                               " shares its location with another active one");
            }
            program.setLocation(fixed, location);
            activeAt[name] = fixed;
        }
    }
    GLint previous = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &previous);
    glUseProgram(program.id());
    for (const auto& [unit, name] : samplers) {
        const GLint location = glGetUniformLocation(program.id(), name.c_str());
        if (location >= 0) glUniform1i(location, unit);
    }
    glUseProgram(GLuint(previous));
    for (const auto& [binding, name] : blocks) {
        const GLuint index = glGetUniformBlockIndex(program.id(), name.c_str());
        if (index != GL_INVALID_INDEX) glUniformBlockBinding(program.id(), index, GLuint(binding));
    }
}

// The program gl::use made current on this thread, as gl::uniform needs it: its dialect and,
// for GLSL ES, a copy of its location table (a copy: a program may be destroyed while current).
struct Current {
    Api api = Api::Gl45;
    std::array<GLint, kFixedLocations> locations{};
};
thread_local Current tCurrent;

GLint at(int fixed) {
    if (tCurrent.api == Api::Gl45) return fixed;
    return fixed >= 0 && fixed < kFixedLocations ? tCurrent.locations[std::size_t(fixed)] : -1;
}

}  // namespace

Program buildProgram(const std::string& label, const std::vector<Stage>& stages,
                     const std::vector<std::string>& defines) {
    const Dialect dialect = dialectOf(activeCaps());
    Program program(glCreateProgram(), dialect.api);
    setLabel(GL_PROGRAM, program.id(), label);
    std::vector<Object<ShaderDeleter>> shaders;
    std::vector<AssembledSource> sources;
    for (const Stage& stage : stages) {
        const AssembledSource& source =
            sources.emplace_back(assembleShader(stage.file, defines, dialect));
        Object<ShaderDeleter> shader(glCreateShader(stage.type));
        const char* text = source.text.c_str();
        glShaderSource(shader.id(), 1, &text, nullptr);
        glCompileShader(shader.id());
        GLint ok = GL_FALSE;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (ok != GL_TRUE) {
            throw Error(ErrorKind::Gl, "shader " + stage.file + " (program '" + label +
                                           "') failed to compile:\n" +
                                           annotateInfoLog(shaderLog(shader.id()), source));
        }
        glAttachShader(program.id(), shader.id());
        shaders.push_back(std::move(shader));
    }
    glLinkProgram(program.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        throw Error(ErrorKind::Gl,
                    "program '" + label + "' failed to link:\n" + programLog(program.id()));
    }
    for (const auto& shader : shaders)
        glDetachShader(program.id(), shader.id());
    if (dialect.api == Api::Gles3) bindFixedSlots(program, label, sources);
    return program;
}

void use(const Program& program) {
    glUseProgram(program.id());
    tCurrent.api = program.api();
    if (program.api() == Api::Gles3) tCurrent.locations = program.locations();
}

void uniform(int location, int value) {
    glUniform1i(at(location), value);
}
void uniform(int location, float value) {
    glUniform1f(at(location), value);
}
void uniform(int location, glm::ivec2 value) {
    glUniform2iv(at(location), 1, &value[0]);
}
void uniform(int location, const glm::ivec4& value) {
    glUniform4iv(at(location), 1, &value[0]);
}
void uniform(int location, glm::vec2 value) {
    glUniform2fv(at(location), 1, &value[0]);
}
void uniform(int location, const glm::vec3& value) {
    glUniform3fv(at(location), 1, &value[0]);
}
void uniform(int location, const glm::vec4& value) {
    glUniform4fv(at(location), 1, &value[0]);
}
void uniform(int location, const glm::mat4& value) {
    glUniformMatrix4fv(at(location), 1, GL_FALSE, &value[0][0]);
}
void uniform(int location, std::span<const int> values) {
    glUniform1iv(at(location), GLsizei(values.size()), values.data());
}
void uniform(int location, std::span<const glm::mat4> values) {
    glUniformMatrix4fv(at(location), GLsizei(values.size()), GL_FALSE,
                       values.empty() ? nullptr : &values[0][0][0]);
}
void uniform(int location, std::span<const float> values, int components) {
    const GLsizei count = GLsizei(values.size()) / components;
    switch (components) {
        case 1:
            glUniform1fv(at(location), count, values.data());
            break;
        case 2:
            glUniform2fv(at(location), count, values.data());
            break;
        case 3:
            glUniform3fv(at(location), count, values.data());
            break;
        case 4:
            glUniform4fv(at(location), count, values.data());
            break;
        default:
            throw Error(ErrorKind::Gl, "gl::uniform: array elements have 1 to 4 components");
    }
}

}  // namespace gnomon::gl
