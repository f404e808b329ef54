#include "shadow/DepthPacking.h"

#include <cfloat>
#include <cmath>

namespace gnomon::shadow {
namespace {
glm::vec4 pack(float depth, float base) {
    const glm::vec4 shift(1.0f, base, base * base, base * base * base);
    glm::vec4 c = glm::fract(depth * shift);
    // Remove from each channel what the next, finer channel already holds.
    c -= glm::vec4(c.y, c.z, c.w, c.w) * glm::vec4(1.0f / base, 1.0f / base, 1.0f / base, 0.0f);
    return c;
}
float unpack(const glm::vec4& c, float base) {
    return glm::dot(
        c, glm::vec4(1.0f, 1.0f / base, 1.0f / (base * base), 1.0f / (base * base * base)));
}
}  // namespace

glm::vec4 encodeDepth(DepthFormat format, float depth) {
    switch (format) {
        case DepthFormat::R8:
            return {depth, 0.0f, 0.0f, 1.0f};
        case DepthFormat::Rgba8Packed256:
            return pack(depth, 256.0f);
        case DepthFormat::Rgba8Packed255:
            return pack(depth, 255.0f);
        default:
            return glm::vec4(depth);
    }
}

glm::vec4 quantizeUnorm8(const glm::vec4& c) {
    return glm::round(glm::clamp(c, 0.0f, 1.0f) * 255.0f) / 255.0f;
}

float decodeDepth(DepthFormat format, const glm::vec4& c) {
    switch (format) {
        case DepthFormat::R8:
            return c.x;
        case DepthFormat::Rgba8Packed256:
            return unpack(c, 256.0f);
        case DepthFormat::Rgba8Packed255:
            return unpack(c, 255.0f);
        default:
            return c.x;
    }
}

float depthRoundTripBound(DepthFormat format) {
    switch (format) {
        case DepthFormat::R8:
            return 0.5f / 255.0f;  // half a level
        case DepthFormat::Rgba8Packed256:
            // The red channel holds k/256, stored as the nearest k'/255: up to half a level
            // off near depth 0.5 (~0.002; the WebGL Programming Guide's 0.0015 tolerance holds only
            // near 1).
            return 0.5f / 255.0f + 1e-6f;
        case DepthFormat::Rgba8Packed255:
            return 2e-7f;  // float arithmetic, not storage
        case DepthFormat::Depth16:
            return 0.5f / 65535.0f;
        case DepthFormat::Depth24:
            return 0.5f / 16777215.0f;
        case DepthFormat::Depth32F:
            return 6e-8f;
    }
    return 0.0f;
}

}  // namespace gnomon::shadow

namespace gnomon::shadow {

float storedDepthSpacing(DepthFormat format, float stored) {
    switch (format) {
        case DepthFormat::R8:
        case DepthFormat::Rgba8Packed256:
            return 1.0f / 255.0f;
        case DepthFormat::Depth16:
            return 1.0f / 65535.0f;
        case DepthFormat::Depth24:
            return 1.0f / 16777215.0f;
        case DepthFormat::Rgba8Packed255:
            // Exact in 8-bit channels; the decode's float sum (terms up to 1) limits it.
            return 2.0f * FLT_EPSILON;
        case DepthFormat::Depth32F: {
            const float s = std::max(stored, 1e-30f);
            return std::nextafter(s, 2.0f) - s;
        }
    }
    return 0.0f;
}

float toleranceStep(DepthFormat format) {
    return storedDepthSpacing(format, 0.5f);
}

float worldDepthResolution(float z, float near, float far, int bits) {
    // stored(z) = ((f + n) / (f - n) - 2 f n / ((f - n) z)) / 2 + 1/2, so
    // d stored / d z = f n / ((f - n) z^2); one step of 1 / (2^bits - 1) spans its inverse.
    const double steps = std::ldexp(1.0, bits) - 1.0;
    return float((double(far) - near) * double(z) * z / (double(far) * near * steps));
}

}  // namespace gnomon::shadow
