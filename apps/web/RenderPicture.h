// The page's real-time picture: gnomon's renderer in a WebGL2 context of the page's own
// (canvas #gl, never shown), the frame read back as the CLI's `gnomon render` reads it.
#pragma once

#include <vector>

#include "gnomon/Image.h"
#include "gnomon/Options.h"
#include "gnomon/Scene.h"
#include "gnomon/Score.h"

namespace gnomon::web {

// Throws gnomon::Error when the browser gives no WebGL2 context with float render targets,
// or for what the renderer refuses (in the CLI's words).
Image renderPicture(const Scene& scene, const RenderOptions& options);

// gnomon score in the page: the frame scored against the reference traced on the project's
// BVH on the page's one thread (the same ScoreResult as `gnomon score`).
ScoreResult scorePicture(const Scene& scene, const RenderOptions& options);

// `gnomon bench`'s whole frame in the page: `warmup` then `frames` frames rendered and read
// back with every map redrawn, each one's wall time in ms (as the CLI's "frame (wall,
// render())").
std::vector<double> benchPicture(const Scene& scene, const RenderOptions& options, int warmup,
                                 int frames);

}  // namespace gnomon::web
