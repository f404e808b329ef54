// The GL layer's promises: framebuffer completeness in words, shader errors naming the
// .glsl file and line, move-only ownership that deletes exactly once.
#include <gtest/gtest.h>

#include <algorithm>

#include "GlTest.h"
#include "gl/Objects.h"
#include "gl/Program.h"
#include "gl/ShaderSource.h"

namespace gnomon::test {
namespace {

TEST(GlLayer, IncompleteFramebufferIsNamedInWords) {
    sharedRenderer().glInfo();  // context current
    gl::Framebuffer empty("empty");
    try {
        empty.checkComplete();
        FAIL() << "an empty framebuffer must not be complete";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Gl);
        EXPECT_NE(std::string(e.what()).find("missing attachment"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("'empty'"), std::string::npos) << e.what();
    }
}

TEST(GlLayer, StatusTextCoversTheStatuses) {
    EXPECT_NE(gl::framebufferStatusText(GL_FRAMEBUFFER_UNSUPPORTED).find("unsupported"),
              std::string::npos);
    EXPECT_NE(gl::framebufferStatusText(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT)
                  .find("incomplete attachment"),
              std::string::npos);
    EXPECT_NE(gl::framebufferStatusText(0x1234).find("0x1234"), std::string::npos);
}

TEST(GlLayer, CompileErrorNamesIncludedFileAndLine) {
    sharedRenderer().glInfo();
    // A define that breaks the PCF loop inside the included shadow_lookup.glsl.
    try {
        gl::buildProgram("broken", {{GL_FRAGMENT_SHADER, "main.frag.glsl"}},
                         {"FILTER_PCF", "PCF_SIZE )"});
        FAIL() << "the program must not compile";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("main.frag.glsl"), std::string::npos) << what;
        EXPECT_NE(what.find("shadow_lookup.glsl:"), std::string::npos) << what;
    }
}

TEST(GlLayer, InfoLogReferencesAreRewritten) {
    gl::AssembledSource src;
    src.files = {"main.frag.glsl", "lights.glsl"};
    src.lines = {{0, 1}, {0, 0}, {1, 1}, {1, 2}, {1, 3}, {0, 3}};
    EXPECT_EQ(gl::annotateInfoLog("0:6(5): error: x\n0:4(1): error: y", src),
              "main.frag.glsl:3:5: error: x\nlights.glsl:2:1: error: y");
    EXPECT_EQ(gl::annotateInfoLog("0(5) : error C0000", src), "lights.glsl:3 : error C0000");
    EXPECT_EQ(gl::annotateInfoLog("0:2(1): error: z", src),
              "main.frag.glsl:(injected #define):1: error: z");
    EXPECT_EQ(gl::annotateInfoLog("0:99(1): error: w", src), "0:99(1): error: w");
}

TEST(GlLayer, AssembledSourceMapsEveryLine) {
    const gl::AssembledSource s = gl::assembleShader("main.frag.glsl", {"A 1", "B"});
    EXPECT_EQ(s.files.at(0), "main.frag.glsl");
    EXPECT_EQ(s.text.rfind("#version 450 core\n#define A 1\n#define B\n", 0), 0u);
    EXPECT_EQ(std::count(s.text.begin(), s.text.end(), '\n'), std::ptrdiff_t(s.lines.size()));
    EXPECT_EQ(s.text.find("#line"), std::string::npos);
    // Line 2 of the assembled text is the first injected define; the original line 2 follows.
    EXPECT_EQ(s.lines.at(1).line, 0);
    EXPECT_EQ(s.lines.at(3).file, 0);
    EXPECT_EQ(s.lines.at(3).line, 2);
    // The first included file's lines are numbered from 1 again.
    const auto first = std::find_if(s.lines.begin(), s.lines.end(),
                                    [](const gl::SourceLine& l) { return l.file == 1; });
    ASSERT_NE(first, s.lines.end());
    EXPECT_EQ(first->line, 1);
}

// A real driver error inside an included file names that file and the exact line.
TEST(GlLayer, DriverErrorInIncludedFileNamesItsLine) {
    sharedRenderer().glInfo();
    try {
        gl::buildProgram("broken", {{GL_FRAGMENT_SHADER, "main.frag.glsl"}},
                         {"FILTER_PCF", "PCF_SIZE 3", "kFilterReach )"});
        FAIL() << "the program must not compile";
    } catch (const Error& e) {
        // kFilterReach is first declared in shadow_lookup.glsl, inside #if FILTER_PCF.
        const std::string source(gl::embeddedShader("shadow_lookup.glsl"));
        int line = 0, wanted = 0;
        for (size_t pos = 0, next; pos < source.size(); pos = next + 1) {
            next = source.find('\n', pos);
            if (next == std::string::npos) next = source.size();
            ++line;
            if (wanted == 0 && source.compare(pos, 24, "const float kFilterReach") == 0) {
                wanted = line;
            }
        }
        ASSERT_GT(wanted, 0);
        const std::string what = e.what();
        EXPECT_NE(what.find("shadow_lookup.glsl:" + std::to_string(wanted)), std::string::npos)
            << what;
    }
}

TEST(GlLayer, MovedObjectsAreDeletedOnce) {
    sharedRenderer().glInfo();
    GLuint name = 0;
    {
        gl::Buffer a("moved", 16, nullptr, 0);
        name = a.id();
        gl::Buffer b = std::move(a);
        EXPECT_EQ(a.id(), 0u);
        EXPECT_EQ(b.id(), name);
        EXPECT_TRUE(glIsBuffer(name));
    }
    EXPECT_FALSE(glIsBuffer(name));
}

TEST(GlLayer, IntegerTexelsReadBackAsWritten) {
    // The light lists' texture (render/TiledLights.h): RGBA32I, row y = 0 first, rewritten
    // whole. ES reads no integer texture back; its lists are checked by their pictures.
    sharedRenderer().glInfo();
    if (testsGles()) GTEST_SKIP() << "no integer texture readback on ES";
    std::vector<std::int32_t> texels(3 * 2 * 4);
    for (std::size_t i = 0; i < texels.size(); ++i)
        texels[i] = std::int32_t(i * 37) - 300;
    gl::Texture t = gl::Texture::integers2D("integers", texels.data(), 3, 2);
    std::vector<std::int32_t> back(texels.size());
    t.read(0, 0, 0, 3, 2, GL_RGBA_INTEGER, GL_INT, back.size() * 4, back.data());
    EXPECT_EQ(back, texels);
    std::reverse(texels.begin(), texels.end());
    t.writeIntegers2D(texels.data());
    t.read(0, 0, 0, 3, 2, GL_RGBA_INTEGER, GL_INT, back.size() * 4, back.data());
    EXPECT_EQ(back, texels);
}

}  // namespace
}  // namespace gnomon::test
