// Shared pieces of the GL tests: one Renderer per test process (context creation is the
// slow part) and helpers to compare renders.
#pragma once

#include <string>

#include "gnomon/gnomon.h"

namespace gnomon::test {

Renderer& sharedRenderer();
// True when the tests run on OpenGL ES 3.0 (GNOMON_TEST_GLES=1): what WebGL2 lacks is skipped.
bool testsGles();

// First line of a test that reads a depth map back, which OpenGL ES 3.0 (WebGL2) cannot:
// skipped there, with the reason.
#define GNOMON_NEEDS_DEPTH_READBACK() \
    if (::gnomon::test::testsGles())  \
    GTEST_SKIP() << "OpenGL ES 3.0 (WebGL2) cannot read a depth map back"

// Folder of the committed golden PNGs and of this run's outputs.
inline std::string goldenDir() {
    return GNOMON_GOLDEN_DIR;
}
inline std::string outputDir() {
    return GNOMON_TEST_OUTPUT_DIR;
}

// An orthographic camera 10 above the origin looking straight down (image up = -z),
// seeing x and z in [-halfView, halfView]: image column and row map linearly to x and z.
inline Camera lookingStraightDown(float halfView) {
    Camera c;
    c.projection = Projection::Orthographic;
    c.eye = {0.0f, 10.0f, 0.0f};
    c.centre = {0.0f, 0.0f, 0.0f};
    c.up = {0.0f, 0.0f, -1.0f};
    c.left = c.bottom = -halfView;
    c.right = c.top = halfView;
    c.near = 1.0f;
    c.far = 20.0f;
    return c;
}

inline int luminance(const std::uint8_t* p) {
    return int(p[0]) + int(p[1]) + int(p[2]);
}

}  // namespace gnomon::test
