// The local lights' placement (LocalLights.h). The rule, in short:
// - Places: rays from the camera through points i = 0, 1, 2... of Roberts' R2 sequence over the
//   picture meet the scene's surfaces at anchors. An anchor is kept when the surface faces the
//   ray squarely enough and a light can stand free in front of it even at the most lights (the
//   nearest to it): the way there open, no surface within half that distance, inside the box of
//   the scene and the eye. Anchors alternate spot, point in the order they are kept. None of
//   this depends on the count, so N lights use the first N anchors of any larger count.
// - Range: N discs of radius range / kOverlap on the anchors' surfaces would tile the picture,
//   so together the lights cover the same share of the view whatever N is. A disc of radius r
//   at distance d from the eye, on a surface whose normal makes cosine c with the way back to
//   the eye, covers pi c (r / d)^2 of the image plane at distance 1, whose area is A; hence
//   range = kOverlap d sqrt(A / (pi c N)) (orthographic: without d). Surfaces, not a volume,
//   are what is lit and seen, hence N^(-1/2) rather than N^(-1/3); and the view, not the
//   scene's size, sets the reach, so a view of one corner of a large scene is covered as well
//   as one of all of it (the scene's size only bounds it).
// - Stand-off: a spot stands half its range off its anchor (its cone then lights a disc about
//   its range wide), a point light a quarter (it lights all round; its own surface should take
//   most of it), along the bisector of the surface's normal and the way back to the eye, so it
//   is in the open space the view looks through; halved while it would not stand free.
// - Intensity: each light gives its anchor an irradiance of about kIrradiance whatever its
//   stand-off, so the picture is about as bright for every N. A stand-off proportional to
//   N^(-1/2) under inverse-square falloff makes each intensity proportional to 1/N, so the
//   lights' total intensity stays about the same.
#include "LocalLights.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "gnomon/gnomon.h"

namespace gnomon::cli {
namespace {

constexpr float kPi = 3.14159265358979f;
// How much the lights' reaches overlap: kOverlap^2 discs cover each point of the picture on
// average, since a light fades out well before its range (window and inverse-square falloff).
constexpr float kOverlap = 2.0f;
// Stand-off from the anchor, in ranges.
constexpr float kSpotStandOff = 0.5f, kPointStandOff = 0.25f;
// Spot cone half-angles: at half its range off a surface, the outer cone lights a disc of
// about 0.6 of the range in radius, inside the range.
constexpr float kSpotInnerDegrees = 35.0f, kSpotOuterDegrees = 50.0f;
// The irradiance each light gives its anchor (1: a white surface lit to its own colour).
constexpr float kIrradiance = 1.0f;
// No surface nearer a light than this share of its stand-off: far enough that no surface
// next to it is lit many times brighter than its anchor.
constexpr float kClearance = 0.5f;
// Surfaces met more obliquely than this (the cosine between the ray and the normal) take no
// light: seen edge-on, they are hardly in the picture.
constexpr float kMinFacing = 0.1f;
// The way from an anchor starts this share of the stand-off off the surface, past the
// rounding of the anchor's own triangle.
constexpr float kLead = 1e-3f;

struct Box {
    glm::vec3 lo{0.0f}, hi{0.0f};
    bool holds(const glm::vec3& p) const {
        return !glm::any(glm::lessThan(p, lo)) && !glm::any(glm::greaterThan(p, hi));
    }
};

// Where a light may go: a point of a surface the view sees, the way off it into the open, and
// the point's distance from the eye.
struct Anchor {
    glm::vec3 point{0.0f}, away{0.0f};
    float distance = 0.0f;
    float facing = 1.0f;  // the cosine between the normal and the way back to the eye
    bool spot = true;
};

// The camera's rays as the renderer projects (through cameraClipFromWorld, so its aspect rule
// and its handling of a degenerate up are the renderer's): from the near plane through a point
// of the picture.
class ViewRays {
public:
    ViewRays(const Camera& camera, float aspect)
        : mWorldFromClip(glm::inverse(cameraClipFromWorld(camera, aspect))),
          mEye(camera.eye),
          mPerspective(camera.projection == Projection::Perspective) {
        const float a = camera.aspect > 0.0f ? camera.aspect : aspect;
        const float t = std::tan(glm::radians(camera.fovyDegrees) * 0.5f);
        mArea = mPerspective
                    ? 4.0f * t * t * a
                    : std::abs((camera.right - camera.left) * (camera.top - camera.bottom));
    }

