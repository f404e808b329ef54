// Image comparison for goldens: max channel difference, fraction of pixels over a threshold
// and mean difference, plus a visual diff (DESIGN habit 6: goldens with stated tolerances).
#include <algorithm>
#include <cstdlib>

#include "gnomon/Error.h"
#include "gnomon/Image.h"

namespace gnomon {

ImageDiff compareImages(const Image& a, const Image& b, int threshold) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels) {
        throw Error(ErrorKind::InvalidInput,
                    "images differ in shape: " + std::to_string(a.width) + "x" +
                        std::to_string(a.height) + "x" + std::to_string(a.channels) + " vs " +
                        std::to_string(b.width) + "x" + std::to_string(b.height) + "x" +
                        std::to_string(b.channels));
    }
    const size_t need = size_t(a.width) * a.height * a.channels;
    if (a.pixels.size() != need || b.pixels.size() != need) {
        throw Error(ErrorKind::InvalidInput, "image pixel data does not match its shape");
    }
    ImageDiff d;
    d.diff = Image(a.width, a.height, 3);
    size_t failing = 0;
    double sum = 0.0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const std::uint8_t* pa = a.at(x, y);
            const std::uint8_t* pb = b.at(x, y);
            int worst = 0;
            for (int c = 0; c < a.channels; ++c) {
                const int delta = std::abs(int(pa[c]) - int(pb[c]));
                worst = std::max(worst, delta);
                sum += delta;
                if (c < 3) d.diff.at(x, y)[c] = std::uint8_t(std::min(255, delta * 4));
            }
            if (a.channels < 3) {
                for (int c = a.channels; c < 3; ++c)
                    d.diff.at(x, y)[c] = d.diff.at(x, y)[0];
            }
            d.maxChannelDiff = std::max(d.maxChannelDiff, worst);
            if (worst > threshold) ++failing;
        }
    }
    const double pixels = double(a.width) * a.height;
    d.failingFraction = pixels > 0 ? double(failing) / pixels : 0.0;
    d.meanAbsDiff = pixels > 0 ? sum / (pixels * a.channels) : 0.0;
    return d;
}

}  // namespace gnomon
