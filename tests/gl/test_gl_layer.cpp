// The GL layer's promises: framebuffer completeness in words (S5), shader errors naming the
// .glsl file and line, move-only ownership that deletes exactly once.
#include <gtest/gtest.h>

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
    const std::vector<std::string> files = {"main.frag.glsl", "lights.glsl"};
    EXPECT_EQ(gl::annotateInfoLog("0:12(5): error: x\n1:3(1): error: y", files),
              "main.frag.glsl:12:5: error: x\nlights.glsl:3:1: error: y");
    EXPECT_EQ(gl::annotateInfoLog("1(7) : error C0000", files), "lights.glsl:7 : error C0000");
}

TEST(GlLayer, AssembledSourceKeepsLineNumbers) {
    const gl::AssembledSource s = gl::assembleShader("main.frag.glsl", {"A 1", "B"});
    EXPECT_EQ(s.files.at(0), "main.frag.glsl");
    EXPECT_EQ(s.text.rfind("#version 450 core\n#define A 1\n#define B\n#line 2 0\n", 0), 0u);
    EXPECT_NE(s.text.find("#line 1 1"), std::string::npos);
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

}  // namespace
}  // namespace gnomon::test
