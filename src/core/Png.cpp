// Image files: PNG written with libpng (8-bit 1-4 channels and 16-bit grey, which stb cannot
// write) and read with stb_image; JPEG written with stb_image_write. Writes are atomic
// (core/AtomicFile.h).
#include <png.h>
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <bit>
#include <cctype>
#include <csetjmp>
#include <filesystem>
#include <memory>

#include "core/AtomicFile.h"
#include "gnomon/Error.h"
#include "gnomon/Image.h"

namespace gnomon {
namespace {

void writePngRows(const std::string& path, int width, int height, int bitDepth, int colourType,
                  const std::vector<png_bytep>& rows) {
    writeFileAtomically(path, [&](std::FILE* f) {
        png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
        png_infop info = png ? png_create_info_struct(png) : nullptr;
        if (!png || !info) {
            png_destroy_write_struct(&png, &info);
            throw Error(ErrorKind::Io, "cannot write '" + path + "': out of memory in libpng");
        }
        if (setjmp(png_jmpbuf(png))) {
            png_destroy_write_struct(&png, &info);
            throw Error(ErrorKind::Io, "cannot write '" + path + "': libpng failed");
        }
        png_init_io(png, f);
        png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), bitDepth, colourType,
                     PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_write_info(png, info);
        // PNG stores 16-bit samples big-endian; ours are native.
        if (bitDepth == 16 && std::endian::native == std::endian::little) png_set_swap(png);
        png_write_image(png, const_cast<png_bytepp>(rows.data()));
        png_write_end(png, nullptr);
        png_destroy_write_struct(&png, &info);
    });
}

void checkSize(const std::string& path, int width, int height, size_t have, size_t need) {
    if (width <= 0 || height <= 0 || have != need) {
        throw Error(ErrorKind::InvalidInput,
                    "cannot write '" + path + "': image is " + std::to_string(width) + "x" +
                        std::to_string(height) + " with " + std::to_string(have) +
                        " samples, expected " + std::to_string(need));
    }
}

}  // namespace

void writePng(const std::string& path, const Image& image) {
    if (image.channels < 1 || image.channels > 4) {
        throw Error(ErrorKind::InvalidInput,
                    "cannot write '" + path + "': " + std::to_string(image.channels) + " channels");
    }
    checkSize(path, image.width, image.height, image.pixels.size(),
              size_t(image.width) * image.height * image.channels);
    static const int kTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                 PNG_COLOR_TYPE_RGB_ALPHA};
    std::vector<png_bytep> rows(size_t(image.height));
    for (int y = 0; y < image.height; ++y) {
        rows[size_t(y)] = const_cast<png_bytep>(image.at(0, y));
    }
    writePngRows(path, image.width, image.height, 8, kTypes[image.channels - 1], rows);
}

void writePng(const std::string& path, const Image16& image) {
    checkSize(path, image.width, image.height, image.pixels.size(),
              size_t(image.width) * image.height);
    std::vector<png_bytep> rows(size_t(image.height));
    for (int y = 0; y < image.height; ++y) {
        rows[size_t(y)] = reinterpret_cast<png_bytep>(
            const_cast<std::uint16_t*>(&image.pixels[size_t(y) * image.width]));
    }
    writePngRows(path, image.width, image.height, 16, PNG_COLOR_TYPE_GRAY, rows);
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
    checkSize(path, image.width, image.height, image.pixels.size(),
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
