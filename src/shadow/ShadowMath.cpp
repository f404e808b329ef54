#include "shadow/ShadowMath.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/SceneUtil.h"

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

// The boxes Fit works with in one frame: visible receivers (clipped to the view frustum's
// box) and all casters.
struct FitBoxes {
    std::vector<Aabb> receivers;
    const std::vector<Aabb>* casters = nullptr;
    bool snap = false;           // the fit follows the view: keep it steady
    HeldExtent* held = nullptr;  // with snap: the extent kept from the previous frame
};

// `receivers` false: only the casters (a fit to view samples needs no receiver boxes).
FitBoxes visibleReceivers(const FitScene& scene, bool receivers = true) {
    FitBoxes f;
    f.casters = &scene.casters;
    f.snap = scene.viewKnown && scene.stabilise;
    if (!receivers) return f;
    std::array<glm::vec3, 8> frustum{};
    if (scene.viewKnown) frustum = frustumCorners(scene.viewClipFromWorld);
    for (const Aabb& r : scene.receivers) {
        if (r.empty()) continue;
        if (!scene.viewKnown) {
            f.receivers.push_back(r);
            continue;
        }
        // Rounding must not grow the box, nor empty a flat one (a ground plane has no
        // thickness: its clipped points may all round to one side of it).
        const Aabb clipped = clipToFrustum(r, scene.viewClipFromWorld, frustum).box();
        if (!clipped.empty()) f.receivers.push_back(clampInto(clipped, r));
    }
    return f;
}

// Rounds `x` up to a step of 1/16 of its power of two: few distinct sizes, at most 1/16 more.
float quantizeUp(float x) {
    const float step = std::exp2(std::ceil(std::log2(std::max(x, 1e-20f))) - 4.0f);
    return std::ceil(x / step) * step;
}

// The rotation from world into a directional light's space: a turn only, so a snapped
// origin stays on one grid whatever the view does.
glm::mat4 lightRotation(const glm::vec3& direction) {
    return safeLookAt(glm::vec3(0.0f), glm::normalize(direction), glm::vec3(0, 1, 0));
}

// The stabilised box of a fit that follows the view, in place: from the needed box
// [lo, hi] x [zFar, zNear] in light space, a quantised size with room for the origin's snap
// and the origin on a multiple of a texel, so the same inputs up to a texel give the same
// camera. The shorter side is the longer one over a power of two: under a low sun the
// receivers stretch along the light, and a square would spend the short axis's texels on
// nothing (ToyCar on its ground, sun 8 degrees high: 0.48 % misclassified square, 0.21 %
// so), while two sides quantised apart would each step on their own, twice the steps a
// moving view sees as the map's grid jumping (Sponza's dolly: 0.09 % flicker per frame).
void snapExtent(int mapSize, glm::vec2& lo, glm::vec2& hi, float& zNear, float& zFar) {
    const glm::vec2 size = hi - lo;
    const float pad = 1.0f - 4.0f / float(mapSize);
    const int longAxis = size.x >= size.y ? 0 : 1;
    const float longSide = quantizeUp(size[longAxis] / pad);
    const float shortNeeded = std::max(size[1 - longAxis] / pad, longSide / 1024.0f);
    glm::vec2 side;
    side[longAxis] = longSide;
    side[1 - longAxis] = longSide / std::exp2(std::floor(std::log2(longSide / shortNeeded)));
    const glm::vec2 texel = side / float(mapSize);
    const glm::vec2 centre = 0.5f * (lo + hi);
    lo = glm::floor((centre - 0.5f * side) / texel) * texel;
    hi = lo + side;
    // Depth: a quantised range from a near plane on a grid of 1/16 of it, so the stored
    // depths' scale and offset change now and then, not with every move of the view.
    const float step = quantizeUp(zNear - zFar) / 16.0f;
    const float range = quantizeUp(zNear - zFar + step);  // room for the near plane's snap
    zNear = std::ceil(zNear / step) * step;
    zFar = zNear - range;
}

