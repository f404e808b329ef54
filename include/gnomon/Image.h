// Images in memory and on disk. `Image` is 8 bits per channel (1-4 channels, rows top to
// bottom), `Image16` is 16-bit greyscale (shadow maps). PNG writes go to a temporary file
// in the same folder that is renamed into place, so a failed write leaves nothing behind.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace gnomon {

struct Image {
    int width = 0;
    int height = 0;
    int channels = 4;
    std::vector<std::uint8_t> pixels;  // row-major, top row first, `channels` bytes per pixel

    Image() = default;
    Image(int w, int h, int c) : width(w), height(h), channels(c), pixels(size_t(w) * h * c) {}
    std::uint8_t* at(int x, int y) { return &pixels[(size_t(y) * width + x) * channels]; }
    const std::uint8_t* at(int x, int y) const {
        return &pixels[(size_t(y) * width + x) * channels];
    }
    bool empty() const { return pixels.empty(); }
};

struct Image16 {
    int width = 0;
    int height = 0;
    std::vector<std::uint16_t> pixels;  // greyscale, row-major, top row first
};

// Write as PNG (8-bit with `channels` channels, or 16-bit grey). Throws gnomon::Error.
void writePng(const std::string& path, const Image& image);
void writePng(const std::string& path, const Image16& image);
// Write in the format `path`'s extension names: .png (as writePng), .jpg or .jpeg (JPEG,
// quality 95, alpha dropped). Any other extension is refused (InvalidInput) before anything
// is written.
void writeImage(const std::string& path, const Image& image);
// True when writeImage accepts `path`'s extension.
bool imageFormatKnown(const std::string& path);
// Read a PNG as 8-bit RGBA. Throws gnomon::Error naming the file.
Image readPng(const std::string& path);
// Write text (JSON, CSV, SVG) the same way: to a temporary file, then renamed into place.
void writeTextFile(const std::string& path, const std::string& text);

// Difference between two images of the same size, as goldens are judged.
struct ImageDiff {
    int maxChannelDiff = 0;        // largest |a-b| over all channels and pixels, 0..255
    double failingFraction = 0.0;  // pixels where some channel differs by more than threshold
    double meanAbsDiff = 0.0;      // mean |a-b| over all channels, 0..255
    Image diff;                    // RGB, |a-b| scaled x4 so small errors show
};
ImageDiff compareImages(const Image& a, const Image& b, int threshold);

}  // namespace gnomon
