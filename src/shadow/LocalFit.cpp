#include "shadow/LocalFit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "shadow/FrustumClip.h"

namespace gnomon::shadow::fit {

namespace {

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
    for (std::size_t i = 0; fromBoxes && i < boxes.receivers().size(); ++i) {
        const Aabb& r = boxes.receivers()[i];
        if (boxes.beyondReach(r) || outsideClipVolume(r, sides, true)) continue;
        float nearest = 0.0f, far = 0.0f;
        depthRange(r, lightFromWorld, nearest, far);
        farthest = std::max(farthest, far);
    }
    if (boxes.reach > 0.0f) farthest = std::min(farthest, boxes.reach);
    if (!(farthest > 0.0f)) return f;
    // Near at the nearest point of a caster inside the pyramid (not the nearest corner of
    // its box: a floor reaching behind the light would pull near to ~0 and waste the depth
    // precision of the whole map). Clipped to the pyramid from 1/1000 of far to far.
    const glm::mat4 volume = pyramid(farthest * 1e-3f, farthest * 1.01f) * lightFromWorld;
    const std::array<glm::vec3, 8> volumeCorners = frustumCorners(volume);
    float nearestCaster = std::numeric_limits<float>::max();
    for (const Aabb& c : *boxes.casters) {
        if (c.empty() || boxes.beyondReach(c) || outsideClipVolume(c, volume, false)) continue;
        // Its clipped points lie no nearer than its nearest corner: a box whose corners are
        // all as far as the nearest caster so far cannot bring near closer.
        float cornerNearest = 0.0f, cornerFarthest = 0.0f;
        depthRange(c, lightFromWorld, cornerNearest, cornerFarthest);
        if (cornerNearest >= nearestCaster) continue;
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

// Six faces around the light reaching the farthest receiver corner; near just before the
// nearest caster, no nearer than depth precision allows (geometry nearer than near still
// casts: the pass clamps depth for fitted lights).
LightCameraFrame fitCube(const glm::vec3& position, const FitBoxes& boxes, int mapSize) {
    LightCameraFrame f;
    f.kind = FrameKind::Cube;
    f.lightFromWorld = glm::translate(glm::mat4(1.0f), -position);
    f.valid = false;
    float farthest = 0.0f;
    for (const Aabb& r : boxes.receivers()) {
        if (boxes.beyondReach(r)) continue;
        for (const glm::vec3& c : r.corners())
            farthest = std::max(farthest, glm::length(c - position));
    }
    if (boxes.reach > 0.0f) farthest = std::min(farthest, boxes.reach);
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

// The frustum over `window` (what the view sees, in tan units of `lightFromWorld`), with a
// few texels of margin so filter taps at its rim stay inside the map. Steady while the view
// moves when `boxes.snap` (as the orthographic fit is): each side a quantised size with its
// corner on its own texel grid, far quantised, and with `boxes.held` the previous frame's
// window kept while it serves; small camera moves leave the map as it was.
// Invalid when the window reaches further than `widest` tan units from the axis, or, with
// `onlyHeld`, when the held window does not serve (the held one is then left as it was).
LightCameraFrame fitWindow(const glm::mat4& lightFromWorld, const SampleWindow& window,
                           const FitBoxes& boxes, int mapSize, float widest,
                           bool onlyHeld = false) {
    LightCameraFrame none;
    none.valid = false;
    const float n = float(std::max(mapSize, 16));
    glm::vec2 size = glm::max(window.hi - window.lo, 1e-4f) / (1.0f - 8.0f / n);
    glm::vec2 lo = 0.5f * (window.lo + window.hi - size);
    float farthest = window.farthest;
    if (boxes.snap) {
        const glm::vec2 neededLo = lo, neededHi = lo + size;
        size = {quantizeUp(size.x / (1.0f - 4.0f / n)), quantizeUp(size.y / (1.0f - 4.0f / n))};
        const glm::vec2 texel = size / n;
        lo = glm::floor((0.5f * (window.lo + window.hi) - 0.5f * size) / texel) * texel;
        farthest = quantizeUp(farthest);
        // Frames that follow one another keep the previous window while it holds this one's
        // and is at most kHoldSlack looser, as orthographic fits keep their extent.
        HeldExtent* held = boxes.held;
        if (held) {
            const bool serves =
                held->valid && held->mapSize == mapSize && held->rotation == lightFromWorld &&
                glm::all(glm::lessThanEqual(held->lo, neededLo)) &&
                glm::all(glm::greaterThanEqual(held->hi, neededHi)) &&
                held->zFar >= window.farthest &&
                glm::all(glm::lessThanEqual(held->hi - held->lo, kHoldSlack * size)) &&
                held->zFar <= kHoldSlack * farthest;
            if (serves) {
                lo = held->lo;
                size = held->hi - held->lo;
                farthest = held->zFar;
            } else if (onlyHeld) {
                return none;
            } else {
                *held = {true, lightFromWorld, mapSize, lo, lo + size, 0.0f, farthest};
            }
        }
    }
    if (onlyHeld && !(boxes.snap && boxes.held)) return none;
    const glm::vec2 hi = lo + size;
    if (std::max(size.x, size.y) > widest || std::max(glm::length(lo), glm::length(hi)) > widest) {
        return none;
    }
    return fitFrustum(lightFromWorld, lo, hi, boxes, mapSize, farthest);
}

// Narrows `window` (tan units of `lightFromWorld`, as samplesWindow gives it) to where a
// caster could shadow what it holds: the casters' boxes clipped to its pyramid, out to its
// farthest sample, seen from the light, grown by `marginTan`. A point the window then leaves
// out lies beside every caster seen from the light, so it is lit, as a lookup outside the map
// reads it (a model on a wide ground under a close lamp: the ground the view sees around the
// model's shadow took most of the map). False when no caster reaches into the window.
bool narrowToCasters(const glm::mat4& lightFromWorld, SampleWindow& window, const FitBoxes& boxes,
                     float marginTan) {
    const float far = window.farthest, near = far * 1e-4f;  // fitFrustum clamps at 1e-3
    const glm::mat4 volume = glm::frustum(window.lo.x * near, window.hi.x * near,
                                          window.lo.y * near, window.hi.y * near, near, far) *
                             lightFromWorld;
    const std::array<glm::vec3, 8> corners = frustumCorners(volume);
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const Aabb& c : *boxes.casters) {
        if (c.empty() || boxes.beyondReach(c) || outsideClipVolume(c, volume, false)) continue;
        const ClippedPoints inside = clipToFrustum(c, volume, corners);
        for (int i = 0; i < inside.count; ++i) {
            const glm::vec3 v =
                glm::vec3(lightFromWorld * glm::vec4(inside.points[size_t(i)], 1.0f));
            if (!(-v.z > 0.0f)) continue;
            lo = glm::min(lo, glm::vec2(v) / -v.z);
            hi = glm::max(hi, glm::vec2(v) / -v.z);
        }
    }
    window.lo = glm::max(window.lo, lo - marginTan);
    window.hi = glm::min(window.hi, hi + marginTan);
    return glm::all(glm::lessThan(window.lo, window.hi));
}

// The margin narrowToCasters leaves around the casters of a spot's or a point light's
// frustum: 16 of the samples' window's texels (what a lookup's taps and offsets may read past
// a caster's box, with room to spare).
float windowMargin(const SampleWindow& window, int mapSize) {
    return 16.0f * std::max(window.hi.x - window.lo.x, window.hi.y - window.lo.y) /
           float(std::max(mapSize, 1));
}

}  // namespace

// A point light: when the view's samples all lie in a window no wider than a cube face's
// (2 x 2 tan units) around their mean direction, one frustum over that window: never
// coarser than a cube face on its axis and often many times finer (a lamp over a small model
// spends a few percent of a cube on what the view sees). The window is first narrowed to
// where casters can shadow it (narrowToCasters), so a model on a wide ground may fit one
// frustum where the ground alone would not. Else the cube.
LightCameraFrame fitPoint(const glm::vec3& position, const ViewSamples* samples,
                          const FitBoxes& boxes, int mapSize) {
    glm::vec3 axis(0.0f);
    SampleWindow window;
    if (!samples || !samplesDirection(*samples, position, axis, boxes.reach))
        return fitCube(position, boxes, mapSize);
    // Following frames keep the held frustum, axis and all, while it still holds the view:
    // the mean direction drifts with every camera move, and a new axis is a new texel grid.
    const HeldExtent* held = boxes.snap ? boxes.held : nullptr;
    if (held && held->valid &&
        glm::length(glm::vec3(held->rotation * glm::vec4(position, 1.0f))) <=
            1e-5f * (1.0f + glm::length(position)) &&
        samplesWindow(*samples, held->rotation, window, nullptr, boxes.reach) &&
        narrowToCasters(held->rotation, window, boxes, windowMargin(window, mapSize))) {
        const LightCameraFrame f = fitWindow(held->rotation, window, boxes, mapSize, 2.0f, true);
        if (f.valid) return f;
    }
    if (boxes.snap) {
        // The axis on a grid of half degrees, so small camera moves keep it.
        const float step = glm::radians(0.5f);
        const float yaw = std::round(std::atan2(axis.x, -axis.z) / step) * step;
        const float pitch = std::round(std::asin(std::clamp(axis.y, -1.0f, 1.0f)) / step) * step;
        axis = {std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
    }
    const glm::mat4 lightFromWorld = safeLookAt(position, position + axis, glm::vec3(0, 1, 0));
    if (!samplesWindow(*samples, lightFromWorld, window, nullptr, boxes.reach) ||
        !narrowToCasters(lightFromWorld, window, boxes, windowMargin(window, mapSize))) {
        return fitCube(position, boxes, mapSize);
    }
    const LightCameraFrame f = fitWindow(lightFromWorld, window, boxes, mapSize, 2.0f);
    return f.valid ? f : fitCube(position, boxes, mapSize);
}

// One face of a point light's cube as a frustum of its own: the face's pyramid, widened by
// `marginTan` (what a lookup at the face's rim reads beyond it), narrowed to the window of the
// view's samples it holds and to where casters can shadow them (none: no map). A cube spends the
// same texels on every direction; a model on a ground under a close lamp lands on a few percent of
// the faces it appears in, and its shadows come out coarse. Without a window (a sample's footprint
// reaches the light), or where the window, with its margin and quantised size, would be no finer
// than the whole widened face (the view sees all of the face), the whole face: it never moves, so
// it needs no steadying either.
LightCameraFrame fitPointFace(const glm::vec3& position, int face, float marginTan,
                              const ViewSamples* samples, const FitBoxes& boxes, int mapSize) {
    const glm::mat4 lightFromWorld =
        cubeFaceRotation(face) * glm::translate(glm::mat4(1.0f), -position);
    const float t = 1.0f + std::max(marginTan, 0.0f);
    const SampleWindow faceWindow{glm::vec2(-t), glm::vec2(t), 0.0f};
    SampleWindow window;
    if (samples && samplesWindow(*samples, lightFromWorld, window, &faceWindow, boxes.reach)) {
        if (!narrowToCasters(lightFromWorld, window, boxes, marginTan)) {
            LightCameraFrame none;
            none.valid = false;  // nothing the view sees through this face can be shadowed
            return none;
        }
        const LightCameraFrame f = fitWindow(lightFromWorld, window, boxes, mapSize, 4.0f * t);
        // The whole face's texel, as fitFrustum sizes it, without fitting it.
        if (f.valid && f.texelWorldSize < 2.0f * t / float(mapSize)) return f;
    }
    return fitFrustum(lightFromWorld, faceWindow.lo, faceWindow.hi, boxes, mapSize);
}

// A spot light: its cone's square window, narrowed to the part of it where the view's samples
// lie (a spot over a room's corner spends its map on the corner the camera sees, not on the
// whole cone), and to where casters can shadow them (none: no map). Without samples, or when
// they do not narrow it, the whole cone.
LightCameraFrame fitSpot(const glm::vec3& position, const glm::vec3& axis, float fovyRadians,
                         const ViewSamples* samples, const FitBoxes& boxes, int mapSize) {
    const float t = std::tan(0.5f * fovyRadians);
    const glm::mat4 lightFromWorld = safeLookAt(position, position + axis, glm::vec3(0, 1, 0));
    const SampleWindow cone{glm::vec2(-t), glm::vec2(t), 0.0f};
    SampleWindow window;
    if (samples && samplesWindow(*samples, lightFromWorld, window, &cone, boxes.reach)) {
        if (!narrowToCasters(lightFromWorld, window, boxes, windowMargin(window, mapSize))) {
            LightCameraFrame none;
            none.valid = false;  // no caster can shadow what the view sees in the cone: no map
            return none;
        }
        // The window lies in the cone; its margin may take it a few texels past the cone.
        const LightCameraFrame f = fitWindow(lightFromWorld, window, boxes, mapSize, 4.0f * t);
        if (f.valid) return f;
    }
    return fitFrustum(lightFromWorld, cone.lo, cone.hi, boxes, mapSize);
}

}  // namespace gnomon::shadow::fit