// snapExtent, or the extent `held` from the previous frame while it serves (HeldExtent);
// `held` then holds this frame's.
void steadyExtent(HeldExtent* held, const glm::mat4& rotation, int mapSize, glm::vec2& lo,
                  glm::vec2& hi, float& zNear, float& zFar) {
    const glm::vec2 neededLo = lo, neededHi = hi;
    const float neededNear = zNear, neededFar = zFar;
    snapExtent(mapSize, lo, hi, zNear, zFar);
    if (held == nullptr) return;
    const bool serves = held->valid && held->mapSize == mapSize && held->rotation == rotation &&
                        glm::all(glm::lessThanEqual(held->lo, neededLo)) &&
                        glm::all(glm::greaterThanEqual(held->hi, neededHi)) &&
                        held->zNear >= neededNear && held->zFar <= neededFar &&
                        glm::all(glm::lessThanEqual(held->hi - held->lo, kHoldSlack * (hi - lo))) &&
                        held->zNear - held->zFar <= kHoldSlack * (zNear - zFar);
    if (serves) {
        lo = held->lo;
        hi = held->hi;
        zNear = held->zNear;
        zFar = held->zFar;
        return;
    }
    *held = {true, rotation, mapSize, lo, hi, zNear, zFar};
}

// Orthographic camera through `rotation`: across the light, the receivers' extent
// (`receivers`, in light space) where a caster overlaps it; in depth, from the nearest such
// caster to the farthest receiver.
LightCameraFrame fitOrthographic(const glm::mat4& rotation, const Aabb& receivers,
                                 const FitBoxes& boxes, int mapSize) {
    LightCameraFrame f;
    f.orthographic = true;
    f.kind = FrameKind::Orthographic;
    f.valid = false;
    if (receivers.empty()) return f;
    Aabb casters;
    for (const Aabb& c : *boxes.casters) {
        if (c.empty()) continue;
        const Aabb ls = c.transformed(rotation);
        // Light space looks down -z: a caster entirely farther than every receiver, or beside
        // them all, cannot shadow one.
        if (ls.max.z < receivers.min.z || ls.max.x < receivers.min.x ||
            ls.min.x > receivers.max.x || ls.max.y < receivers.min.y ||
            ls.min.y > receivers.max.y) {
            continue;
        }
        casters.extend(ls);
    }
    if (casters.empty()) return f;
    glm::vec2 lo = glm::max(glm::vec2(receivers.min), glm::vec2(casters.min));
    glm::vec2 hi = glm::min(glm::vec2(receivers.max), glm::vec2(casters.max));
    float zNear = std::max(casters.max.z, receivers.min.z);  // nearest to the light
    float zFar = receivers.min.z;                            // farthest from it
    // A margin keeps the outermost texels and depths inside the map: relative to the box
    // on each axis, and never below the float rounding of light-space coordinates, which
    // grows with their distance from the world origin (a small box far away).
    const float worldScale =
        std::max({glm::length(glm::vec3(receivers.max)), glm::length(glm::vec3(receivers.min)),
                  glm::length(glm::vec3(casters.max)), glm::length(glm::vec3(casters.min))});
    const glm::vec3 margin = glm::max(1e-3f * glm::vec3(hi - lo, zNear - zFar),
                                      glm::vec3(16.0f * FLT_EPSILON * worldScale));
    lo -= glm::vec2(margin);
    hi += glm::vec2(margin);
    zNear += margin.z;
    zFar -= margin.z;
    if (boxes.snap) steadyExtent(boxes.held, rotation, mapSize, lo, hi, zNear, zFar);
    const glm::vec2 size = hi - lo;
    f.valid = true;
    f.lightFromWorld = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -zNear)) * rotation;
    f.near = 0.0f;
    f.far = zNear - zFar;
    f.clipFromLight = glm::ortho(lo.x, hi.x, lo.y, hi.y, f.near, f.far);
    f.texelWorldSize = std::max(size.x, size.y) / float(mapSize);
    return f;
}

constexpr float kNoEnd = std::numeric_limits<float>::max();

