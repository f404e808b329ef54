#include "shadow/ShadowMath.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace gnomon::shadow {

glm::mat4 textureFromClip() {
    glm::mat4 m(0.5f);
    m[3] = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    return m;
}

glm::mat4 safeLookAt(const glm::vec3& eye, const glm::vec3& centre, const glm::vec3& up) {
    const glm::vec3 forward = glm::normalize(centre - eye);
    glm::vec3 u = up;
    // Not normalised first: a zero `up` must take the fallback, not produce NaN.
    const float upLength = glm::length(u);
    if (!(upLength > 0.0f) || !(glm::length(glm::cross(forward, u)) >= 1e-3f * upLength)) {
        const glm::vec3 a = glm::abs(forward);
        u = (a.x <= a.y && a.x <= a.z) ? glm::vec3(1, 0, 0)
            : (a.y <= a.z)             ? glm::vec3(0, 1, 0)
                                       : glm::vec3(0, 0, 1);
    }
    return glm::lookAt(eye, centre, u);
}

glm::mat4 viewFromWorld(const Camera& camera) {
    return safeLookAt(camera.eye, camera.centre, camera.up);
}

glm::mat4 clipFromView(const Camera& camera, float aspect) {
    const float a = camera.aspect > 0.0f ? camera.aspect : aspect;
    if (camera.projection == Projection::Orthographic) {
        return glm::ortho(camera.left, camera.right, camera.bottom, camera.top, camera.near,
                          camera.far);
    }
    return glm::perspective(glm::radians(camera.fovyDegrees), a, camera.near, camera.far);
}

