// writePng (gnomon/Image.h) with libpng: 8-bit images of 1-4 channels and 16-bit grey ones
// (shadow map depths, which stb cannot write). Writes are atomic (core/AtomicFile.h).
#include <png.h>

#include <bit>
#include <csetjmp>

#include "core/AtomicFile.h"
#include "core/ImageWrite.h"
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

}  // namespace

void writePng(const std::string& path, const Image& image) {
    if (image.channels < 1 || image.channels > 4) {
        throw Error(ErrorKind::InvalidInput,
                    "cannot write '" + path + "': " + std::to_string(image.channels) + " channels");
    }
    checkImageSize(path, image.width, image.height, image.pixels.size(),
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
    checkImageSize(path, image.width, image.height, image.pixels.size(),
                   size_t(image.width) * image.height);
    std::vector<png_bytep> rows(size_t(image.height));
    for (int y = 0; y < image.height; ++y) {
        rows[size_t(y)] = reinterpret_cast<png_bytep>(
            const_cast<std::uint16_t*>(&image.pixels[size_t(y) * image.width]));
    }
    writePngRows(path, image.width, image.height, 16, PNG_COLOR_TYPE_GRAY, rows);
}

}  // namespace gnomon