// What a directional light's map must cover, in its light space: with view samples, those
// whose view depth lies in [depthFrom, depthTo]; without, the visible receivers' boxes.
Aabb receiversInLight(const FitScene& scene, const FitBoxes& boxes, const glm::vec3& direction,
                      float depthFrom, float depthTo) {
    const glm::mat4 rotation = lightRotation(direction);
    if (scene.samples) return samplesInLight(*scene.samples, rotation, depthFrom, depthTo);
    Aabb receivers;
    for (const Aabb& r : boxes.receivers)
        receivers.extend(r.transformed(rotation));
    return receivers;
}

// A perspective frame through `lightFromWorld` (a look-at) whose image is the window
// [lo, hi] of tan units (x / -z, y / -z): far at the farthest receiver corner inside the
// window's pyramid (or at `farthest` when the caller knows it), near at the nearest caster
// that can shadow one.
LightCameraFrame fitFrustum(const glm::mat4& lightFromWorld, glm::vec2 lo, glm::vec2 hi,
                            const FitBoxes& boxes, int mapSize, float farthest = 0.0f) {
    LightCameraFrame f;
    f.lightFromWorld = lightFromWorld;
    f.valid = false;
    auto pyramid = [&](float near, float far) {
        return glm::frustum(lo.x * near, hi.x * near, lo.y * near, hi.y * near, near, far);
    };
    // The pyramid's four side planes (far pushed out of reach): what the map can see at all.
    const glm::mat4 sides = pyramid(1.0f, 1e30f) * lightFromWorld;
    const bool fromBoxes = !(farthest > 0.0f);
    for (std::size_t i = 0; fromBoxes && i < boxes.receivers.size(); ++i) {
        const Aabb& r = boxes.receivers[i];
        if (outsideClipVolume(r, sides, true)) continue;
        float nearest = 0.0f, far = 0.0f;
        depthRange(r, lightFromWorld, nearest, far);
        farthest = std::max(farthest, far);
    }
    if (!(farthest > 0.0f)) return f;
    // Near at the nearest point of a caster inside the pyramid (not the nearest corner of
    // its box: a floor reaching behind the light would pull near to ~0 and waste the depth
    // precision of the whole map). Clipped to the pyramid from 1/1000 of far to far.
    const glm::mat4 volume = pyramid(farthest * 1e-3f, farthest * 1.01f) * lightFromWorld;
    const std::array<glm::vec3, 8> volumeCorners = frustumCorners(volume);
    float nearestCaster = std::numeric_limits<float>::max();
    for (const Aabb& c : *boxes.casters) {
        if (c.empty() || outsideClipVolume(c, volume, false)) continue;
        const ClippedPoints inside = clipToFrustum(c, volume, volumeCorners);
        for (int i = 0; i < inside.count; ++i) {
            const float d = -(lightFromWorld * glm::vec4(inside.points[size_t(i)], 1.0f)).z;
            nearestCaster = std::min(nearestCaster, d);
        }
    }
    if (nearestCaster == std::numeric_limits<float>::max()) return f;
    // The light may sit inside the bounds: keep near positive, at most 1/1000 of far,
    // so depth precision stays usable.
    f.valid = true;
    f.far = std::max(farthest * 1.01f, 1e-3f);
    f.near = std::clamp(nearestCaster * 0.99f, f.far * 1e-3f, f.far * 0.999f);
    f.clipFromLight = pyramid(f.near, f.far);
    // At distance 1 along the axis (the shader scales by clip w, that distance).
    f.texelWorldSize = std::max(hi.x - lo.x, hi.y - lo.y) / float(mapSize);
    return f;
}

// Perspective camera from `eye` along `axis` with a square fovy (spot lights' cones).
LightCameraFrame fitPerspective(const glm::vec3& eye, const glm::vec3& axis, float fovyRadians,
                                const FitBoxes& boxes, int mapSize) {
    const float t = std::tan(0.5f * fovyRadians);
    return fitFrustum(safeLookAt(eye, eye + axis, glm::vec3(0, 1, 0)), glm::vec2(-t), glm::vec2(t),
                      boxes, mapSize);
}