namespace {

// Depth range of the bounds' corners in front of a light camera (view looks down -z).
void depthRange(const Aabb& bounds, const glm::mat4& lightFromWorld, float& nearest,
                float& farthest) {
    nearest = std::numeric_limits<float>::max();
    farthest = std::numeric_limits<float>::lowest();
    for (const glm::vec3& c : bounds.corners()) {
        const float d = -(lightFromWorld * glm::vec4(c, 1.0f)).z;
        nearest = std::min(nearest, d);
        farthest = std::max(farthest, d);
    }
}

LightCameraFrame fromNumbers(const ShadowCamera& c, const glm::mat4& lightFromWorld, int mapSize) {
    LightCameraFrame f;
    f.lightFromWorld = lightFromWorld;
    f.near = c.near;
    f.far = c.far;
    f.orthographic = c.projection == Projection::Orthographic;
    f.kind = f.orthographic ? FrameKind::Orthographic : FrameKind::Perspective;
    if (f.orthographic) {
        f.clipFromLight = glm::ortho(c.left, c.right, c.bottom, c.top, c.near, c.far);
        f.texelWorldSize = std::max(c.right - c.left, c.top - c.bottom) / float(mapSize);
    } else {
        const float fovy = glm::radians(c.fovyDegrees);
        f.clipFromLight = glm::perspective(fovy, c.aspect, c.near, c.far);
        f.texelWorldSize = 2.0f * std::tan(0.5f * fovy) * std::max(1.0f, c.aspect) / float(mapSize);
    }
    return f;
}

// Orthographic camera along `direction` holding the whole box, near/far at its corners.
LightCameraFrame fitOrthographic(const glm::vec3& direction, const Aabb& bounds, int mapSize) {
    LightCameraFrame f;
    f.orthographic = true;
    f.kind = FrameKind::Orthographic;
    const glm::vec3 centre = bounds.centre();
    const float radius = std::max(bounds.radius(), 1e-4f);
    const glm::vec3 eye = centre - glm::normalize(direction) * (2.0f * radius);
    f.lightFromWorld = safeLookAt(eye, centre, glm::vec3(0, 1, 0));
    Aabb ls = bounds.transformed(f.lightFromWorld);
    // A margin keeps the outermost texels and depths inside the map: relative to the box,
    // and never below the float rounding of the view transform, whose translation grows with
    // the distance from the world origin (a small box far away).
    const float worldScale = glm::length(centre) + 2.0f * radius;
    const float margin = std::max(1e-3f * radius, 16.0f * FLT_EPSILON * worldScale);
    f.near = -ls.max.z - margin;
    f.far = -ls.min.z + margin;
    const float w = ls.max.x - ls.min.x + 2 * margin, h = ls.max.y - ls.min.y + 2 * margin;
    f.clipFromLight = glm::ortho(ls.min.x - margin, ls.max.x + margin, ls.min.y - margin,
                                 ls.max.y + margin, f.near, f.far);
    f.texelWorldSize = std::max(w, h) / float(mapSize);
    return f;
}

// Perspective camera from `eye` along `axis` with fovy, near/far fitted to the box.
LightCameraFrame fitPerspective(const glm::vec3& eye, const glm::vec3& axis, float fovyRadians,
                                const Aabb& bounds, int mapSize) {
    LightCameraFrame f;
    f.lightFromWorld = safeLookAt(eye, eye + axis, glm::vec3(0, 1, 0));
    float nearest = 0.0f, farthest = 0.0f;
    depthRange(bounds, f.lightFromWorld, nearest, farthest);
    // The light may sit inside the bounds: keep near positive, at most 1/1000 of far,
    // so depth precision stays usable (SPEC S12).
    f.far = std::max(farthest * 1.01f, 1e-3f);
    f.near = std::clamp(nearest * 0.99f, f.far * 1e-3f, f.far * 0.999f);
    f.clipFromLight = glm::perspective(fovyRadians, 1.0f, f.near, f.far);
    f.texelWorldSize = 2.0f * std::tan(0.5f * fovyRadians) / float(mapSize);
    return f;
}

// Six faces around the light reaching the farthest corner; near as close as depth precision
// allows (geometry nearer than near still casts: the pass clamps depth for fitted lights).
LightCameraFrame fitCube(const glm::vec3& position, const Aabb& bounds, int mapSize) {
    LightCameraFrame f;
    f.kind = FrameKind::Cube;
    f.lightFromWorld = glm::translate(glm::mat4(1.0f), -position);
    float farthest = 0.0f;
    for (const glm::vec3& c : bounds.corners()) {
        farthest = std::max(farthest, glm::length(c - position));
    }
    const glm::vec3 nearestPoint = glm::clamp(position, bounds.min, bounds.max);
    const float nearest = glm::length(nearestPoint - position);
    f.far = std::max(farthest * 1.01f, 1e-3f);
    f.near = std::clamp(nearest * 0.99f, f.far * 1e-3f, f.far * 0.5f);
    f.clipFromLight = glm::perspective(glm::radians(90.0f), 1.0f, f.near, f.far);
    f.texelWorldSize = 2.0f / float(mapSize);  // tan(45 deg) = 1: two units per face at d = 1
    return f;
}

}  // namespace

bool outsideClipVolume(const Aabb& box, const glm::mat4& clipFromWorld, bool ignoreNear) {
    if (box.empty()) return true;
    glm::vec4 clip[8];
    const auto corners = box.corners();
    for (int i = 0; i < 8; ++i)
        clip[i] = clipFromWorld * glm::vec4(corners[size_t(i)], 1.0f);
    // Plane k: -w <= x, x <= w, -w <= y, y <= w, -w <= z, z <= w.
    for (int plane = 0; plane < 6; ++plane) {
        if (ignoreNear && plane == 4) continue;
        const int axis = plane / 2;
        const float sign = plane % 2 ? 1.0f : -1.0f;
        bool allOutside = true;
        for (int i = 0; i < 8 && allOutside; ++i) {
            allOutside = sign * clip[i][axis] > clip[i].w;
        }
        if (allOutside) return true;
    }
    return false;
}

