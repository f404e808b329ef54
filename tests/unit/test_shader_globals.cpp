// Shaders keep no module-scope mutable variables: a value a helper works out goes back to its
// caller as a return value (a struct where there are several, or an out parameter), never
// through a global that the caller has to know to read, or to reset before the next light.
// This scans shaders/*.glsl and names each file-scope declaration that is not const, uniform,
// in, out, buffer or shared, with its file and line.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Global {
    int line = 0;      // 1-based, where the declaration starts
    std::string text;  // the declaration, whitespace folded
};

// `source` with comments and preprocessor lines (continuations too) blanked out, every newline
// kept so that offsets still give line numbers.
std::string codeOnly(const std::string& source) {
    std::string out = source;
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (out.compare(i, 2, "//") == 0) {
            while (i < out.size() && out[i] != '\n')
                out[i++] = ' ';
        } else if (out.compare(i, 2, "/*") == 0) {
            const std::size_t end = out.find("*/", i + 2);
            const std::size_t stop = end == std::string::npos ? out.size() : end + 2;
            for (; i < stop; ++i)
                if (out[i] != '\n') out[i] = ' ';
            --i;
        }
    }
    std::size_t lineStart = 0;
    bool continued = false;
    while (lineStart < out.size()) {
        std::size_t lineEnd = out.find('\n', lineStart);
        if (lineEnd == std::string::npos) lineEnd = out.size();
        const std::size_t first = out.find_first_not_of(" \t", lineStart);
        const bool directive = first < lineEnd && out[first] == '#';
        if (continued || directive) {
            const std::size_t last = out.find_last_not_of(" \t\r", lineEnd - 1);
            continued = last != std::string::npos && last >= lineStart && out[last] == '\\';
            std::fill(out.begin() + std::ptrdiff_t(lineStart),
                      out.begin() + std::ptrdiff_t(lineEnd), ' ');
        }
        lineStart = lineEnd + 1;
    }
    return out;
}

std::vector<std::string> words(const std::string& text) {
    std::vector<std::string> out;
    std::string word;
    for (char c : text + ' ') {
        if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') {
            word += c;
        } else if (!word.empty()) {
            out.push_back(word);
            word.clear();
        }
    }
    return out;
}

// Drops every `layout(...)` qualifier.
std::string withoutLayouts(std::string text) {
    for (std::size_t at; (at = text.find("layout")) != std::string::npos;) {
        const std::size_t open = text.find('(', at);
        if (open == std::string::npos) break;
        int depth = 0;
        std::size_t close = open;
        for (; close < text.size(); ++close) {
            if (text[close] == '(') ++depth;
            if (text[close] == ')' && --depth == 0) break;
        }
        text.erase(at, close + 1 - at);
    }
    return text;
}

const std::set<std::string>& qualifiers() {
    static const std::set<std::string> kWords = {
        "flat",    "smooth", "noperspective", "centroid", "sample",   "patch",    "highp",
        "mediump", "lowp",   "coherent",      "volatile", "restrict", "readonly", "writeonly"};
    return kWords;
}

// The first word of a declaration after its layouts and qualifiers ("" when there is none).
std::string leadingWord(const std::string& statement) {
    const std::vector<std::string> w = words(withoutLayouts(statement));
    for (const std::string& word : w)
        if (!qualifiers().count(word)) return word;
    return "";
}

// Whether a file-scope statement (up to its `;`) declares mutable storage of the module's own.
bool declaresMutable(const std::string& statement) {
    static const std::set<std::string> kShared = {"const",     "uniform",   "in",      "out",
                                                  "buffer",    "shared",    "precise", "invariant",
                                                  "precision", "attribute", "varying"};
    const std::string text = withoutLayouts(statement);
    const std::string first = leadingWord(text);
    if (first.empty() || kShared.count(first)) return false;
    if (first == "struct") {
        // `struct S { ... };` declares a type; `struct S { ... } s;` a variable too.
        const std::size_t close = text.rfind('}');
        return close != std::string::npos && !words(text.substr(close)).empty();
    }
    // A function prototype: a parenthesis before any initialiser.
    return text.substr(0, text.find('=')).find('(') == std::string::npos;
}