// Six faces around the light reaching the farthest receiver corner; near just before the
// nearest caster, no nearer than depth precision allows (geometry nearer than near still
// casts: the pass clamps depth for fitted lights).
LightCameraFrame fitCube(const glm::vec3& position, const FitBoxes& boxes, int mapSize) {
    LightCameraFrame f;
    f.kind = FrameKind::Cube;
    f.lightFromWorld = glm::translate(glm::mat4(1.0f), -position);
    f.valid = false;
    float farthest = 0.0f;
    for (const Aabb& r : boxes.receivers) {
        for (const glm::vec3& c : r.corners())
            farthest = std::max(farthest, glm::length(c - position));
    }
    if (!(farthest > 0.0f)) return f;
    // A face's depth is the distance along its axis, the largest of |dx|, |dy|, |dz|, which is
    // as small as 1/sqrt(3) of the Euclidean distance towards a face's corners. A near plane
    // at the Euclidean distance cuts into casters there: depth clamp stores them at 0, the
    // receivers they shadow also lie in front of near (same ray, same face), their reference
    // depth is <= 0 too and the comparison passes: lit. So near is the nearest caster's
    // depth along the axes. Clamping the light into the box minimises every |d| at once, so
    // it also gives the box's smallest largest-component. Casters beyond every receiver
    // (Euclidean) shadow none and are not waited for.
    float nearestCaster = std::numeric_limits<float>::max();
    for (const Aabb& c : *boxes.casters) {
        if (c.empty()) continue;
        const glm::vec3 d = glm::abs(glm::clamp(position, c.min, c.max) - position);
        if (glm::length(d) <= farthest) {
            nearestCaster = std::min(nearestCaster, std::max({d.x, d.y, d.z}));
        }
    }
    if (nearestCaster == std::numeric_limits<float>::max()) return f;
    f.valid = true;
    f.far = std::max(farthest * 1.01f, 1e-3f);
    f.near = std::clamp(nearestCaster * 0.99f, f.far * 1e-3f, f.far * 0.5f);
    f.clipFromLight = glm::perspective(glm::radians(90.0f), 1.0f, f.near, f.far);
    f.texelWorldSize = 2.0f / float(mapSize);  // tan(45 deg) = 1: two units per face at d = 1
    return f;
}

// A point light: when the view's samples all lie in a window no wider than a cube face's
// (2 x 2 tan units) around their mean direction, one frustum over that window: never
// coarser than a cube face on its axis and often many times finer (a lamp over a small model
// spends a few percent of a cube on what the view sees). Else the cube. A few texels of
// margin keep filter taps at the window's rim inside the map.
LightCameraFrame fitPoint(const glm::vec3& position, const ViewSamples* samples,
                          const FitBoxes& boxes, int mapSize) {
    glm::vec3 axis(0.0f);
    SampleWindow window;
    if (!samples || !samplesDirection(*samples, position, axis))
        return fitCube(position, boxes, mapSize);
    const float n = float(std::max(mapSize, 16));
    if (boxes.snap) {
        // Steady while the view moves, as the orthographic fit is: the axis on a grid of
        // half degrees, each side of the window a quantised size with its corner on its own
        // texel grid, far quantised; small camera moves leave the map as it was.
        const float step = glm::radians(0.5f);
        const float yaw = std::round(std::atan2(axis.x, -axis.z) / step) * step;
        const float pitch = std::round(std::asin(std::clamp(axis.y, -1.0f, 1.0f)) / step) * step;
        axis = {std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
    }
    const glm::mat4 lightFromWorld = safeLookAt(position, position + axis, glm::vec3(0, 1, 0));
    if (!samplesWindow(*samples, lightFromWorld, window)) return fitCube(position, boxes, mapSize);
    // A few texels of margin keep filter taps at the window's rim inside the map.
    glm::vec2 size = glm::max(window.hi - window.lo, 1e-4f) / (1.0f - 8.0f / n);
    glm::vec2 lo = 0.5f * (window.lo + window.hi - size);
    float farthest = window.farthest;
    if (boxes.snap) {
        size = {quantizeUp(size.x / (1.0f - 4.0f / n)), quantizeUp(size.y / (1.0f - 4.0f / n))};
        const glm::vec2 texel = size / n;
        lo = glm::floor((0.5f * (window.lo + window.hi) - 0.5f * size) / texel) * texel;
        farthest = quantizeUp(farthest);
    }
    const glm::vec2 hi = lo + size;
    if (std::max(size.x, size.y) > 2.0f || std::max(glm::length(lo), glm::length(hi)) > 2.0f)
        return fitCube(position, boxes, mapSize);
    const LightCameraFrame f = fitFrustum(lightFromWorld, lo, hi, boxes, mapSize, farthest);
    return f.valid ? f : fitCube(position, boxes, mapSize);
}

}  // namespace

