#include "gl/ShaderSource.h"

#include <regex>
#include <sstream>

#include "gnomon/Error.h"

namespace gnomon::gl {

struct EmbeddedFile {
    const char* name;
    const unsigned char* data;
    std::size_t size;
};
// Defined in the generated embedded_shaders.cpp.
extern const EmbeddedFile kEmbeddedShaders[];
extern const std::size_t kEmbeddedShaderCount;

std::string_view embeddedShader(const std::string& name) {
    for (std::size_t i = 0; i < kEmbeddedShaderCount; ++i) {
        if (name == kEmbeddedShaders[i].name) {
            return {reinterpret_cast<const char*>(kEmbeddedShaders[i].data),
                    kEmbeddedShaders[i].size};
        }
    }
    throw Error(ErrorKind::Gl, "no embedded shader named '" + name + "'");
}

std::vector<std::string> embeddedShaderNames() {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < kEmbeddedShaderCount; ++i)
        names.emplace_back(kEmbeddedShaders[i].name);
    return names;
}

Dialect dialectOf(const Caps& caps) {
    return {caps.api, caps.api == Api::Gles3 && caps.multiDraw};
}

namespace {

// The assembled text as lines, before they are joined.
struct Lines {
    std::vector<std::string> text;
    std::vector<SourceLine> at;
    void add(std::string line, int file, int lineNo) {
        text.push_back(std::move(line));
        at.push_back({file, lineNo});
    }
};

void expand(const std::string& file, AssembledSource& out, Lines& lines,
            std::vector<std::string>& stack, bool isRoot, const std::vector<std::string>& defines) {
    for (const auto& open : stack) {
        if (open == file) throw Error(ErrorKind::Gl, "shader include cycle through " + file);
    }
    for (const auto& done : out.files) {
        if (!isRoot && done == file) return;  // include once
    }
    const int index = int(out.files.size());
    out.files.push_back(file);
    stack.push_back(file);
    std::istringstream in{std::string(embeddedShader(file))};
    std::string line;
    int lineNo = 0;
    static const std::regex kInclude(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
    while (std::getline(in, line)) {
        ++lineNo;
        std::smatch m;
        if (std::regex_match(line, m, kInclude)) {
            expand(m[1].str(), out, lines, stack, false, defines);
        } else if (isRoot && lineNo == 1 && line.rfind("#version", 0) == 0) {
            lines.add(line, index, lineNo);
            for (const auto& d : defines)
                lines.add("#define " + d, index, SourceLine::kInjectedDefine);
        } else {
            lines.add(line, index, lineNo);
        }
    }
    stack.pop_back();
}

[[noreturn]] void cannotRewrite(const AssembledSource& out, const SourceLine& at,
                                const std::string& why) {
    throw Error(ErrorKind::Gl, "shader " + out.files[std::size_t(at.file)] + ":" +
                                   std::to_string(at.line) + ": " + why);
}

// The dialect's own lines, after #version: GLSL ES has no default precision for floats in
// fragment shaders nor for most sampler types, and its lowp sampler2D default would round
// the object records; highp everywhere, as OpenGL 4.5 computes.
std::vector<std::string> dialectLines(const Dialect& dialect, bool vertex) {
    std::vector<std::string> l;
    if (vertex && dialect.multiDraw) l.push_back("#extension GL_ANGLE_multi_draw : require");
    l.push_back("#define GNOMON_GLES 1");
    l.push_back("#define GNOMON_OBJECTS_PER_ROW " + std::to_string(kObjectsPerRow));
    if (vertex)
        l.push_back(dialect.multiDraw ? "#define GNOMON_DRAW_ID gl_DrawID"
                                      : "#define GNOMON_DRAW_ID 0");
    l.push_back("precision highp float;");
    l.push_back("precision highp int;");
    for (const char* type :
         {"sampler2D", "sampler3D", "samplerCube", "sampler2DShadow", "samplerCubeShadow",
          "sampler2DArray", "sampler2DArrayShadow", "isampler2D", "isampler3D", "isamplerCube",
          "isampler2DArray", "usampler2D", "usampler3D", "usamplerCube", "usampler2DArray"})
        l.push_back(std::string("precision highp ") + type + ";");
    return l;
}

// The uniform declarations' layouts: recorded and removed.
bool rewriteUniformLayout(std::string& line, AssembledSource& out, const SourceLine& at) {
    if (line.find("layout") == line.npos || line.find("uniform") == line.npos) return false;
    static const std::regex kLocation(
        R"(^(\s*)layout\s*\(\s*location\s*=\s*(\d+)\s*\)\s*(uniform\s.*?(\w+)\s*(\[[^\]]*\])?\s*;.*)$)");
    static const std::regex kSampler(
        R"(^(\s*)layout\s*\(\s*binding\s*=\s*(\d+)\s*\)\s*(uniform\s.*?(\w+)\s*;.*)$)");
    static const std::regex kBlock(
        R"(^(\s*)layout\s*\(\s*std140\s*,\s*binding\s*=\s*(\d+)\s*\)\s*uniform\s+(\w+)(.*)$)");
    std::smatch m;
    if (std::regex_match(line, m, kLocation)) {
        const int location = std::stoi(m[2].str());
        if (location >= kFixedLocations) {
            cannotRewrite(out, at,
                          "uniform location " + m[2].str() + " is beyond the " +
                              std::to_string(kFixedLocations) + " a program keeps");
        }
        out.locations.push_back({location, m[4].str()});
        line = m[1].str() + m[3].str();
    } else if (std::regex_match(line, m, kSampler)) {
        out.samplers.push_back({std::stoi(m[2].str()), m[4].str()});
        line = m[1].str() + m[3].str();
    } else if (std::regex_match(line, m, kBlock)) {
        out.blocks.push_back({std::stoi(m[2].str()), m[3].str()});
        line = m[1].str() + "layout(std140) uniform " + m[3].str() + m[4].str();
    } else {
        return false;
    }
    return true;
}

// A preprocessor line (#if, #define...).
bool isDirective(const std::string& line) {
    const std::size_t first = line.find_first_not_of(" \t");
    return first != line.npos && line[first] == '#';
}

// `in|out Block { [qualifiers] T m; ... } instance;` becomes `[qualifiers] in|out T Block_m;`
// line for line (the block's own lines become comments, #if lines inside stay); then
// `instance.m` is `Block_m` wherever it is used.
void flattenInterfaceBlocks(Lines& lines, const AssembledSource& out) {
    static const std::regex kOpen(R"(^\s*(in|out)\s+(\w+)\s*\{\s*(//.*)?$)");
    static const std::regex kMember(
        R"(^(\s*)((?:(?:flat|smooth|centroid)\s+)*)(\w+)\s+(\w+)\s*;(.*)$)");
    static const std::regex kClose(R"(^\s*\}\s*(\w+)\s*;\s*(//.*)?$)");
    static const std::regex kBlank(R"(^\s*(//.*)?$)");
    std::string storage, block;
    for (std::size_t i = 0; i < lines.text.size(); ++i) {
        std::string& line = lines.text[i];
        std::smatch m;
        if (block.empty()) {
            if (line.find('{') != line.npos && std::regex_match(line, m, kOpen)) {
                storage = m[1].str();
                block = m[2].str();
                line = "// " + line + "  (interface block flattened for GLSL ES)";
            }
            continue;
        }
        if (std::regex_match(line, m, kClose)) {
            const std::string instance = m[1].str() + ".";
            const std::regex use("\\b" + m[1].str() + "\\.(\\w+)");
            line = "// " + line;
            for (std::size_t j = i + 1; j < lines.text.size(); ++j) {
                if (lines.text[j].find(instance) == std::string::npos) continue;
                lines.text[j] = std::regex_replace(lines.text[j], use, block + "_$1");
            }
            block.clear();
        } else if (std::regex_match(line, m, kMember)) {
            line = m[1].str() + m[2].str() + storage + " " + m[3].str() + " " + block + "_" +
                   m[4].str() + ";" + m[5].str();
        } else if (!isDirective(line) && !std::regex_match(line, kBlank)) {
            cannotRewrite(out, lines.at[i],
                          "cannot flatten this interface block member for GLSL ES");
        }
    }
    if (!block.empty()) {
        throw Error(ErrorKind::Gl,
                    "shader " + out.files[0] + ": interface block " + block + " has no end");
    }
}

bool endsWith(const std::string& s, std::string_view end) {
    return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

void toGles(Lines& lines, AssembledSource& out, const Dialect& dialect, bool vertex) {
    if (lines.text.empty() || lines.text[0].rfind("#version", 0) != 0) {
        throw Error(ErrorKind::Gl, "shader " + out.files[0] + " does not start with #version");
    }
    lines.text[0] = "#version 300 es";
    const std::vector<std::string> own = dialectLines(dialect, vertex);
    lines.text.insert(lines.text.begin() + 1, own.begin(), own.end());
    lines.at.insert(lines.at.begin() + 1, own.size(), {0, SourceLine::kInjectedDialect});
    for (std::size_t i = 0; i < lines.text.size(); ++i)
        rewriteUniformLayout(lines.text[i], out, lines.at[i]);
    flattenInterfaceBlocks(lines, out);
}

}  // namespace

AssembledSource assembleShader(const std::string& file, const std::vector<std::string>& defines,
                               const Dialect& dialect) {
    AssembledSource out;
    Lines lines;
    std::vector<std::string> stack;
    expand(file, out, lines, stack, true, defines);
    if (dialect.api == Api::Gles3) toGles(lines, out, dialect, endsWith(file, ".vert.glsl"));
    for (const std::string& line : lines.text) {
        out.text += line;
        out.text += '\n';
    }
    out.lines = std::move(lines.at);
    return out;
}

std::string annotateInfoLog(const std::string& log, const AssembledSource& source) {
    // ANGLE: "ERROR: 0:12: ...", Mesa: "0:12(3): error: ...", NVIDIA: "0(12) : error ...".
    static const std::regex kRef(
        R"((^|\n)(?:((?:ERROR|WARNING): )(\d+):(\d+):|(\d+)(?::(\d+)\((\d+)\)|\((\d+)\))))");
    std::string out;
    auto begin = log.cbegin();
    std::smatch m;
    while (std::regex_search(begin, log.cend(), m, kRef)) {
        out.append(begin, m[0].first);
        const std::string number = m[4].matched   ? m[4].str()
                                   : m[6].matched ? m[6].str()
                                                  : m[8].str();
        const std::size_t assembled = std::stoul(number);
        if (assembled >= 1 && assembled <= source.lines.size()) {
            const SourceLine& at = source.lines[assembled - 1];
            const std::string where = at.line > 0 ? std::to_string(at.line)
                                      : at.line == SourceLine::kInjectedDefine
                                          ? std::string("(injected #define)")
                                          : std::string("(injected for GLSL ES)");
            out += m[1].str() + m[2].str() + source.files[std::size_t(at.file)] + ":" + where;
            if (m[7].matched) out += ":" + m[7].str();
            if (m[4].matched) out += ":";
        } else {
            out += m[0].str();  // not a line we know: leave the driver's text
        }
        begin = m[0].second;
    }
    out.append(begin, log.cend());
    return out;
}

}  // namespace gnomon::gl
