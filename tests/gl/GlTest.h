// Shared pieces of the GL tests: one Renderer per test process (context creation is the
// slow part) and helpers to compare renders.
#pragma once

#include <string>

#include "gnomon/gnomon.h"

namespace gnomon::test {

Renderer& sharedRenderer();

// Folder of the committed golden PNGs and of this run's outputs.
inline std::string goldenDir() {
    return GNOMON_GOLDEN_DIR;
}
inline std::string outputDir() {
    return GNOMON_TEST_OUTPUT_DIR;
}

inline int luminance(const std::uint8_t* p) {
    return int(p[0]) + int(p[1]) + int(p[2]);
}

}  // namespace gnomon::test
