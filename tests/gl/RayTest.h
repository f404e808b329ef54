// Shared by the shadow-ray tests: a scene's options with rays, and the misclassified pairs of
// a score held to a bound.
#pragma once

#include <gtest/gtest.h>

#include "gnomon/gnomon.h"

namespace gnomon::test {

// `s`'s own options at size x size with `--shadow-rays mode`.
inline RenderOptions withRays(const Scene& s, int size, ShadowRayMode mode) {
    RenderOptions o = s.options;
    o.width = o.height = size;
    o.shadow.shadowRays = mode;
    return o;
}

// Pixel x light pairs wrong, out of the pairs scored.
inline double wrongPairs(const ScoreResult& r) {
    return r.overall.misclassified * double(r.overall.pixels);
}

// At most `share` of the pixel x light pairs plus `allowance` pairs wrong (a pixel centre
// within a float's rounding of an edge falls either side), none away from the reference's
// shadow boundaries.
inline void expectWrongAtMost(const ScoreResult& r, double share, double allowance) {
    EXPECT_LE(wrongPairs(r), share * double(r.overall.pixels) + allowance);
    EXPECT_EQ(r.overall.falseShadowOutsideBand, 0.0);
    EXPECT_EQ(r.overall.leakOutsideBand, 0.0);
}

}  // namespace gnomon::test
