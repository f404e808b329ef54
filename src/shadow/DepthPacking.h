// Depth stored in 8-bit colour channels, mirrored on the CPU exactly as the
// GPU does it, so the precision of each scheme can be tested without a GPU. Encoding writes
// channel values in [0, 1]; an RGBA8 target then keeps round(v * 255) / 255 of each.
//   r8:        depth in red only: 256 levels.
//   packed-256: fract(d * 256^i) per channel, minus the next channel's carry / 256 (the WebGL
//              book). Decoding sums c_i / 256^i. Storage rounds to 255ths, not 256ths: the
//              red channel's k/256 comes back as the nearest k'/255, up to ~0.002 off near
//              depth 0.5 and ~0.0004 near depth 1, where the depths of the WebGL Programming
//              Guide's sample lie.
//   packed-255: the same in base 255, which matches 8-bit storage (the online WebGL tutorial's
//   shadow chapter).
#pragma once

#include <glm/glm.hpp>

#include "gnomon/Options.h"

namespace gnomon::shadow {

// Channel values before storage.
glm::vec4 encodeDepth(DepthFormat format, float depth);
// What an RGBA8 target keeps of them.
glm::vec4 quantizeUnorm8(const glm::vec4& channels);
// Depth from stored channels.
float decodeDepth(DepthFormat format, const glm::vec4& channels);
// The largest round-trip error the format promises (used by tests and the docs).
float depthRoundTripBound(DepthFormat format);

}  // namespace gnomon::shadow

namespace gnomon::shadow {

// Spacing of representable stored depths around stored depth `stored` [0, 1]:
// 1 / (2^bits - 1) for fixed-point storage (r8, depth16, depth24; packed-256 is only as good
// as its red channel's 255ths), one float ulp of the stored value for depth32f (growing with
// the stored depth, which is where perspective depths crowd, near 1), and two float epsilons
// for packed-255 (exact in 8-bit channels; the decode's float sum limits it).
float storedDepthSpacing(DepthFormat format, float stored);

// The step the depth-aware tolerance counts in: the spacing of stored depths for fixed-point
// formats, and for depth32f one ulp of 0.5 at every depth. A stored depth is computed, by the
// rasterizer and by the lookup, as a difference of terms near 1 (a perspective's
// (f + n) / (f - n) - 2fn / ((f - n) z)), so near 0 it is off by their rounding, not by its
// own finer spacing: a point light's cube fitted tight to a floor right under it stores
// depths near 1e-3, and with the stored depth's own ulp it shadowed all of that floor.
// A lookup's tolerance is constant + depthAware x this step (shaders/shadow_lookup.glsl's
// depthTolerance, where the lookup's own float rounding, its mapRounding, is below it).
float toleranceStep(DepthFormat format);

// The course text's error graph: the view-space distance between adjacent stored depths at
// view distance `z` for a perspective camera (near, far) storing `bits` bits, i.e. how far
// apart two surfaces must be to be told apart. Grows with z^2.
float worldDepthResolution(float z, float near, float far, int bits);

}  // namespace gnomon::shadow
