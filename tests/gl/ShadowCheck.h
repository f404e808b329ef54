// The GL tests' main assertion: shadows where the scene's own geometry says (CPU ray casting,
// tests/support/GeometryShadows) and nowhere else. Renders `scene` at 256x256 with and
// without shadows; pixels the oracle calls shadowed must be darker, pixels it calls lit
// unchanged. On failure the renders and the oracle's classes are written as PNGs.
#pragma once

#include "gnomon/gnomon.h"

namespace gnomon::test {

void expectShadowsMatchGeometry(const Scene& scene, RenderOptions options);

}  // namespace gnomon::test
