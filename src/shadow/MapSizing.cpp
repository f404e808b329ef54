#include "shadow/MapSizing.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

namespace gnomon::shadow {

namespace {
std::size_t texelBytes(DepthFormat f) {
    if (f == DepthFormat::Depth16) return 2;
    return isColourFormat(f) ? 8 : 4;  // colour formats: RGBA8 beside a 24-bit depth test
}
}  // namespace

int neededMapSize(const Light& light, const Camera& view, int width, int height, int largest) {
    if (!(light.range > 0.0f) || (light.type != LightType::Point && light.type != LightType::Spot))
        return 0;
    const float side = float(std::max(width, height));
    float radiusPixels = side;  // the camera inside the range: all of the picture
    if (view.projection == Projection::Orthographic) {
        radiusPixels =
            light.range / std::max(0.5f * (view.top - view.bottom), 1e-30f) * 0.5f * float(height);
    } else {
        const float d = glm::length(light.position - view.eye);
        if (d > light.range) {
            const float s = light.range / d;
            const float tanAngle = s / std::sqrt(1.0f - s * s);
            radiusPixels =
                tanAngle / std::tan(glm::radians(0.5f * view.fovyDegrees)) * 0.5f * float(height);
        }
    }
    const float pixels = std::min(2.0f * radiusPixels, side);
    const float want = kNeededTexelsPerPixel * pixels;
    int size = kMinNeededMapSize;
    for (int k = 1; size < largest && float(size) < want; ++k)
        size = neededSizeStep(k);
    return std::min(size, largest);
}

int neededSizeStep(int k) {
    const int octave = kMinNeededMapSize << (k / 2);
    if (k % 2 == 0) return octave;
    return int(float(octave) * std::numbers::sqrt2_v<float>) / 4 * 4;
}

int windowMapSize(float fittedTexel, float wholeTexel, int size, int held) {
    if (!(fittedTexel > 0.0f) || !(wholeTexel > 0.0f) || size <= kMinNeededMapSize) return size;
    const float want = float(size) * fittedTexel / wholeTexel;  // the window's width in texels
    int least = size;  // halved while half still holds the window's texels
    while (least / 2 >= kMinNeededMapSize && float(least / 2) >= want)
        least /= 2;
    return held >= least && held <= size ? held : least;
}

std::size_t largestArrayBytes(const MapLayout& l) {
    const std::size_t maps = std::size_t(l.size2D) * std::size_t(l.size2D) *
                             std::size_t(l.layers2D) * texelBytes(l.format2D);
    const std::size_t cubes = std::size_t(l.sizeCube) * std::size_t(l.sizeCube) * 6u *
                              std::size_t(l.cubes) * texelBytes(l.formatCube);
    return std::max(maps, cubes);
}

}  // namespace gnomon::shadow
