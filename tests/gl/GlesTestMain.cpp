// main() for the GLSL ES tests: lists tests without GL (for CTest discovery); otherwise opens
// the OpenGL ES context and the OpenGL 4.5 one, and exits 77 (CTest: skipped) when either
// cannot be made, with the reason.
#include <gtest/gtest.h>

#include <cstdio>
#include <optional>

#include "GlesTest.h"
#include "gl/Context.h"
#include "gnomon/Error.h"

namespace gnomon::test {
namespace {

struct Contexts {
    gl::HeadlessContext es{false, false, gl::Api::Gles3};
    gl::ContextCaps esCaps;  // read with the ES context current
    gl::HeadlessContext native{false, false, gl::Api::Gl45};
    gl::ContextCaps nativeCaps;
};
std::optional<Contexts> gContexts;

}  // namespace

void useEs() {
    gContexts->es.makeCurrent();
    gContexts->esCaps.activate();
}

void useNative() {
    gContexts->native.makeCurrent();
    gContexts->nativeCaps.activate();
}

const gl::Caps& esCaps() {
    return gContexts->esCaps.get();
}

}  // namespace gnomon::test

int main(int argc, char** argv) {
    testing::InitGoogleTest(&argc, argv);
    if (!GTEST_FLAG_GET(list_tests)) {
        try {
            gnomon::test::gContexts.emplace();
        } catch (const gnomon::Error& e) {
            if (e.kind() != gnomon::ErrorKind::Gl) throw;
            std::fprintf(stderr, "skipping GLSL ES tests: %s\n", e.what());
            return 77;
        }
        gnomon::test::useEs();
    }
    const int result = RUN_ALL_TESTS();
    gnomon::test::gContexts.reset();
    return result;
}
