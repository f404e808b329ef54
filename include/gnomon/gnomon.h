// gnomon: real-time shadows you can measure. Include this for the whole public API.
#pragma once

#include "gnomon/Error.h"
#include "gnomon/Image.h"
#include "gnomon/OptionSchema.h"
#include "gnomon/Options.h"
#include "gnomon/Renderer.h"
#include "gnomon/Scene.h"
#include "gnomon/SceneFile.h"
#include "gnomon/ScenePath.h"
#include "gnomon/Score.h"
#include "gnomon/Tune.h"

namespace gnomon {
// "MAJOR.MINOR.PATCH" of the library.
const char* version();
}  // namespace gnomon
