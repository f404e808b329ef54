#include "shadow/FrustumClip.h"

#include <algorithm>
#include <cmath>

#include "shadow/ShadowMath.h"

namespace gnomon::shadow {

namespace {

// Clips the segment p0 -> p1 to where all six signed distances (linear along it) are >= 0;
// adds the ends of what remains to `out`.
void clipSegment(const glm::vec3& p0, const glm::vec3& p1, const float (&d0)[6],
                 const float (&d1)[6], ClippedPoints& out) {
    float t0 = 0.0f, t1 = 1.0f;
    for (int k = 0; k < 6; ++k) {
        if (d0[k] < 0.0f && d1[k] < 0.0f) return;
        if (d0[k] < 0.0f) t0 = std::max(t0, d0[k] / (d0[k] - d1[k]));
        if (d1[k] < 0.0f) t1 = std::min(t1, d0[k] / (d0[k] - d1[k]));
    }
    if (t0 > t1) return;
    out.extend(p0 + (p1 - p0) * t0);
    out.extend(p0 + (p1 - p0) * t1);
}

// Signed distances of a clip-space point to the six planes of the clip volume.
void clipDistances(const glm::vec4& c, float (&d)[6]) {
    d[0] = c.w + c.x;
    d[1] = c.w - c.x;
    d[2] = c.w + c.y;
    d[3] = c.w - c.y;
    d[4] = c.w + c.z;
    d[5] = c.w - c.z;
}

void boxDistances(const Aabb& b, const glm::vec3& p, float (&d)[6]) {
    for (int k = 0; k < 3; ++k) {
        d[2 * k] = p[k] - b.min[k];
        d[2 * k + 1] = b.max[k] - p[k];
    }
}

}  // namespace

// `a` moved inside `b` corner by corner: their intersection when they overlap, and never
// empty when `a` is not (for a box that rounding put a hair beside `b`).
Aabb clampInto(const Aabb& a, const Aabb& b) {
    Aabb out;
    out.min = glm::clamp(a.min, b.min, b.max);
    out.max = glm::clamp(a.max, b.min, b.max);
    return out;
}

// The vertices of the part of `box` inside the clip volume of `clipFromWorld` (exact: the
// intersection of two convex solids has its vertices on the edges of one clipped by the
// other). `frustum`: the volume's corners in world space, numbered by x, y, z bits.
ClippedPoints clipToFrustum(const Aabb& box, const glm::mat4& clipFromWorld,
                            const std::array<glm::vec3, 8>& frustum) {
    ClippedPoints out;
    const std::array<glm::vec3, 8> corners = box.corners();
    float boxClip[8][6], frustumBox[8][6];
    for (int i = 0; i < 8; ++i) {
        clipDistances(clipFromWorld * glm::vec4(corners[size_t(i)], 1.0f), boxClip[i]);
        boxDistances(box, frustum[size_t(i)], frustumBox[i]);
    }
    // Edges join the corners whose indices differ in one bit (both solids number corners
    // by x, y, z bits).
    for (int i = 0; i < 8; ++i) {
        for (int bit = 1; bit < 8; bit <<= 1) {
            const int j = i | bit;
            if (j == i) continue;
            clipSegment(corners[size_t(i)], corners[size_t(j)], boxClip[i], boxClip[j], out);
            clipSegment(frustum[size_t(i)], frustum[size_t(j)], frustumBox[i], frustumBox[j], out);
        }
    }
    return out;
}

std::array<glm::vec3, 8> frustumCorners(const glm::mat4& clipFromWorld) {
    const glm::mat4 worldFromClip = glm::inverse(clipFromWorld);
    std::array<glm::vec3, 8> c{};
    for (int i = 0; i < 8; ++i) {
        const glm::vec4 p = worldFromClip * glm::vec4(i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f,
                                                      i & 4 ? 1.0f : -1.0f, 1.0f);
        c[size_t(i)] = glm::vec3(p) / p.w;
    }
    return c;
}

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

bool beyondNearPlane(const Aabb& box, const glm::mat4& clipFromWorld) {
    if (box.empty()) return false;
    for (const glm::vec3& c : box.corners()) {
        const glm::vec4 p = clipFromWorld * glm::vec4(c, 1.0f);
        if (p.z + p.w <= 0.0f) return false;
    }
    return true;
}

}  // namespace gnomon::shadow

namespace gnomon {

// Declared in gnomon/Scene.h: the scene's box against the camera's volume, in clip space.
bool cameraSeesScene(const Scene& scene, int width, int height) {
    glm::vec3 lo, hi;
    sceneBounds(scene, lo, hi);
    if (scene.objects.empty() || lo == hi || width <= 0 || height <= 0) return true;
    const glm::mat4 clipFromWorld =
        gnomon::clipFromView(scene.camera, float(width) / float(height)) *
        gnomon::viewFromWorld(scene.camera);
    glm::vec4 corners[8];
    for (int c = 0; c < 8; ++c)
        corners[c] = clipFromWorld *
                     glm::vec4(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z, 1.0f);
    // Coordinates past a float's range: the camera stands so far out (1e20 and more from a
    // scene of a few units) that its projection overflows, and nothing can be drawn.
    for (const glm::vec4& p : corners)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) ||
            !std::isfinite(p.w))
            return false;
    // The view volume is -w <= x, y, z <= w: the box is unseen when every corner lies beyond
    // the same one of those six planes.
    for (int axis = 0; axis < 3; ++axis) {
        for (const float side : {-1.0f, 1.0f}) {
            bool allBeyond = true;
            for (const glm::vec4& p : corners)
                allBeyond = allBeyond && side * p[axis] > p.w;
            if (allBeyond) return false;
        }
    }
    // Wholly in front of the camera: how many pixels the box spans each way.
    glm::vec2 ndcLo(1e30f), ndcHi(-1e30f);
    for (const glm::vec4& p : corners) {
        if (!(p.w > 0.0f)) return true;
        ndcLo = glm::min(ndcLo, glm::vec2(p) / p.w);
        ndcHi = glm::max(ndcHi, glm::vec2(p) / p.w);
    }
    const glm::vec2 pixels = 0.5f * (ndcHi - ndcLo) * glm::vec2(width, height);
    return pixels.x >= 1.0f || pixels.y >= 1.0f;
}

}  // namespace gnomon
