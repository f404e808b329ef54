#include "shadow/ShadowMath.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/SceneUtil.h"
#include "shadow/LocalFit.h"

namespace gnomon::shadow {

glm::mat4 textureFromClip() {
    glm::mat4 m(0.5f);
    m[3] = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    return m;
}

Camera depthFitted(const Camera& camera, const Aabb& bounds) {
    if (bounds.empty()) return camera;
    float nearest = 0.0f, farthest = 0.0f;
    fit::depthRange(bounds, viewFromWorld(camera), nearest, farthest);
    if (!std::isfinite(nearest) || !std::isfinite(farthest)) return camera;
    // A margin of the span (and of the distance, for a perspective near plane) keeps the
    // planes off the box's own faces, which a ground's quad may lie in.
    const float margin = 0.01f * (farthest - nearest);
    Camera fitted = camera;
    const bool perspective = camera.projection == Projection::Perspective;
    const float near = perspective ? 0.99f * nearest - margin : nearest - margin;
    fitted.near = std::max(camera.near, near);
    fitted.far = std::min(camera.far, farthest + margin + 0.01f * std::abs(farthest));
    // The box wholly outside the camera's range: nothing is drawn either way.
    if (!(fitted.far > fitted.near)) return camera;
    return fitted;
}

namespace fit {
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

float quantizeUp(float x) {
    const float step = std::exp2(std::ceil(std::log2(std::max(x, 1e-20f))) - 4.0f);
    return std::ceil(x / step) * step;
}
}  // namespace fit

using fit::FitBoxes;
using fit::quantizeUp;

namespace {

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

}  // namespace

void clipReceivers(const FitScene& scene, std::vector<Aabb>& out) {
    out.clear();
    std::array<glm::vec3, 8> frustum{};
    if (scene.viewKnown) frustum = frustumCorners(scene.viewClipFromWorld);
    for (const Aabb& r : scene.receivers) {
        if (r.empty()) continue;
        if (!scene.viewKnown) {
            out.push_back(r);
            continue;
        }
        // Rounding must not grow the box, nor empty a flat one (a ground plane has no
        // thickness: its clipped points may all round to one side of it).
        const Aabb clipped = clipToFrustum(r, scene.viewClipFromWorld, frustum).box();
        if (!clipped.empty()) out.push_back(clampInto(clipped, r));
    }
}

namespace {

// `receivers` false: only the casters (a fit to view samples needs no receiver boxes).
FitBoxes visibleReceivers(const FitScene& scene, bool receivers = true) {
    FitBoxes f;
    f.casters = &scene.casters;
    f.snap = scene.viewKnown && scene.stabilise;
    if (!receivers) return f;
    if (scene.visibleFilled) {
        f.shared = &scene.visibleReceivers;
    } else {
        clipReceivers(scene, f.own);
    }
    return f;
}

// The rotation from world into a directional light's space: a turn only, so a snapped
// origin stays on one grid whatever the view does.
glm::mat4 lightRotation(const glm::vec3& direction) {
    return safeLookAt(glm::vec3(0.0f), glm::normalize(direction), glm::vec3(0, 1, 0));
}

// The stabilised box of a fit that follows the view, in place: from the needed box
// [lo, hi] x [zFar, zNear] in light space, a quantised size with room for the origin's snap
// and the origin on a multiple of a texel, so the same inputs up to a texel give the same
// camera. Under a low sun the receivers stretch along the light, and a square would spend
// the short axis's texels on nothing. For frames that follow a moving view (`following`) the
// shorter side is the longer one over a power of two: sides quantised apart each step on
// their own, and a tight short side leaves the held extent (steadyExtent) sooner, so the
// moving view would see the map's grid jump more often. A still frame has nothing to hold
// and takes the short side's own quantised size, up to twice the texels across it.
void snapExtent(int mapSize, bool following, glm::vec2& lo, glm::vec2& hi, float& zNear,
                float& zFar) {
    const glm::vec2 size = hi - lo;
    const float pad = 1.0f - 4.0f / float(mapSize);
    const int longAxis = size.x >= size.y ? 0 : 1;
    const float longSide = quantizeUp(size[longAxis] / pad);
    const float shortNeeded = std::max(size[1 - longAxis] / pad, longSide / 1024.0f);
    glm::vec2 side;
    side[longAxis] = longSide;
    side[1 - longAxis] = following
                             ? longSide / std::exp2(std::floor(std::log2(longSide / shortNeeded)))
                             : std::min(longSide, quantizeUp(shortNeeded));
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
    snapExtent(mapSize, held != nullptr, lo, hi, zNear, zFar);
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
    for (const Aabb& r : boxes.receivers())
        receivers.extend(r.transformed(rotation));
    return receivers;
}

}  // namespace

bool outsideCube(const Aabb& box, const LightCameraFrame& cube) {
    if (box.empty()) return true;
    return box.distanceTo(glm::vec3(glm::inverse(cube.lightFromWorld)[3])) > cube.far;
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

float lightReach(const Light& light) {
    const bool local = light.type == LightType::Point || light.type == LightType::Spot;
    return local && light.range > 0.0f ? light.range : 0.0f;
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
    boxes.reach = lightReach(light);
    boxes.apex = light.position;
    LightCameraFrame frame;
    if (boxes.reach > 0.0f && scene.samples && !scene.samples->empty() &&
        !anySampleWithin(*scene.samples, light.position, boxes.reach)) {
        frame.valid = false;  // its range holds nothing the view sees
        return frame;
    }
    switch (light.type) {
        case LightType::Directional:
        case LightType::Area:
            // Area lights have parallel rays like the sun: the same orthographic fit (the
            // plane only sets the falloff).
            return fitOrthographic(lightRotation(light.direction),
                                   receiversInLight(scene, boxes, light.direction, 0.0f, kNoEnd),
                                   boxes, mapSize);
        case LightType::Spot:
            frame =
                fit::fitSpot(light.position, glm::normalize(light.direction),
                             glm::radians(2.0f * std::clamp(light.outerConeDegrees, 1.0f, 89.0f)),
                             scene.samples, boxes, mapSize);
            break;
        case LightType::Point:
            frame = fit::fitPoint(light.position, scene.samples, boxes, mapSize);
            break;
    }
    frame.reach = boxes.reach;
    return frame;
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

LightCameraFrame sizedLightCameraFrame(const Light& light, const ShadowOptions& options,
                                       const Camera& view, const FitScene& scene, int& size,
                                       HeldExtent* held, int wanted) {
    const bool named = light.shadowMapSize > 0 || options.mapSize > 0;
    size = !named && wanted > 0 ? wanted : shadowMapSizeOf(light, options);
    LightCameraFrame frame = lightCameraFrame(light, view, scene, size, held);
    // Fitted again at the cube's size: a frustum's fit quantises its window by the map size,
    // and a fit that finds no frustum at 2048 finds none at the coarser 1024 either (its
    // margins only grow), so this stays a cube.
    if (frame.valid && frame.kind == FrameKind::Cube && !named && size > kDefaultCubeFaceSize) {
        size = kDefaultCubeFaceSize;
        frame = lightCameraFrame(light, view, scene, size, held);
    }
    // A cube draws only the faces the view's pixels look up (a face spans 90 degrees over
    // `size` texels, each at most 2 / size radians wide, at its centre).
    if (frame.valid && frame.kind == FrameKind::Cube && scene.samples && !scene.samples->empty()) {
        const std::uint8_t seen =
            cubeFacesSeen(*scene.samples, light.position,
                          cubeLookupReachTexels(options) * 2.0f / float(size), lightReach(light));
        if (seen) frame.faces = seen;
    }
    return frame;
}

LightCameraFrame pointFaceFrame(const Light& light, int face, const ShadowOptions& options,
                                const FitScene& scene, int mapSize, HeldExtent* held) {
    FitBoxes boxes = visibleReceivers(scene, true);
    boxes.held = held;
    boxes.reach = lightReach(light);
    boxes.apex = light.position;
    // The face's texels at its rim are 2 / mapSize tan units wide, as a cube's: a lookup
    // there reads as far past the rim as a cube's lookup reads into the next face.
    const float margin = cubeLookupReachTexels(options) * 2.0f / float(std::max(mapSize, 1));
    LightCameraFrame frame =
        fit::fitPointFace(light.position, face, margin, scene.samples, boxes, mapSize);
    frame.reach = boxes.reach;
    return frame;
}

float cubeLookupReachTexels(const ShadowOptions& options) {
    // The filter's widest tap with its bilinear footprint (the moment filters' cubes take the
    // default 3 x 3 PCF; PCSS searches and filters up to kPcssMaxTexels, 48).
    float taps = 2.0f;
    switch (options.filter) {
        case ShadowFilter::None:
        case ShadowFilter::Hw2x2:
            taps = 1.0f;
            break;
        case ShadowFilter::Pcf:
        case ShadowFilter::Poisson:
            taps = float(options.pcfSize / 2) + 1.0f;
            break;
        case ShadowFilter::Pcss:
            taps = 49.0f;
            break;
        default:
            break;
    }
    // Moves of the point before its taps: the normal offset (texels x filter reach), the
    // grazing planes' shift (at most the reach), the stand-in lift (at most 6 texels); and
    // two texels to spare.
    return taps * (2.0f + std::max(options.normalOffset, 0.0f)) + 6.0f + 2.0f;
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
