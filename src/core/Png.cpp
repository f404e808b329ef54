// Image files: PNG read with stb_image (written by core/PngWriteLibpng.cpp or, without
// libpng, core/PngWriteStb.cpp); JPEG written with stb_image_write. Writes are atomic
// (core/AtomicFile.h).
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <cctype>
#include <filesystem>
#include <memory>

#include "core/AtomicFile.h"
#include "core/ImageWrite.h"
#include "gnomon/Error.h"
#include "gnomon/Image.h"

namespace gnomon {

void checkImageSize(const std::string& path, int width, int height, std::size_t have,
                    std::size_t need) {
    if (width <= 0 || height <= 0 || have != need) {
        throw Error(ErrorKind::InvalidInput,
                    "cannot write '" + path + "': image is " + std::to_string(width) + "x" +
                        std::to_string(height) + " with " + std::to_string(have) +
                        " samples, expected " + std::to_string(need));
    }
}

namespace {
std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}
}  // namespace

bool imageFormatKnown(const std::string& path) {
    const std::string ext = lowerExtension(path);
    return ext == ".png" || ext == ".jpg" || ext == ".jpeg";
}

void writeImage(const std::string& path, const Image& image) {
    const std::string ext = lowerExtension(path);
    if (ext == ".png") return writePng(path, image);
    if (ext != ".jpg" && ext != ".jpeg") {
        throw Error(ErrorKind::InvalidInput, "cannot write '" + path +
                                                 "': the format follows the extension: .png, .jpg "
                                                 "or .jpeg, got '" +
                                                 (ext.empty() ? "none" : ext) + "'");
    }
    checkImageSize(path, image.width, image.height, image.pixels.size(),
                   size_t(image.width) * image.height * image.channels);
    // Encoded in memory first, so a failed encode writes nothing.
    std::vector<unsigned char> bytes;
    auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<unsigned char>*>(context);
        const auto* d = static_cast<const unsigned char*>(data);
        out->insert(out->end(), d, d + size);
    };
    if (!stbi_write_jpg_to_func(append, &bytes, image.width, image.height, image.channels,
                                image.pixels.data(), 95)) {
        throw Error(ErrorKind::Io, "cannot write '" + path + "': JPEG encoding failed");
    }
    writeFileAtomically(path, [&](std::FILE* f) {
        if (std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size())
            throw Error(ErrorKind::Io, "cannot write '" + path + "'");
    });
}

Image readPng(const std::string& path) {
    int w = 0, h = 0, n = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> data(stbi_load(path.c_str(), &w, &h, &n, 4),
                                                   stbi_image_free);
    if (!data) {
        throw Error(ErrorKind::Io, "cannot read image '" + path + "': " + stbi_failure_reason());
    }
    Image image(w, h, 4);
    std::copy(data.get(), data.get() + image.pixels.size(), image.pixels.begin());
    return image;
}

}  // namespace gnomon
