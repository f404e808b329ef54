// Shader sources embedded into the binary at build time (cmake/EmbedFiles.cmake turns each
// shaders/*.glsl into a byte array), and their assembly: `#include "file.glsl"` expansion with
// #line markers, and #defines injected after #version, so one file serves every variant.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace gnomon::gl {

// The embedded text of shaders/<name>; throws gnomon::Error when there is no such file.
std::string_view embeddedShader(const std::string& name);

struct AssembledSource {
    std::string text;                // ready for glShaderSource
    std::vector<std::string> files;  // #line source-string number -> file name
};

// Expands includes (each file once) and inserts `#define` lines after `#version`.
AssembledSource assembleShader(const std::string& file, const std::vector<std::string>& defines);

// Rewrites a driver info log so "N:LINE(COL)" / "N(LINE)" references name the file.
std::string annotateInfoLog(const std::string& log, const std::vector<std::string>& files);

}  // namespace gnomon::gl
