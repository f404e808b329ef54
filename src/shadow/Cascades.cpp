// Cascaded shadow maps for directional lights: where the view's depth range is split
// ("practical split scheme", Zhang et al. 2006, Parallel-Split Shadow Maps) and the
// stabilised orthographic camera of each slice (a bounding sphere for a steady size, an
// origin snapped to whole texels so edges do not shimmer as the view moves). Declared in
// ShadowMath.h with the other light cameras.
#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "shadow/ShadowMath.h"

namespace gnomon::shadow {

std::vector<float> cascadeSplits(float near, float far, int count, float lambda) {
    std::vector<float> splits(size_t(count) + 1);
    for (int i = 0; i <= count; ++i) {
        const float t = float(i) / float(count);
        const float logSplit = near * std::pow(far / near, t);
        const float uniformSplit = near + (far - near) * t;
        splits[size_t(i)] = lambda * logSplit + (1.0f - lambda) * uniformSplit;
    }
    splits.front() = near;
    splits.back() = far;
    return splits;
}

void stabiliseDepthRange(float& nearest, float& farthest) {
    constexpr float kSteps = 2.0f;  // per octave (see the header)
    if (nearest > 0.0f) nearest = std::exp2(std::floor(std::log2(nearest) * kSteps) / kSteps);
    if (farthest > 0.0f) farthest = std::exp2(std::ceil(std::log2(farthest) * kSteps) / kSteps);
}

int autoCascadeCount(float nearest, float farthest) {
    if (!(nearest > 0.0f) || !(farthest > nearest)) return 1;
    const float octaves = std::log2(farthest / nearest) / 3.0f;  // factors of 8
    return std::clamp(1 + int(std::floor(octaves)), 1, 4);
}

LightCameraFrame cascadeFrame(const glm::vec3& lightDirection, const Camera& view, float aspect,
                              float splitNear, float splitFar, const Aabb& sceneBounds, int mapSize,
                              bool stabilise) {
    // The slice's eight corners in world space.
    const glm::mat4 worldFromView = glm::inverse(viewFromWorld(view));
    const float a = view.aspect > 0.0f ? view.aspect : aspect;
    const float tanY = std::tan(0.5f * glm::radians(view.fovyDegrees)), tanX = tanY * a;
    glm::vec3 corners[8];
    for (int i = 0; i < 8; ++i) {
        const float d = (i & 4) ? splitFar : splitNear;
        const glm::vec3 vs((i & 1 ? 1.0f : -1.0f) * tanX * d, (i & 2 ? 1.0f : -1.0f) * tanY * d,
                           -d);
        corners[i] = glm::vec3(worldFromView * glm::vec4(vs, 1.0f));
    }
    // Bounding sphere: centred on the slice's axis where it best fits both end caps.
    const glm::vec3 nearCentre = glm::vec3(worldFromView * glm::vec4(0, 0, -splitNear, 1));
    const glm::vec3 farCentre = glm::vec3(worldFromView * glm::vec4(0, 0, -splitFar, 1));
    const float nearHalf2 = (tanX * tanX + tanY * tanY) * splitNear * splitNear;
    const float farHalf2 = (tanX * tanX + tanY * tanY) * splitFar * splitFar;
    const float length = splitFar - splitNear;
    // Distance t from the near cap where both caps' rims are equally far.
    const float t =
        std::clamp((length * length + farHalf2 - nearHalf2) / (2.0f * length), 0.0f, length);
    const glm::vec3 centre = nearCentre + (farCentre - nearCentre) * (t / length);
    float radius = 0.0f;
    for (const glm::vec3& c : corners)
        radius = std::max(radius, glm::length(c - centre));
    if (stabilise) radius = std::ceil(radius * 16.0f) / 16.0f;  // a steady size, not float noise

    LightCameraFrame f;
    f.kind = FrameKind::Orthographic;
    f.orthographic = true;
    const glm::vec3 dir = glm::normalize(lightDirection);
    // Rotation only (origin at the world origin), so snapping happens in a fixed grid.
    const glm::mat4 rotation = safeLookAt(glm::vec3(0.0f), dir, glm::vec3(0, 1, 0));
    glm::vec3 lsCentre = glm::vec3(rotation * glm::vec4(centre, 1.0f));
    const float texel = 2.0f * radius / float(mapSize);
    if (stabilise) {
        lsCentre.x = std::floor(lsCentre.x / texel) * texel;
        lsCentre.y = std::floor(lsCentre.y / texel) * texel;
    }
    // Depth: from the sphere's far side back to the farthest scene corner towards the light.
    const Aabb lsScene = sceneBounds.transformed(rotation);
    // In depth, the centre on a grid of an eighth of the radius: the depth range, and so the
    // stored depths' scale and offset, change now and then rather than with every move.
    if (stabilise) lsCentre.z = std::ceil(lsCentre.z / (0.125f * radius)) * (0.125f * radius);
    // Farthest from the light, with room for the snap when there is one.
    const float zFar = lsCentre.z - (stabilise ? 1.125f : 1.0f) * radius;
    const float zNear = std::max(lsCentre.z + radius, lsScene.max.z);  // nearest to the light
    f.lightFromWorld =
        glm::translate(glm::mat4(1.0f), -glm::vec3(lsCentre.x, lsCentre.y, 0.0f)) * rotation;
    f.near = -zNear - 1e-3f * radius;
    f.far = -zFar + 1e-3f * radius;
    f.clipFromLight = glm::ortho(-radius, radius, -radius, radius, f.near, f.far);
    f.texelWorldSize = texel;
    return f;
}

}  // namespace gnomon::shadow
