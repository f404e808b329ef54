// Temporal stability (no GL): between two frames of a camera or light path, the pixels whose
// rendered shadow changed while the ray-traced reference's did not. Both renders show one
// view: the earlier frame's picture, and that same view drawn with the later frame's shadow
// maps and lights (Renderer::render with a fit camera). So the camera's own motion changes
// no pixel, and a shadow edge that is steadily in the wrong place (scored per frame by
// Metrics) does not count: only a rendered shadow that moves where the true one holds still
// (shimmering, swimming cascades, popping map sizes). Comparing each pixel with the one that
// saw its surface point in the other frame would not do: at a steady but misplaced edge the
// two samples fall on either side of it in proportion to the motion, and that bias is larger
// than the flicker of stabilised maps.
#pragma once

#include <cstdint>
#include <vector>

#include "truth/Reference.h"

namespace gnomon::truth {

struct FlickerCount {
    long compared = 0;      // pixel x light pairs where the light's shadow shows in both
    long flickered = 0;     // of them: the rendered shadow changed and the reference's did not
    long truthChanged = 0;  // of them: the reference's shadow changed (the light moved)
    std::vector<std::uint8_t> map;  // per pixel: 1 where some light flickered
    double fraction() const { return compared > 0 ? double(flickered) / double(compared) : 0.0; }
};

// `before` and `after`: the renderer's visibility per pixel x light ([pixel * lights +
// light], rows top first, as Reference) of one view, with the references traced for each
// (one reference twice when only the maps differ). Shadowed means visibility below 0.5 (the
// reference's soft visibility with `soft`, as the per-frame metrics threshold it).
FlickerCount countFlicker(const Reference& referenceBefore, const std::vector<float>& before,
                          const Reference& referenceAfter, const std::vector<float>& after,
                          bool soft);

}  // namespace gnomon::truth
