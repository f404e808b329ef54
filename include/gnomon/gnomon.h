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

// Tells the process's allocator to keep the memory it frees (glibc: mallopt's mmap and trim
// thresholds at 32 and 64 MiB, where glibc's own dynamic ones stop rising). Mesa's llvmpipe
// allocates and frees on every draw; with glibc's defaults the freed top of the heap goes
// back to the system each time and the kernel faults the pages in again, which counts where
// many draws meet small maps (docs/results/performance.md, "The heap kept between draws").
// It changes the whole process, so the library never calls it itself: a program calls it
// once at start, as the gnomon tool does. False where it does nothing (not glibc, or under
// AddressSanitizer, whose allocator serves malloc).
bool keepFreedHeap();
}  // namespace gnomon