bool outsideCube(const Aabb& box, const LightCameraFrame& cube) {
    if (box.empty()) return true;
    const glm::vec3 eye = glm::vec3(glm::inverse(cube.lightFromWorld)[3]);
    const glm::vec3 nearest = glm::clamp(eye, box.min, box.max);
    return glm::length(nearest - eye) > cube.far;
}

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

LightCameraFrame cascadeFrame(const glm::vec3& lightDirection, const Camera& view, float aspect,
                              float splitNear, float splitFar, const Aabb& sceneBounds,
                              int mapSize) {
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
    radius = std::ceil(radius * 16.0f) / 16.0f;  // a steady size, not float noise

    LightCameraFrame f;
    f.kind = FrameKind::Orthographic;
    f.orthographic = true;
    const glm::vec3 dir = glm::normalize(lightDirection);
    // Rotation only (origin at the world origin), so snapping happens in a fixed grid.
    const glm::mat4 rotation = safeLookAt(glm::vec3(0.0f), dir, glm::vec3(0, 1, 0));
    glm::vec3 lsCentre = glm::vec3(rotation * glm::vec4(centre, 1.0f));
    const float texel = 2.0f * radius / float(mapSize);
    lsCentre.x = std::floor(lsCentre.x / texel) * texel;
    lsCentre.y = std::floor(lsCentre.y / texel) * texel;
    // Depth: from the sphere's far side back to the farthest scene corner towards the light.
    const Aabb lsScene = sceneBounds.transformed(rotation);
    const float zFar = lsCentre.z - radius;                            // farthest from the light
    const float zNear = std::max(lsCentre.z + radius, lsScene.max.z);  // nearest to the light
    f.lightFromWorld =
        glm::translate(glm::mat4(1.0f), -glm::vec3(lsCentre.x, lsCentre.y, 0.0f)) * rotation;
    f.near = -zNear - 1e-3f * radius;
    f.far = -zFar + 1e-3f * radius;
    f.clipFromLight = glm::ortho(-radius, radius, -radius, radius, f.near, f.far);
    f.texelWorldSize = texel;
    return f;
}

glm::mat4 cubeFaceRotation(int face) {
    static const glm::vec3 kForward[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                          {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    static const glm::vec3 kUp[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1},
                                     {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    return glm::lookAt(glm::vec3(0.0f), kForward[face], kUp[face]);
}

glm::mat4 LightCameraFrame::faceClipFromWorld(int face) const {
    return clipFromLight * cubeFaceRotation(face) * lightFromWorld;
}

float cubeStoredDepth(const glm::vec3& d, float near, float far) {
    const float z = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    const float ndc = (far + near) / (far - near) - 2.0f * far * near / ((far - near) * z);
    return 0.5f * ndc + 0.5f;
}

LightCameraFrame lightCameraFrame(const Light& light, const Camera& view, const Aabb& bounds,
                                  int mapSize) {
    const ShadowCamera& c = light.shadowCamera;
    switch (c.policy) {
        case ShadowCameraPolicy::Manual:
            return fromNumbers(c, safeLookAt(light.position, c.target, c.up), mapSize);
        case ShadowCameraPolicy::Course:
            return fromNumbers(c, safeLookAt(light.position, view.centre, view.up), mapSize);
        case ShadowCameraPolicy::Fit:
            break;
    }
    if (bounds.empty()) {
        LightCameraFrame f;
        f.valid = false;
        return f;
    }
    switch (light.type) {
        case LightType::Directional:
            return fitOrthographic(light.direction, bounds, mapSize);
        case LightType::Spot:
            return fitPerspective(
                light.position, glm::normalize(light.direction),
                glm::radians(2.0f * std::clamp(light.outerConeDegrees, 1.0f, 89.0f)), bounds,
                mapSize);
        case LightType::Area:
            // Parallel rays like the sun: the same orthographic fit (the plane only sets
            // the falloff).
            return fitOrthographic(light.direction, bounds, mapSize);
        case LightType::Point:
            return fitCube(light.position, bounds, mapSize);
    }
    return {};
}

}  // namespace gnomon::shadow
