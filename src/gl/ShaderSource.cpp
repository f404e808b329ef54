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

namespace {

void addLine(AssembledSource& out, const std::string& text, int file, int line) {
    out.text += text;
    out.text += '\n';
    out.lines.push_back({file, line});
}

void expand(const std::string& file, AssembledSource& out, std::vector<std::string>& stack,
            bool isRoot, const std::vector<std::string>& defines) {
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
            expand(m[1].str(), out, stack, false, defines);
        } else if (isRoot && lineNo == 1 && line.rfind("#version", 0) == 0) {
            addLine(out, line, index, lineNo);
            for (const auto& d : defines)
                addLine(out, "#define " + d, index, 0);
        } else {
            addLine(out, line, index, lineNo);
        }
    }
    stack.pop_back();
}

}  // namespace

AssembledSource assembleShader(const std::string& file, const std::vector<std::string>& defines) {
    AssembledSource out;
    std::vector<std::string> stack;
    expand(file, out, stack, true, defines);
    return out;
}

std::string annotateInfoLog(const std::string& log, const AssembledSource& source) {
    // Mesa: "0:12(3): error: ...", NVIDIA: "0(12) : error ...".
    static const std::regex kRef(R"((^|\n)(\d+)(:(\d+)\((\d+)\)|\((\d+)\)))");
    std::string out;
    auto begin = log.cbegin();
    std::smatch m;
    while (std::regex_search(begin, log.cend(), m, kRef)) {
        out.append(begin, m[0].first);
        const std::size_t assembled = std::stoul(m[4].matched ? m[4].str() : m[6].str());
        if (assembled >= 1 && assembled <= source.lines.size()) {
            const SourceLine& at = source.lines[assembled - 1];
            out += m[1].str() + source.files[std::size_t(at.file)] + ":" +
                   (at.line > 0 ? std::to_string(at.line) : std::string("(injected #define)"));
            if (m[5].matched) out += ":" + m[5].str();
        } else {
            out += m[0].str();  // not a line we know: leave the driver's text
        }
        begin = m[0].second;
    }
    out.append(begin, log.cend());
    return out;
}

}  // namespace gnomon::gl
