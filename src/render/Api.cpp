// The public library's own symbols. Everything else in libgnomon comes whole from the
// internal static libraries (linked with WHOLE_ARCHIVE so no public function is dropped).
#include "gnomon/gnomon.h"

namespace gnomon {
const char* version() {
    return GNOMON_VERSION;
}
}  // namespace gnomon