bool outsideCube(const Aabb& box, const LightCameraFrame& cube) {
    if (box.empty()) return true;
    const glm::vec3 eye = glm::vec3(glm::inverse(cube.lightFromWorld)[3]);
    const glm::vec3 nearest = glm::clamp(eye, box.min, box.max);
    return glm::length(nearest - eye) > cube.far;
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

LightCameraFrame lightCameraFrame(const Light& light, const Camera& view, const FitScene& scene,
                                  int mapSize, HeldExtent* held) {
    const ShadowCamera& c = light.shadowCamera;
    switch (c.policy) {
        case ShadowCameraPolicy::Manual:
            return fromNumbers(c, safeLookAt(light.position, c.target, c.up), mapSize);
        case ShadowCameraPolicy::Course:
            return fromNumbers(c, safeLookAt(light.position, view.centre, view.up), mapSize);
        case ShadowCameraPolicy::Fit:
            break;
    }
    const bool parallel = light.type == LightType::Directional || light.type == LightType::Area;
    FitBoxes boxes = visibleReceivers(scene, !(parallel && scene.samples));
    boxes.held = held;
    switch (light.type) {
        case LightType::Directional:
        case LightType::Area:
            // Area lights have parallel rays like the sun: the same orthographic fit (the
            // plane only sets the falloff).
            return fitOrthographic(lightRotation(light.direction),
                                   receiversInLight(scene, boxes, light.direction, 0.0f, kNoEnd),
                                   boxes, mapSize);
        case LightType::Spot:
            return fitPerspective(
                light.position, glm::normalize(light.direction),
                glm::radians(2.0f * std::clamp(light.outerConeDegrees, 1.0f, 89.0f)), boxes,
                mapSize);
        case LightType::Point:
            return fitPoint(light.position, scene.samples, boxes, mapSize);
    }
    return {};
}

LightCameraFrame sampledCascadeFrame(const glm::vec3& direction, const FitScene& scene,
                                     float depthFrom, float depthTo, int mapSize,
                                     HeldExtent* held) {
    FitBoxes boxes = visibleReceivers(scene, scene.samples == nullptr);
    boxes.held = held;
    return fitOrthographic(lightRotation(direction),
                           receiversInLight(scene, boxes, direction, depthFrom, depthTo), boxes,
                           mapSize);
}

LightCameraFrame lightCameraFrame(const Light& light, const Camera& view, const Aabb& bounds,
                                  int mapSize) {
    FitScene scene;
    scene.casters = {bounds};
    scene.receivers = {bounds};
    return lightCameraFrame(light, view, scene, mapSize);
}

FitScene fitScene(const Scene& scene, double seconds, float aspect) {
    FitScene f;
    const std::vector<Aabb> meshes = meshBounds(scene);
    for (const Object& o : scene.objects) {
        const Aabb box = meshes[o.mesh].transformed(o.worldFromModelAt(seconds));
        if (o.castsShadows) f.casters.push_back(box);
        if (o.receivesShadows) f.receivers.push_back(box);
    }
    f.viewKnown = true;
    f.viewClipFromWorld = clipFromView(scene.camera, aspect) * viewFromWorld(scene.camera);
    return f;
}

}  // namespace gnomon::shadow
