#include "truth/ShadowRays.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "gnomon/Error.h"
#include "scene/SceneUtil.h"

namespace gnomon::truth {

namespace {

// Two unit vectors perpendicular to `w` and to each other.
void tangents(const glm::vec3& w, glm::vec3& u, glm::vec3& v) {
    const glm::vec3 a = std::fabs(w.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    u = glm::normalize(glm::cross(w, a));
    v = glm::cross(w, u);
}

}  // namespace

ShadowRays::ShadowRays(const Scene& scene, const RenderOptions& options, TracerKind kind)
    : mLights(scene.lights), mBlend(options.shadow.blendShadows) {
    mOrigin = sceneOrigin(scene, options.time);
    Aabb bounds;
    for (const Object& obj : scene.objects) {
        const Mesh& mesh = scene.meshes[obj.mesh];
        // Moved as the renderer moves it (render/RelativeScene.h): the same floats.
        Object moved = obj;
        makeRelative(moved, mOrigin);
        const glm::mat4 m = moved.worldFromModelAt(options.time);
        std::vector<glm::vec3> p(mesh.positions.size());
        for (std::size_t i = 0; i < p.size(); ++i) {
            p[i] = glm::vec3(m * glm::vec4(mesh.positions[i], 1.0f));
            bounds.extend(p[i]);
        }
        mPositions.push_back(std::move(p));
    }
    for (Light& light : mLights)
        makeRelative(light, mOrigin);
    mScale = bounds.empty() ? 1.0f : std::max(bounds.radius(), 1e-6f);
    mAlpha.resize(scene.objects.size());
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const Material& m = scene.materials[scene.objects[o].material];
        if (m.alphaMode == AlphaMode::Opaque) continue;
        mAlpha[o] = {
            &scene.meshes[scene.objects[o].mesh], &m,
            m.baseColourTexture >= 0 ? &scene.textures[std::size_t(m.baseColourTexture)] : nullptr};
    }
    mOn.resize(scene.lights.size());
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        mOn[i] =
            options.shadow.enabled && scene.lights[i].castsShadows && lightIsOn(scene, options, i);
    }
    const TracerInput input{&scene, &mPositions, &mAlpha, mBlend};
    mTracer = kind == TracerKind::Bvh ? makeBvhTracer(input) : makeEmbreeTracer(input);
}

float ShadowRays::lead(const glm::vec3& point, const glm::vec3& n, const glm::vec3& dir) const {
    // 2e-6 of the scene: over ten float steps of a point as far out as the scene reaches
    // (the point is taken from its triangle's corners, Reference.cpp), and as much again
    // for its distance from the origin. Short, so that the ray misses no thin occluder near
    // its start (tests/crosscheck compares it with an exact caster).
    const float margin = 2e-6f * mScale + 1e-6f * glm::length(point);
    return margin / std::max(glm::dot(n, dir), kEdgeOnCosine);
}

glm::vec3 ShadowRays::directionOf(const Light& light) {
    return glm::length(light.direction) > 0.0f ? glm::normalize(light.direction)
                                               : glm::vec3(0, -1, 0);
}

bool ShadowRays::towardsLight(std::size_t l, const glm::vec3& point, glm::vec3& toLight,
                              float& distance) const {
    if (!mOn[l]) return false;
    const Light& light = mLights[l];
    const glm::vec3 ld = directionOf(light);
    distance = std::numeric_limits<float>::infinity();
    switch (light.type) {
        case LightType::Directional:
            toLight = -ld;
            return true;
        case LightType::Area:
            toLight = -ld;
            distance = glm::dot(point - light.position, ld);
            return distance > 0.0f;  // in front of the light's plane
        case LightType::Spot:
        case LightType::Point:
            break;
    }
    const glm::vec3 d = light.position - point;
    distance = glm::length(d);
    if (!(distance > 0.0f)) return false;
    if (light.range > 0.0f && distance >= light.range) return false;  // unlit
    toLight = d / distance;
    return light.type != LightType::Spot ||
           glm::dot(-toLight, ld) > std::cos(glm::radians(light.outerConeDegrees));
}

float ShadowRays::transmitted(const glm::vec3& point, const glm::vec3& dir, float near, float far,
                              glm::vec3* tint) const {
    if (!(near < far)) {  // the light lies within the surface's margin
        if (tint) *tint = glm::vec3(1.0f);
        return 1.0f;
    }
    return mTracer->transmitted(point, dir, near, far, tint);
}

int ShadowRays::side(std::size_t l, const glm::vec3& point, const glm::vec3& n) const {
    glm::vec3 toLight;
    float distance = 0.0f;
    if (!towardsLight(l, point, toLight, distance)) return -1;
    if (!(glm::dot(n, toLight) > kEdgeOnCosine)) return 0;
    return transmitted(point, toLight, lead(point, n, toLight), distance) < 0.5f ? 0 : 1;
}

bool ShadowRays::otherSideWithin(std::size_t l, const glm::vec3& point, const glm::vec3& n,
                                 float radius, int here) const {
    glm::vec3 u, v;
    tangents(n, u, v);
    const float behind = 1e-3f * radius;
    for (int i = 0; i < 16; ++i) {
        const float r = i < 8 ? radius : 0.5f * radius;
        const float a = float(i) * 0.785398163f + (i < 8 ? 0.0f : 0.392699082f);
        const glm::vec3 q = point + r * (std::cos(a) * u + std::sin(a) * v);
        // The surface nearest q along the normal, within the radius on either side: the
        // receiver curved or bent away from its plane. None: q lies off its edge.
        float nearest = std::numeric_limits<float>::infinity();
        glm::vec3 onSurface(0.0f), hitNormal(0.0f);
        for (const float dir : {-1.0f, 1.0f}) {
            // Each ray starts a little behind q, so a surface through q itself is found.
            const glm::vec3 start = q - n * (dir * behind);
            const TraceHit hit =
                mTracer->nearest(start, dir * n, 0.0f, std::min(radius, nearest) + behind);
            if (!hit.hit()) continue;
            nearest = std::max(hit.t - behind, 0.0f);
            onSurface = start + n * (dir * hit.t);
            hitNormal = hit.geometricNormal;
        }
        const float length = glm::length(hitNormal);
        if (!(length > 0.0f)) continue;
        glm::vec3 m = hitNormal / length;
        if (glm::dot(m, n) < 0.0f) m = -m;    // the side the centre's normal is on
        if (glm::dot(m, n) < 0.5f) continue;  // another surface across this one, not it
        const int there = side(l, onSurface, m);
        if (there >= 0 && there != here) return true;
    }
    return false;
}

}  // namespace gnomon::truth
