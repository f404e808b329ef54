// The shader assembler's GLSL ES dialect, as text (no GL): the rewrites keep the 4.5 files'
// lines one for one, record every uniform location, sampler unit and block binding they
// remove, flatten the interface blocks, and error logs name the injected lines as such.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <sstream>

#include "gl/ShaderSource.h"

namespace gnomon::test {
namespace {

const gl::Dialect kGles{gl::Api::Gles3, false};
const gl::Dialect kGlesMultiDraw{gl::Api::Gles3, true};

// Every program root: the files gnomon compiles, named *.vert.glsl and *.frag.glsl.
std::vector<std::string> roots() {
    std::vector<std::string> r;
    for (const std::string& name : gl::embeddedShaderNames()) {
        if (name.ends_with(".vert.glsl") || name.ends_with(".frag.glsl")) r.push_back(name);
    }
    return r;
}

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

// How many lines the dialect puts after #version.
std::size_t dialectLineCount(const gl::AssembledSource& s) {
    return std::size_t(std::count_if(s.lines.begin(), s.lines.end(), [](const gl::SourceLine& l) {
        return l.line == gl::SourceLine::kInjectedDialect;
    }));
}

TEST(GlesAssembly, OpensWithVersionDialectLinesThenTheCallersDefines) {
    const gl::AssembledSource s = gl::assembleShader("main.frag.glsl", {"A 1", "B"}, kGles);
    const std::vector<std::string> lines = linesOf(s.text);
    ASSERT_GT(lines.size(), 30u);
    EXPECT_EQ(lines[0], "#version 300 es");
    const std::size_t n = dialectLineCount(s);
    ASSERT_GT(n, 0u);
    for (std::size_t i = 1; i <= n; ++i)
        EXPECT_EQ(s.lines[i].line, gl::SourceLine::kInjectedDialect) << lines[i];
    EXPECT_EQ(lines[n + 1], "#define A 1");
    EXPECT_EQ(lines[n + 2], "#define B");
    EXPECT_EQ(s.lines[n + 1].line, gl::SourceLine::kInjectedDefine);
    EXPECT_EQ(s.lines[n + 3].line, 2);  // the file's own line 2 follows
    const std::vector<std::string> own(lines.begin() + 1, lines.begin() + long(n) + 1);
    for (const char* wanted :
         {"#define GNOMON_GLES 1", "precision highp float;", "precision highp int;",
          "precision highp sampler2D;", "precision highp sampler2DArray;",
          "precision highp sampler2DShadow;", "precision highp sampler2DArrayShadow;",
          "precision highp usampler2D;"}) {
        EXPECT_NE(std::find(own.begin(), own.end(), wanted), own.end()) << wanted;
    }
    EXPECT_EQ(std::count(s.text.begin(), s.text.end(), '\n'), std::ptrdiff_t(s.lines.size()));
}

TEST(GlesAssembly, MultiDrawExtensionAndDrawIdInVertexShadersOnly) {
    const std::string vertex = gl::assembleShader("main.vert.glsl", {}, kGlesMultiDraw).text;
    EXPECT_EQ(vertex.rfind("#version 300 es\n#extension GL_ANGLE_multi_draw : require\n", 0), 0u);
    EXPECT_NE(vertex.find("\n#define GNOMON_DRAW_ID gl_DrawID\n"), std::string::npos);
    const std::string single = gl::assembleShader("main.vert.glsl", {}, kGles).text;
    EXPECT_EQ(single.find("#extension"), std::string::npos);
    EXPECT_NE(single.find("\n#define GNOMON_DRAW_ID 0\n"), std::string::npos);
    const std::string fragment = gl::assembleShader("main.frag.glsl", {}, kGlesMultiDraw).text;
    EXPECT_EQ(fragment.find("GL_ANGLE_multi_draw"), std::string::npos);
    EXPECT_EQ(fragment.find("GNOMON_DRAW_ID"), std::string::npos);
}

// Past the dialect's lines, assembled line n of ES text comes from the same file and line as
// line n of the 4.5 text: error logs map back alike, and no declaration moves.
TEST(GlesAssembly, RewritesLineForLine) {
    for (const std::string& root : roots()) {
        const gl::AssembledSource gl45 = gl::assembleShader(root, {"X 1"});
        const gl::AssembledSource es = gl::assembleShader(root, {"X 1"}, kGles);
        const std::size_t n = dialectLineCount(es);
        ASSERT_EQ(es.lines.size(), gl45.lines.size() + n) << root;
        EXPECT_EQ(es.files, gl45.files) << root;
        for (std::size_t i = 1; i < gl45.lines.size(); ++i) {
            EXPECT_EQ(es.lines[i + n].file, gl45.lines[i].file) << root << " line " << i;
            EXPECT_EQ(es.lines[i + n].line, gl45.lines[i].line) << root << " line " << i;
        }
    }
}

// OpenGL 4.5's text is the files as they are: the dialect touches nothing there.
TEST(GlesAssembly, Gl45TextIsTheFilesThemselves) {
    const gl::AssembledSource s = gl::assembleShader("debug_lines.vert.glsl", {"A 1"});
    std::string file(gl::embeddedShader("debug_lines.vert.glsl"));
    const std::size_t afterVersion = file.find('\n') + 1;
    file.insert(afterVersion, "#define A 1\n");
    EXPECT_EQ(s.text, file);
    EXPECT_TRUE(s.locations.empty() && s.samplers.empty() && s.blocks.empty());
}

// No uniform layout that GLSL ES 3.00 rejects is left, and each recorded slot is a
// declaration of the 4.5 text: the same name at the same location, unit or binding.
TEST(GlesAssembly, RecordsEveryUniformLayoutItRemoves) {
    static const std::regex kLeft(
        R"(layout\s*\((\s*location\s*=\s*\d+\s*|\s*binding\s*=\s*\d+\s*|\s*std140\s*,\s*binding[^)]*)\)\s*uniform)");
    for (const std::string& root : roots()) {
        const gl::AssembledSource gl45 = gl::assembleShader(root, {});
        const gl::AssembledSource es = gl::assembleShader(root, {}, kGles);
        EXPECT_FALSE(std::regex_search(es.text, kLeft)) << root;
        auto declared = [&](const std::string& layout, const std::string& name) {
            for (const std::string& line : linesOf(gl45.text)) {
                if (line.rfind(layout, 0) == 0 &&
                    std::regex_search(line, std::regex("\\b" + name + R"(\s*(\[|;|\{|$))"))) {
                    return true;
                }
            }
            return false;
        };
        for (const gl::FixedSlot& f : es.locations) {
            EXPECT_TRUE(
                declared("layout(location = " + std::to_string(f.slot) + ") uniform", f.name))
                << root << ": " << f.name;
        }
        for (const gl::FixedSlot& f : es.samplers) {
            EXPECT_TRUE(
                declared("layout(binding = " + std::to_string(f.slot) + ") uniform", f.name))
                << root << ": " << f.name;
        }
        for (const gl::FixedSlot& f : es.blocks) {
            EXPECT_TRUE(
                declared("layout(std140, binding = " + std::to_string(f.slot) + ")", f.name))
                << root << ": " << f.name;
        }
        const std::vector<std::string> gl45Lines = linesOf(gl45.text);
        const std::regex uniformLayout(R"(^\s*layout\(.*\)\s*uniform)");
        const std::size_t uniformLayouts = std::size_t(
            std::count_if(gl45Lines.begin(), gl45Lines.end(), [&](const std::string& l) {
                return std::regex_search(l, uniformLayout) && l.find("image") == std::string::npos;
            }));
        EXPECT_EQ(es.locations.size() + es.samplers.size() + es.blocks.size(), uniformLayouts)
            << root;
    }
}

TEST(GlesAssembly, TablesOfTheMainPass) {
    const gl::AssembledSource frag = gl::assembleShader("main.frag.glsl", {}, kGles);
    auto has = [](const std::vector<gl::FixedSlot>& table, int slot, const char* name) {
        return std::find(table.begin(), table.end(), gl::FixedSlot{slot, name}) != table.end();
    };
    EXPECT_TRUE(has(frag.locations, 3, "uAmbient"));
    EXPECT_TRUE(has(frag.locations, 6, "uLightRanges"));
    EXPECT_TRUE(has(frag.locations, 13, "uClipFromWorld"));
    EXPECT_TRUE(has(frag.samplers, 1, "uShadowCubes"));
    EXPECT_TRUE(has(frag.samplers, 8, "uTransmittanceCubes"));
    EXPECT_TRUE(has(frag.blocks, 1, "Lights"));
    EXPECT_TRUE(has(frag.blocks, 2, "LightOrder"));
    EXPECT_NE(frag.text.find("\nlayout(std140) uniform Lights {"), std::string::npos);
    // Both of moments.frag's unit-0 samplers (exclusive #if branches) are kept.
    const gl::AssembledSource moments = gl::assembleShader("moments.frag.glsl", {}, kGles);
    EXPECT_TRUE(has(moments.samplers, 0, "uDepths"));
    EXPECT_TRUE(has(moments.samplers, 0, "uRows"));
    // depth.vert's location 1 names the light's matrix or, with VIEW_CAMERA, the view's.
    const gl::AssembledSource depth = gl::assembleShader("depth.vert.glsl", {}, kGles);
    EXPECT_TRUE(has(depth.locations, 1, "uClipFromWorld"));
    EXPECT_TRUE(has(depth.locations, 1, "uViewFromWorld"));
    EXPECT_TRUE(has(depth.locations, 2, "uClipFromView"));
}

TEST(GlesAssembly, InterfaceBlocksBecomeVaryings) {
    const std::string vert = gl::assembleShader("main.vert.glsl", {}, kGles).text;
    const std::string frag = gl::assembleShader("main.frag.glsl", {}, kGles).text;
    EXPECT_NE(vert.find("\n    out vec3 VertexOut_wsPosition;\n"), std::string::npos);
    // GLSL ES wants the interpolation qualifier before the storage qualifier.
    EXPECT_NE(vert.find("\n    flat out vec4 VertexOut_material;"), std::string::npos);
    EXPECT_NE(frag.find("\n    flat in vec4 VertexOut_material;\n"), std::string::npos);
    // The block's #if lines stay where they were, around the members they hold.
    EXPECT_NE(frag.find("\n    flat in float VertexOut_receives;\n#ifdef MATERIAL_PATH\n"
                        "    in vec2 VertexOut_uv;\n"),
              std::string::npos);
    EXPECT_NE(frag.find("s.base = VertexOut_colour;"), std::string::npos);
    EXPECT_NE(frag.find("#define CASCADE_DEPTH dot(uCascadeDepth, vec4(VertexOut_wsPosition"),
              std::string::npos);
    const std::regex block(R"(\n\s*(in|out)\s+\w+\s*\{)");
    for (const std::string& root : roots()) {
        const std::string text = gl::assembleShader(root, {}, kGles).text;
        EXPECT_FALSE(std::regex_search(text, block)) << root;
        for (const char* instance : {"vIn.", "vOut.", "vAlpha."})
            EXPECT_EQ(text.find(instance), std::string::npos) << root << ": " << instance;
    }
    const std::string alpha = gl::assembleShader("depth.frag.glsl", {"ALPHA_TEST"}, kGles).text;
    EXPECT_NE(alpha.find("    flat in float AlphaOut_cutoff;"), std::string::npos);
    EXPECT_NE(alpha.find("AlphaOut_alpha * texture(uBaseColourTexture, AlphaOut_uv).a"),
              std::string::npos);
}

// The object records' ES layout and draw base are the C++ side's constants.
TEST(GlesAssembly, SceneDataFollowsTheEsConstants) {
    const gl::AssembledSource es = gl::assembleShader("depth.vert.glsl", {}, kGles);
    EXPECT_NE(std::find(es.locations.begin(), es.locations.end(),
                        gl::FixedSlot{gl::kDrawBaseLocation, "uDrawBase"}),
              es.locations.end());
    EXPECT_NE(es.text.find("\n#define GNOMON_OBJECTS_PER_ROW " +
                           std::to_string(gl::kObjectsPerRow) + "\n"),
              std::string::npos);
}

// ANGLE's references (Chrome's WebGL errors), Mesa's and NVIDIA's, on ES text: the dialect's
// own lines are named as injected, the files' lines by file and line.
TEST(GlesAssembly, InfoLogNamesInjectedAndFileLines) {
    const gl::AssembledSource s = gl::assembleShader("main.frag.glsl", {"A 1"}, kGles);
    const std::vector<std::string> lines = linesOf(s.text);
    const auto precision = std::find(lines.begin(), lines.end(), "precision highp float;");
    ASSERT_NE(precision, lines.end());
    const int injected = int(precision - lines.begin()) + 1;
    const int define = int(dialectLineCount(s)) + 2;
    const auto it = std::find_if(s.lines.begin(), s.lines.end(), [&](const gl::SourceLine& l) {
        return s.files[std::size_t(l.file)] == "shadow_lookup.glsl" && l.line == 40;
    });
    ASSERT_NE(it, s.lines.end());
    const int shadowLookup40 = int(it - s.lines.begin()) + 1;
    const std::string log =
        "ERROR: 0:" + std::to_string(shadowLookup40) +
        ": 'x' : undeclared identifier\nWARNING: 0:" + std::to_string(injected) +
        ": 'y' : unused\nERROR: 0:" + std::to_string(define) +
        ": 'A' : redefined\nERROR: 0:99999: z\n" + "0:" + std::to_string(shadowLookup40) +
        "(7): error: w";
    EXPECT_EQ(gl::annotateInfoLog(log, s),
              "ERROR: shadow_lookup.glsl:40: 'x' : undeclared identifier\n"
              "WARNING: main.frag.glsl:(injected for GLSL ES): 'y' : unused\n"
              "ERROR: main.frag.glsl:(injected #define): 'A' : redefined\n"
              "ERROR: 0:99999: z\n"
              "shadow_lookup.glsl:40:7: error: w");
}

}  // namespace
}  // namespace gnomon::test
