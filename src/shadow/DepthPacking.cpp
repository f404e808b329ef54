#include "shadow/DepthPacking.h"

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
            // off near depth 0.5 (~0.002; the book's 0.0015 tolerance holds only near 1).
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
