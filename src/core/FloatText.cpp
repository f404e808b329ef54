// shortestText: std::to_chars where the standard library has it for floats (libstdc++, the
// native build). libc++ 14 (Debian's Emscripten) does not, and says so by leaving
// __cpp_lib_to_chars undefined: there the fewest printf digits that read back are used, the
// same text but for the rare float whose shortest reading is not its nearest rounding.
#include "core/FloatText.h"

#include <charconv>
#include <cstdio>
#include <cstdlib>

namespace gnomon {

std::string shortestText(float v) {
    char buf[64];
#if defined(__cpp_lib_to_chars)
    const auto res = std::to_chars(buf, buf + sizeof buf - 1, v);
    *res.ptr = '\0';
#else
    for (int precision = 1; precision <= 9; ++precision) {
        std::snprintf(buf, sizeof buf, "%.*g", precision, double(v));
        if (std::strtof(buf, nullptr) == v) break;
    }
#endif
    return buf;
}

}  // namespace gnomon
