// A second ray caster, written apart from gnomon's reference (truth/Reference.h) and built on
// another library (CGAL's AABB tree in double precision instead of Embree in float), to check
// that reference: a score is only as right as the truth it is measured against. It traces the
// same definition from its own code: one ray per pixel centre from the camera's axes, the
// nearest surface between the camera's near and far planes, and per light one shadow ray
// towards it (hard shadows). Every misclassification gnomon reports rests on the reference's
// answer at such a pixel, so where the two casters agree the scores are not the reference's
// own error.
//
// What it leaves out, and counts as not compared: masked and blended surfaces (their alpha
// rules are the reference's alone), orthographic cameras, soft shadows. It does not skip
// single-sided faces seen from behind, which the reference does (as the main pass culls
// them): a pixel where that matters counts as seeing another surface.
#pragma once

#include <cstddef>
#include <string>

#include "gnomon/Options.h"
#include "gnomon/Scene.h"
#include "truth/Reference.h"

namespace gnomon::crosscheck {

struct Agreement {
    std::size_t pixels = 0;        // pixels either caster sees a surface at
    std::size_t otherSurface = 0;  // of those: a different object, or one sees nothing
    std::size_t pairs = 0;         // pixel x light pairs both call lit or shadowed
    std::size_t disagree = 0;      // of those: one says lit, the other shadowed
    std::size_t referenceLit = 0;  // of those: the reference says lit
    std::size_t reachDiffers = 0;  // one says the light reaches the surface, the other not
    std::size_t notCompared = 0;   // masked or blended surfaces on either ray
    double disagreeShare() const { return pairs ? double(disagree) / double(pairs) : 0.0; }
    double otherSurfaceShare() const {
        return pixels ? double(otherSurface) / double(pixels) : 0.0;
    }
};

// Traces `scene` as the reference does for options' size and time and compares the answers
// with `reference` (traced from the same scene and options). Throws gnomon::Error
// (InvalidInput) for an orthographic camera.
Agreement compareWithReference(const Scene& scene, const RenderOptions& options,
                               const truth::Reference& reference);

// One line: the counts and shares above.
std::string describe(const Agreement& a);

}  // namespace gnomon::crosscheck
