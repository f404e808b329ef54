// main() for the GL tests: lists tests without GL (for CTest discovery); otherwise makes
// sure a headless OpenGL 4.5 context can be created and exits 77 (CTest: skipped) when not,
// with the reason. Everything else is a real failure.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "GlTest.h"

namespace gnomon::test {
// GNOMON_TEST_GLES=1: the renderer on OpenGL ES 3.0 as WebGL2 has it (ctest label gles).
bool testsGles() {
    const char* v = std::getenv("GNOMON_TEST_GLES");
    return v && std::string(v) == "1";
}

Renderer& sharedRenderer() {
    static Renderer renderer([] {
        ContextOptions o;
        o.gles = testsGles();
        return o;
    }());
    return renderer;
}
}  // namespace gnomon::test

int main(int argc, char** argv) {
    testing::InitGoogleTest(&argc, argv);
    if (!GTEST_FLAG_GET(list_tests)) {
        try {
            gnomon::test::sharedRenderer();
        } catch (const gnomon::Error& e) {
            if (e.kind() != gnomon::ErrorKind::Gl) throw;
            std::fprintf(stderr, "skipping GL tests: %s\n", e.what());
            return 77;
        }
    }
    return RUN_ALL_TESTS();
}