    // The ray through `uv` in [0, 1]^2 of the picture, up to the far plane. Its direction is
    // taken to the far plane's point (a long base, so a precise one), or, where a far plane
    // 10^7 nears away leaves that point out of float's reach, to the depth range's middle.
    bvh::BvhRay ray(glm::vec2 uv) const {
        const glm::vec2 ndc = 2.0f * uv - 1.0f;
        const glm::vec3 a = unproject(ndc, -1.0f), f = unproject(ndc, 1.0f);
        const bool farKnown = std::isfinite(f.x) && std::isfinite(f.y) && std::isfinite(f.z);
        bvh::BvhRay r;
        r.origin = a;
        r.dir = glm::normalize((farKnown ? f : unproject(ndc, 0.0f)) - a);
        r.tnear = 0.0f;
        r.tfar = farKnown ? glm::length(f - a) : std::numeric_limits<float>::max();
        return r;
    }
    // The picture's area: on the image plane at distance 1 (perspective), or of the volume.
    float area() const { return mArea; }
    bool perspective() const { return mPerspective; }
    const glm::vec3& eye() const { return mEye; }

private:
    glm::vec3 unproject(glm::vec2 ndc, float z) const {
        const glm::vec4 p = mWorldFromClip * glm::vec4(ndc, z, 1.0f);
        return glm::vec3(p) / p.w;
    }

