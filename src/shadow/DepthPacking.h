// Depth stored in 8-bit colour channels (SPEC S10, S11), mirrored on the CPU exactly as the
// GPU does it, so the precision of each scheme can be tested without a GPU. Encoding writes
// channel values in [0, 1]; an RGBA8 target then keeps round(v * 255) / 255 of each.
//   r8:        depth in red only: 256 levels.
//   packed-256: fract(d * 256^i) per channel, minus the next channel's carry / 256 (the WebGL
//              book). Decoding sums c_i / 256^i. Storage rounds to 255ths, not 256ths: the
//              red channel's k/256 comes back as the nearest k'/255, up to ~0.002 off near
//              depth 0.5 and ~0.0004 near depth 1, where the book's depths lie.
//   packed-255: the same in base 255, which matches 8-bit storage (the tutorial).
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
