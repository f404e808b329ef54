// What the image writers share (internal): the size check, in one wording for every format.
// writePng itself (gnomon/Image.h) lives in one of two files that CMake picks: libpng's
// (PngWriteLibpng.cpp) natively, stb's (PngWriteStb.cpp) where libpng is not built (the web
// build).
#pragma once

#include <cstddef>
#include <string>

namespace gnomon {

// Throws gnomon::Error (InvalidInput) naming `path` unless the image is at least 1x1 and
// holds `need` samples.
void checkImageSize(const std::string& path, int width, int height, std::size_t have,
                    std::size_t need);

}  // namespace gnomon
