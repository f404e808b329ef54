#include "gl/Program.h"

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

}  // namespace

Program buildProgram(const std::string& label, const std::vector<Stage>& stages,
                     const std::vector<std::string>& defines) {
    Program program(glCreateProgram());
    setLabel(GL_PROGRAM, program.id(), label);
    std::vector<Object<ShaderDeleter>> shaders;
    for (const Stage& stage : stages) {
        const AssembledSource source = assembleShader(stage.file, defines);
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
    return program;
}

}  // namespace gnomon::gl
