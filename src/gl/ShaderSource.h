// Shader sources embedded into the binary at build time (cmake/EmbedFiles.cmake turns each
// shaders/*.glsl into a byte array), and their assembly: `#include "file.glsl"` expansion and
// #defines injected after #version, so one file serves every variant. Each assembled line
// remembers its file and line: drivers disagree on #line source numbers (Mesa ignores them
// in compiler messages), so error logs are mapped back by assembled line number instead.
//
// Two dialects. Gl45: the files as they are (GLSL 4.50 core). Gles3 (WebGL2, GLSL ES 3.00):
// `#version 300 es`, injected lines (GNOMON_GLES, precisions, the multi-draw extension) and
// line-for-line rewrites of what ES lacks: uniforms lose their `layout(location = N)`,
// samplers their `layout(binding = N)` and uniform blocks their binding (all recorded, for the
// program to set after linking), and in/out interface blocks become plain varyings named
// Block_member. What else differs is written in the shaders behind GNOMON_GLES.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "gl/Caps.h"

namespace gnomon::gl {

// The embedded text of shaders/<name>; throws gnomon::Error when there is no such file.
std::string_view embeddedShader(const std::string& name);
// Every embedded file's name, in the build's order.
std::vector<std::string> embeddedShaderNames();

// GLSL ES's object records (scene_data.glsl): WebGL2 has no buffer textures, so the records
// are rows of an RGBA32F 2D texture, kObjectsPerRow records (of render::kObjectTexels texels)
// to a row.
inline constexpr int kObjectsPerRow = 64;
// GLSL ES's uniform `uDrawBase` (scene_data.glsl): the first drawn item's object record.
inline constexpr int kDrawBaseLocation = 14;
// Fixed uniform locations a program may declare: 0 to kFixedLocations - 1.
inline constexpr int kFixedLocations = 24;

struct Dialect {
    Api api = Api::Gl45;
    // Gles3: multi-draws number their draws in gl_DrawID (GL_ANGLE_multi_draw, WebGL's
    // WEBGL_multi_draw), which vertex shaders add to uDrawBase.
    bool multiDraw = false;
};
// The dialect of a context with these capabilities.
Dialect dialectOf(const Caps& caps);

struct SourceLine {
    // Lines gnomon inserted have no line of their own: kInjectedDefine for the caller's
    // #defines, kInjectedDialect for the Gles3 dialect's lines.
    static constexpr int kInjectedDefine = 0;
    static constexpr int kInjectedDialect = -1;
    int file = 0;  // index into AssembledSource::files
    int line = 0;  // 1-based line in that file, or one of the two above
};

// What a Gles3 rewrite removed: a uniform's location, a sampler's texture unit or a uniform
// block's binding point, and the uniform, sampler or block it belonged to.
struct FixedSlot {
    int slot = 0;
    std::string name;
    bool operator==(const FixedSlot&) const = default;
};

struct AssembledSource {
    std::string text;                // ready for glShaderSource
    std::vector<std::string> files;  // every file that went in, the root first
    std::vector<SourceLine> lines;   // assembled line n (1-based) is lines[n - 1]
    // Gles3 only, in the order of the text (declarations in #if branches that the
    // preprocessor drops are listed too: a program resolves them after linking).
    std::vector<FixedSlot> locations;  // layout(location = N) uniform T name
    std::vector<FixedSlot> samplers;   // layout(binding = N) uniform sampler... name
    std::vector<FixedSlot> blocks;     // layout(std140, binding = N) uniform Name { ... }
};

// Expands includes (each file once) and inserts `#define` lines after `#version`, in
// `dialect`. Vertex shaders are the files named *.vert.glsl. Throws gnomon::Error when a
// Gles3 rewrite meets a declaration it cannot rewrite.
AssembledSource assembleShader(const std::string& file, const std::vector<std::string>& defines,
                               const Dialect& dialect = {});

// Rewrites a driver info log so "N:LINE(COL)" (Mesa), "N(LINE)" (NVIDIA) and
// "ERROR: N:LINE:" (ANGLE, as Chrome reports WebGL's errors) references, whose LINE counts
// lines of the assembled text, name the .glsl file and its own line.
std::string annotateInfoLog(const std::string& log, const AssembledSource& source);

}  // namespace gnomon::gl
