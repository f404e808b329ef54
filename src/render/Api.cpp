// The public library's own symbols. Everything else in libgnomon comes whole from the
// internal static libraries (linked with WHOLE_ARCHIVE so no public function is dropped).
#include "gnomon/gnomon.h"
#include "shadow/ShadowMath.h"

namespace gnomon {
glm::mat4 cameraClipFromWorld(const Camera& camera, float aspect) {
    return gnomon::clipFromView(camera, aspect) * gnomon::viewFromWorld(camera);
}
const char* version() {
    return GNOMON_VERSION;
}
}  // namespace gnomon
