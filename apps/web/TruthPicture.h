// The picture the web page shows while the renderer does not yet run in the browser: the scene
// from its camera as the ray-traced reference sees it (truth/Reference.h), shaded by one
// light. Each surface shows its material's base colour (textures left out), brighter with
// the cosine to the light where the light's shadow ray arrives, and a quarter of it where the
// ray is blocked or the reference traces none (the light does not reach the surface, or it
// takes no part in shadows: --shadows off, a light that casts none, a surface that receives
// none). The page traces it on the project's BVH; the native check of the page (tests/web)
// traces the same picture on Embree, so the two can be compared.
#pragma once

#include "gnomon/Image.h"
#include "gnomon/Options.h"
#include "gnomon/Scene.h"
#include "truth/Tracer.h"

namespace gnomon::web {

// The light the picture shows: --light-only's when set, else the scene's first light that is
// on and casts shadows, else its first light; -1 for a scene without lights.
int pictureLight(const Scene& scene, const RenderOptions& options);

// RGBA at options.width x height, rows top first, sRGB-encoded for display. Throws
// gnomon::Error when the tracer cannot be made for the scene. Traced on one thread: the page
// has no others.
Image truthPicture(const Scene& scene, const RenderOptions& options, truth::TracerKind tracer);

}  // namespace gnomon::web
