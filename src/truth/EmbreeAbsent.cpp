// makeEmbreeTracer (truth/Tracer.h) for a build without Embree (the web build: Embree is x86
// SIMD and has no wasm build). CMake links this file into gnomon_truth instead of
// gnomon_embree, so the reference and its rays build unchanged; callers there ask for
// TracerKind::Bvh, and one that asks for Embree is told why it cannot have it.
#include "gnomon/Error.h"
#include "truth/Tracer.h"

namespace gnomon::truth {

TracerKind defaultTracer() {
    return TracerKind::Bvh;
}

std::unique_ptr<Tracer> makeEmbreeTracer(const TracerInput&) {
    throw Error(ErrorKind::InvalidInput,
                "this build of gnomon has no Embree: trace the reference on the project's own "
                "BVH (TracerKind::Bvh)");
}

}  // namespace gnomon::truth
