// How close two renders of the same settings must be (golden images, the viewer's
// screenshots against headless renders). Per-channel differences up to 24 are rounding and
// shadow-edge texel placement; at most 0.5% of pixels may exceed that (edges of shadows
// shift by a texel across drivers), and the mean difference must stay under 1 level (a real
// change of shading moves the mean).
#pragma once

namespace gnomon::test {

constexpr int kChannelThreshold = 24;
constexpr double kMaxFailingFraction = 0.005;
constexpr double kMaxMeanDiff = 1.0;

}  // namespace gnomon::test
