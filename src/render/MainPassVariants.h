// What MainPass's program choice and its map binding agree on.
#pragma once

#include "gnomon/Options.h"

namespace gnomon::render {

// Stored depth fetched and compared in the shader: colour formats always, native depth for
// --filter none (so --map-filter applies, as in the LINEAR lookups of W. Brown's course text,
// §12.6).
inline bool handCompare(const ShadowOptions& s) {
    return isColourFormat(s.depthFormat) || s.filter == ShadowFilter::None;
}

}  // namespace gnomon::render