    glm::mat4 mWorldFromClip;
    glm::vec3 mEye;
    bool mPerspective;
    float mArea = 0.0f;
};

// Point i of Roberts' R2 sequence ("The Unreasonable Effectiveness of Quasirandom Sequences",
// 2018) over the picture's inner 90 % (a light at its very edge lights mostly what lies outside
// it): every prefix of the sequence is spread evenly, so the first N rays sample the whole view
// for every N.
glm::vec2 picturePoint(int i) {
    constexpr double g = 1.32471795724474602596;  // the plastic number, g^3 = g + 1
    const double x = std::fmod(0.5 + double(i) / g, 1.0);
    const double y = std::fmod(0.5 + double(i) / (g * g), 1.0);
    return {float(0.05 + 0.9 * x), float(0.05 + 0.9 * y)};
}

// 26 directions (the cube's faces, edges and corners) along which a light's clearance is probed.
const std::vector<glm::vec3>& probeDirections() {
    static const std::vector<glm::vec3> directions = [] {
        std::vector<glm::vec3> d;
        for (int x = -1; x <= 1; ++x)
            for (int y = -1; y <= 1; ++y)
                for (int z = -1; z <= 1; ++z)
                    if (x != 0 || y != 0 || z != 0)
                        d.push_back(glm::normalize(glm::vec3(float(x), float(y), float(z))));
        return d;
    }();
    return directions;
}

float standOffShare(bool spot) {
    return spot ? kSpotStandOff : kPointStandOff;
}

// The range of an anchor's light among `count` (the rule at the top of this file), within
// 1/1000 of the scene's size and the whole of it; `facing` is at least kMinFacing.
float rangeOf(const Anchor& a, const ViewRays& view, int count, float sceneSize) {
    const float reach = kOverlap * std::sqrt(view.area() / (kPi * float(count) * a.facing));
    const float range = view.perspective() ? reach * a.distance : reach;
    return std::clamp(range, 1e-3f * sceneSize, sceneSize);
}

// glTF's range window (1 - (d / range)^4)^2, which the renderer applies over the falloff.
float rangeWindow(float d, float range) {
    const float x = d / range, x4 = x * x * x * x;
    return x >= 1.0f ? 0.0f : (1.0f - x4) * (1.0f - x4);
}

// Whether a light `standOff` off its anchor stands free: the way there from the surface is
// open, no surface lies within kClearance x standOff of it along any probe, and it is inside
// `box`.
bool freeAt(const bvh::Bvh& bvh, const Anchor& a, float standOff, const Box& box) {
    if (!(standOff > 0.0f)) return false;
    const glm::vec3 p = a.point + standOff * a.away;
    if (!box.holds(p)) return false;
    bvh::BvhRay way;
    way.origin = a.point;
    way.dir = a.away;
    way.tnear = kLead * standOff;
    way.tfar = standOff;
    if (bvh.occluded(way, nullptr, nullptr)) return false;
    for (const glm::vec3& d : probeDirections()) {
        bvh::BvhRay probe;
        probe.origin = p;
        probe.dir = d;
        probe.tnear = 0.0f;
        probe.tfar = kClearance * standOff;
        if (bvh.occluded(probe, nullptr, nullptr)) return false;
    }
    return true;
}

// The first `count` anchors along the R2 sequence (the rule at the top of this file). Throws
// when the view shows too little of the scene for them.
std::vector<Anchor> findAnchors(const bvh::Bvh& bvh, const ViewRays& view, const Box& box,
                                float sceneSize, int count) {
    std::vector<Anchor> anchors;
    const int tries = 64 * count + 1024;
    for (int i = 0; i < tries && int(anchors.size()) < count; ++i) {
        const bvh::BvhRay ray = view.ray(picturePoint(i));
        const bvh::BvhHit hit = bvh.nearest(ray, nullptr, nullptr);
        if (!hit.hit()) continue;
        const bvh::BvhTriangle& tri = bvh.triangles()[hit.triangle];
        glm::vec3 normal = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
        const float length = glm::length(normal);
        if (!(length > 0.0f)) continue;
        normal /= length;
        if (glm::dot(normal, ray.dir) > 0.0f) normal = -normal;  // the side the eye sees
        const float facing = -glm::dot(normal, ray.dir);
        if (!(facing >= kMinFacing)) continue;
        Anchor a;
        a.facing = facing;
        a.point = ray.origin + hit.t * ray.dir;
        a.away = glm::normalize(normal - ray.dir);
        a.distance = glm::length(a.point - view.eye());
        a.spot = anchors.size() % 2 == 0;
        // Kept only where its light stands free at the most lights, the nearest to its
        // surface it ever stands: so every count keeps the same anchors.
        const float nearest = standOffShare(a.spot) * rangeOf(a, view, kMaxLocalLights, sceneSize);
        if (freeAt(bvh, a, nearest, box)) anchors.push_back(a);
    }
    if (int(anchors.size()) < count) {
        throw Error(ErrorKind::InvalidInput,
                    "--sweep local-lights: the view shows room for " +
                        std::to_string(anchors.size()) + " of the " + std::to_string(count) +
                        " lights (too little of the scene faces the camera); aim the camera at "
                        "the scene (--camera-eye, --camera-target)");
    }
    return anchors;
}

// The light of anchor `index` among `count`.
Light lightAt(const bvh::Bvh& bvh, const Anchor& a, std::size_t index, const ViewRays& view,
              int count, float sceneSize, const Box& box) {
    const float range = rangeOf(a, view, count, sceneSize);
    // A share of the range off the surface, halved while the light would not stand free; the
    // stand-off at the most lights is free (findAnchors kept only such anchors).
    const float nearest = standOffShare(a.spot) * rangeOf(a, view, kMaxLocalLights, sceneSize);
    float standOff = standOffShare(a.spot) * range;
    while (standOff > nearest && !freeAt(bvh, a, standOff, box))
        standOff *= 0.5f;
    standOff = std::max(standOff, nearest);

    Light l;
    l.name = std::string(a.spot ? "local spot " : "local point ") + std::to_string(index);
    l.type = a.spot ? LightType::Spot : LightType::Point;
    l.position = a.point + standOff * a.away;
    l.direction = -a.away;  // a spot's aim; a point light's only says which surface it lights
    l.colour = glm::vec3(1.0f);
    l.attenuation = {0.0f, 0.0f, 1.0f};
    l.range = range;
    l.intensity = kIrradiance * standOff * standOff / rangeWindow(standOff, range);
    l.innerConeDegrees = kSpotInnerDegrees;
    l.outerConeDegrees = kSpotOuterDegrees;
    l.castsShadows = true;
    l.shadowMapSize = 0;  // the kind's default
    return l;
}

}  // namespace

bvh::Bvh sceneHierarchy(const Scene& scene, double seconds) {
    std::vector<bvh::BvhTriangle> triangles;
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const Object& object = scene.objects[o];
        if (object.mesh >= scene.meshes.size()) continue;
        const Mesh& mesh = scene.meshes[object.mesh];
        const glm::mat4 worldFromModel = object.worldFromModelAt(seconds);
        auto world = [&](std::uint32_t i) {
            return glm::vec3(worldFromModel * glm::vec4(mesh.positions[i], 1.0f));
        };
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1],
                                c = mesh.indices[i + 2];
            if (std::max({a, b, c}) >= mesh.positions.size()) continue;
            bvh::BvhTriangle t;
            t.p0 = world(a);
            t.p1 = world(b);
            t.p2 = world(c);
            t.object = float(o);
            t.primitive = float(i / 3);
            t.flags = float(bvh::BvhTriangle::kCaster);
            triangles.push_back(t);
        }
    }
    if (triangles.empty()) {
        throw Error(ErrorKind::InvalidInput, "--sweep local-lights: scene '" + scene.name +
                                                 "' has no triangles to place lights among");
    }
    if (triangles.size() > bvh::kBvhMaxTriangles) {
        throw Error(ErrorKind::InvalidInput,
                    "--sweep local-lights: scene '" + scene.name + "' has " +
                        std::to_string(triangles.size()) + " triangles, more than the " +
                        std::to_string(bvh::kBvhMaxTriangles) + " a BVH holds");
    }
    return bvh::Bvh(std::move(triangles));
}

