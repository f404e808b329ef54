// What the geometry says about each pixel a render got wrong (no GL): the list of
// misclassified pixel x light pairs with the facts that explain most of them (how edge-on the
// surface is to the light, how far along the shadow ray the occluder lies, the map texel's
// size there), and the errors away from shadow edges counted by cause. An error map shows
// where a shadow is wrong; this says why, so a reader can tell a resolution limit from a
// tolerance that reaches past a caster.
#pragma once

#include <vector>

#include "gnomon/Score.h"
#include "truth/Reference.h"

namespace gnomon::truth {

// A surface whose normal is this close to perpendicular to the light (sin 5.7 degrees) is
// grazed: a map texel covers ten or more texel widths of it, its depth changes by ten
// texels of depth or more per texel, and it receives under a tenth of the light, so a
// misclassification there is the map's resolution limit more than a visible error.
constexpr float kGrazingCosine = 0.1f;
// A leak whose occluder lies within this many map texels (their world size at the surface)
// of the receiver's plane (its distance along the shadow ray times the light's cosine) is at
// a contact: what moves a lookup off its surface (the normal offset, the receiver plane's
// rounding, the depth pass's slope offset, a filter's reach) moves it a few texels.
constexpr float kContactTexels = 4.0f;

// Every misclassified cell of `reference` (rendered `visibility` thresholded at 0.5 against
// the hard reference, or with `soft` the soft one), rows top first, explained; `causes`
// counts the ones outside `band`. `texelWorld` as for aliasingBand. The occluder's distance
// is found along the hard shadow ray (the centre of a soft light), by bisection on
// `reference.rays`; where that ray is clear (a leak of the soft reference's penumbra) it is
// -1 and the leak counts as other.
struct Explained {
    std::vector<ErrorCell> cells;
    ErrorCauses causes;
};
Explained explainErrors(const Reference& reference, const std::vector<float>& visibility,
                        const std::vector<float>& texelWorld, const std::vector<std::uint8_t>& band,
                        bool soft);

}  // namespace gnomon::truth
