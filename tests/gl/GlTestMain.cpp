// main() for the GL tests: lists tests without GL (for CTest discovery); otherwise makes
// sure a headless OpenGL 4.5 context can be created and exits 77 (CTest: skipped) when not,
// with the reason. Everything else is a real failure.
#include <gtest/gtest.h>

#include <cstdio>

#include "GlTest.h"

namespace gnomon::test {
Renderer& sharedRenderer() {
    static Renderer renderer;
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
