// Shader sources embedded into the binary at build time (cmake/EmbedFiles.cmake turns each
// shaders/*.glsl into a byte array), and their assembly: `#include "file.glsl"` expansion and
// #defines injected after #version, so one file serves every variant. Each assembled line
// remembers its file and line: drivers disagree on #line source numbers (Mesa ignores them
// in compiler messages), so error logs are mapped back by assembled line number instead.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace gnomon::gl {

// The embedded text of shaders/<name>; throws gnomon::Error when there is no such file.
std::string_view embeddedShader(const std::string& name);

struct SourceLine {
    int file = 0;  // index into AssembledSource::files
    int line = 0;  // 1-based line in that file; 0 for lines gnomon inserted (#defines)
};

struct AssembledSource {
    std::string text;                // ready for glShaderSource
    std::vector<std::string> files;  // every file that went in, the root first
    std::vector<SourceLine> lines;   // assembled line n (1-based) is lines[n - 1]
};

// Expands includes (each file once) and inserts `#define` lines after `#version`.
AssembledSource assembleShader(const std::string& file, const std::vector<std::string>& defines);

// Rewrites a driver info log so "N:LINE(COL)" (Mesa) and "N(LINE)" (NVIDIA) references,
// whose LINE counts lines of the assembled text, name the .glsl file and its own line.
std::string annotateInfoLog(const std::string& log, const AssembledSource& source);

}  // namespace gnomon::gl
