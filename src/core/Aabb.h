// Axis-aligned bounding boxes: the unit of shadow-camera fitting.
#pragma once

#include <array>
#include <limits>

#include <glm/glm.hpp>

namespace gnomon {

struct Aabb {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{std::numeric_limits<float>::lowest()};

    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void extend(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Aabb& b) {
        if (!b.empty()) {
            extend(b.min);
            extend(b.max);
        }
    }
    glm::vec3 centre() const { return 0.5f * (min + max); }
    glm::vec3 extent() const { return max - min; }
    float radius() const { return 0.5f * glm::length(max - min); }
    // Distance from `p` to the box's nearest point (0 inside).
    float distanceTo(const glm::vec3& p) const { return glm::length(glm::clamp(p, min, max) - p); }
    std::array<glm::vec3, 8> corners() const {
        std::array<glm::vec3, 8> c;
        for (int i = 0; i < 8; ++i) {
            c[size_t(i)] = {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y,
                            (i & 4) ? max.z : min.z};
        }
        return c;
    }
    // The box holding this box's corners after `m` (an affine transform).
    Aabb transformed(const glm::mat4& m) const {
        Aabb out;
        if (empty()) return out;
        for (const glm::vec3& c : corners())
            out.extend(glm::vec3(m * glm::vec4(c, 1.0f)));
        return out;
    }
};

}  // namespace gnomon