std::vector<Light> placeLocalLights(const Scene& scene, int count, float aspect, double seconds) {
    if (count < 1 || count > kMaxLocalLights) {
        throw Error(ErrorKind::InvalidInput, "--sweep local-lights: " + std::to_string(count) +
                                                 " lights is outside 1.." +
                                                 std::to_string(kMaxLocalLights));
    }
    const bvh::Bvh bvh = sceneHierarchy(scene, seconds);
    const bvh::BvhNode& root = bvh.nodes().front();
    const float sceneSize = std::max(glm::length(root.hi - root.lo), 1e-6f);
    // The scene's box grown to hold the eye: lights stay between the surfaces and the viewer.
    const Box box{glm::min(root.lo, scene.camera.eye), glm::max(root.hi, scene.camera.eye)};
    const ViewRays view(scene.camera, aspect);
    const std::vector<Anchor> anchors = findAnchors(bvh, view, box, sceneSize, count);
    std::vector<Light> lights;
    lights.reserve(anchors.size());
    for (std::size_t i = 0; i < anchors.size(); ++i)
        lights.push_back(lightAt(bvh, anchors[i], i, view, count, sceneSize, box));
    return lights;
}

void moveLights(const Scene& base, Scene& moved, int frame) {
    float size = -1.0f;  // the scene's, measured when a light without a range needs it
    for (std::size_t i = 0; i < base.lights.size() && i < moved.lights.size(); ++i) {
        const Light& l = base.lights[i];
        if (l.type != LightType::Spot && l.type != LightType::Point) continue;
        if (!(l.range > 0.0f) && size < 0.0f) {
            glm::vec3 lo(0.0f), hi(0.0f);
            sceneBounds(base, lo, hi);
            size = glm::length(hi - lo);
        }
        const float radius = 0.02f * (l.range > 0.0f ? l.range : size);
        // Each light starts at its own place on its circle (the golden angle apart).
        const float angle =
            2.0f * std::numbers::pi_v<float> * float(frame) / 60.0f + 2.39996f * float(i);
        moved.lights[i].position =
            l.position + radius * glm::vec3(std::cos(angle) - 1.0f, 0.0f, std::sin(angle));
    }
}

}  // namespace gnomon::cli
