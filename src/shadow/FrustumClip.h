// Boxes against frusta, exactly: what part of an object's box a camera's volume holds. The
// fitted light cameras (shadow/ShadowMath) use it to clip receivers to the view and casters
// to a light's volume; the shadow pass to skip casters outside a map; the CLI to say when a
// camera sees none of the scene (gnomon::cameraSeesScene). Pure math, no GL.
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "core/Aabb.h"

namespace gnomon::shadow {

// The vertices of a box clipped by a frustum: at most the ends of 24 clipped edges.
struct ClippedPoints {
    std::array<glm::vec3, 48> points;
    int count = 0;
    void extend(const glm::vec3& p) { points[size_t(count++)] = p; }
    Aabb box() const {
        Aabb b;
        for (int i = 0; i < count; ++i)
            b.extend(points[size_t(i)]);
        return b;
    }
};

// The vertices of the part of `box` inside the clip volume of `clipFromWorld` (exact: the
// intersection of two convex solids has its vertices on the edges of one clipped by the
// other). `frustum`: the volume's corners in world space, numbered by x, y, z bits.
ClippedPoints clipToFrustum(const Aabb& box, const glm::mat4& clipFromWorld,
                            const std::array<glm::vec3, 8>& frustum);

// The eight corners of the clip volume of `clipFromWorld` in world space, numbered by x, y, z
// bits (bit set: +1 in clip space).
std::array<glm::vec3, 8> frustumCorners(const glm::mat4& clipFromWorld);

// `a` moved inside `b` corner by corner: their intersection when they overlap, and never
// empty when `a` is not (for a box that rounding put a hair beside `b`).
Aabb clampInto(const Aabb& a, const Aabb& b);

// True when no point of `box` can land in the clip volume of `clipFromWorld` (each corner
// tested against the six planes; conservative: a box straddling a corner may be kept).
// `ignoreNear`: depth-clamped passes keep casters in front of the near plane.
bool outsideClipVolume(const Aabb& box, const glm::mat4& clipFromWorld, bool ignoreNear);

// True when every corner of `box` lies on the far side of the near plane of `clipFromWorld`
// (z > -w): every line of sight then starts outside the box, so a solid in it shows the view
// none of its back faces.
bool beyondNearPlane(const Aabb& box, const glm::mat4& clipFromWorld);

}  // namespace gnomon::shadow
