// writePng (gnomon/Image.h) where libpng is not built (the web build; CMake picks this file
// instead of PngWriteLibpng.cpp): 8-bit images of 1-4 channels through stb_image_write,
// encoded in memory and written atomically (core/AtomicFile.h). stb writes no 16-bit PNG,
// so the shadow map depths (Image16) are refused with a sentence that says so.
#include <stb/stb_image_write.h>

#include <vector>

#include "core/AtomicFile.h"
#include "core/ImageWrite.h"
#include "gnomon/Error.h"
#include "gnomon/Image.h"

namespace gnomon {

void writePng(const std::string& path, const Image& image) {
    if (image.channels < 1 || image.channels > 4) {
        throw Error(ErrorKind::InvalidInput,
                    "cannot write '" + path + "': " + std::to_string(image.channels) + " channels");
    }
    checkImageSize(path, image.width, image.height, image.pixels.size(),
                   size_t(image.width) * image.height * image.channels);
    // Encoded first, so a failed encode writes nothing.
    std::vector<unsigned char> bytes;
    auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<unsigned char>*>(context);
        const auto* d = static_cast<const unsigned char*>(data);
        out->insert(out->end(), d, d + size);
    };
    if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, image.channels,
                                image.pixels.data(), image.width * image.channels)) {
        throw Error(ErrorKind::Io, "cannot write '" + path + "': PNG encoding failed");
    }
    writeFileAtomically(path, [&](std::FILE* f) {
        if (std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size())
            throw Error(ErrorKind::Io, "cannot write '" + path + "'");
    });
}

void writePng(const std::string& path, const Image16& image) {
    checkImageSize(path, image.width, image.height, image.pixels.size(),
                   size_t(image.width) * image.height);
    throw Error(ErrorKind::InvalidInput,
                "cannot write '" + path +
                    "': 16-bit PNG needs libpng, which this build of gnomon does not have");
}

}  // namespace gnomon