// Whether the text before a `{` at file scope starts a function's body (not a struct's or an
// interface block's).
bool isFunctionHeader(const std::string& statement) {
    static const std::set<std::string> kBlocks = {"struct", "uniform", "in",
                                                  "out",    "buffer",  "shared"};
    return withoutLayouts(statement).find('(') != std::string::npos &&
           !kBlocks.count(leadingWord(statement));
}

std::string folded(const std::string& text) {
    std::string out;
    bool space = false;
    for (char c : text) {
        if (std::isspace(static_cast<unsigned char>(c))) {
            space = !out.empty();
            continue;
        }
        if (space) out += ' ';
        out += c;
        space = false;
    }
    return out;
}

// The module-scope mutable variables of GLSL `source`.
std::vector<Global> moduleScopeGlobals(const std::string& source) {
    std::vector<Global> found;
    std::string statement;  // the file-scope text since the last declaration ended
    int depth = 0, line = 1, start = 0;
    for (char c : codeOnly(source)) {
        if (c == '\n') ++line;
        if (depth == 0 && start == 0 && !std::isspace(static_cast<unsigned char>(c))) start = line;
        if (c == '{' && depth++ == 0) {
            statement += c;
        } else if (c == '}' && --depth == 0) {
            if (isFunctionHeader(statement)) {  // a definition ends at its body: no `;`
                statement.clear();
                start = 0;
            } else {
                statement += c;
            }
        } else if (depth == 0 && c == ';') {
            if (declaresMutable(statement)) found.push_back({start, folded(statement)});
            statement.clear();
            start = 0;
        } else if (depth == 0) {
            statement += c;
        }
    }
    return found;
}

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(ShaderGlobals, TheScannerFindsMutableGlobalsOnly) {
    const std::string source = R"(#version 450 core
#define MACRO float gMacro;
#ifdef X
#endif
// float gCommented;
/* float gBlock;
   int gBlock2; */
layout(binding = 1) uniform sampler2D uTexture;
layout(location = 0) in vec3 aPosition;
flat in int aFlat;
out vec4 oColour;
in Block {
    vec3 p;
} vIn;
layout(std140, binding = 2) uniform Lights {
    vec4 l[4];
};
layout(early_fragment_tests) in;
invariant gl_Position;
const float kConstant = 1.0;
const vec2 kTable[2] = vec2[](vec2(0.0), vec2(1.0));
struct S {
    float x;
};
float prototype(float a);
float function(float a) {
    float local = a;
    return local;
}
vec3 gPlane = vec3(0.0, 1.0, 0.0);
S gStruct;
int gA, gB;
struct T { int y; } gTyped;
float
    gSplit = 2.0;
void main() {
    const S s = S(1.0);
}
)";
    const std::vector<Global> found = moduleScopeGlobals(source);
    ASSERT_EQ(found.size(), 5u);
    EXPECT_EQ(found[0].line, 30);
    EXPECT_EQ(found[0].text, "vec3 gPlane = vec3(0.0, 1.0, 0.0)");
    EXPECT_EQ(found[1].text, "S gStruct");
    EXPECT_EQ(found[2].text, "int gA, gB");
    EXPECT_EQ(found[3].line, 33);
    EXPECT_EQ(found[4].line, 34);
    EXPECT_EQ(found[4].text, "float gSplit = 2.0");
}

TEST(ShaderGlobals, NoShaderHasModuleScopeMutableVariables) {
    const std::filesystem::path dir = GNOMON_SHADER_DIR;
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".glsl") continue;
        ++files;
        for (const Global& g : moduleScopeGlobals(readFile(entry.path()))) {
            ADD_FAILURE() << "shaders/" << entry.path().filename().string() << ":" << g.line
                          << ": module-scope mutable variable '" << g.text
                          << "': return it from the function that computes it (a struct or an "
                             "out parameter) instead";
        }
    }
    EXPECT_GT(files, 10) << "no shaders found in " << dir;
}

}  // namespace
