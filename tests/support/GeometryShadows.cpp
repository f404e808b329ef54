#include "GeometryShadows.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "scene/SceneUtil.h"
#include "shadow/ShadowMath.h"

namespace gnomon::test {
namespace {

// A shadow that takes 0.02 of full scale per channel (15 levels of R+G+B) is visible.
constexpr float kVisible = 0.02f;

struct Triangle {
    glm::vec3 a, b, c;
    int object;
};

struct Hit {
    float t;
    int triangle;
};

// Möller-Trumbore, both sides.
std::optional<float> intersect(const Triangle& tri, const glm::vec3& o, const glm::vec3& d) {
    const glm::vec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a;
    const glm::vec3 p = glm::cross(d, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f) return std::nullopt;
    const float inv = 1.0f / det;
    const glm::vec3 s = o - tri.a;
    const float u = glm::dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f) return std::nullopt;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(d, q) * inv;
    if (v < 0.0f || u + v > 1.0f) return std::nullopt;
    return glm::dot(e2, q) * inv;
}

struct World {
    std::vector<Triangle> triangles;
    std::vector<bool> casts;

    std::optional<Hit> nearest(const glm::vec3& o, const glm::vec3& d, float tMax) const {
        std::optional<Hit> best;
        for (size_t i = 0; i < triangles.size(); ++i) {
            auto t = intersect(triangles[i], o, d);
            if (t && *t > 0.0f && *t < tMax && (!best || *t < best->t)) best = Hit{*t, int(i)};
        }
        return best;
    }
    bool occluded(const glm::vec3& o, const glm::vec3& d, float tMin, float tMax, int self) const {
        for (size_t i = 0; i < triangles.size(); ++i) {
            if (int(i) == self || !casts[size_t(triangles[i].object)]) continue;
            auto t = intersect(triangles[i], o, d);
            if (t && *t > tMin && *t < tMax) return true;
        }
        return false;
    }
};

struct LightModel {
    bool on = false;
    bool shadowed = false;
    shadow::LightCameraFrame frame;
    glm::vec3 eye{0.0f};
    glm::vec3 axis{0.0f};  // view direction of the light camera
};

// The light's diffuse strength at p with normal n (intensity, falloff, cone, N.L).
float lightStrength(const Light& l, const glm::vec3& p, const glm::vec3& n) {
    glm::vec3 toLight;
    float falloff = 1.0f;
    if (l.type == LightType::Directional) {
        toLight = -glm::normalize(l.direction);
    } else if (l.type == LightType::Area) {
        toLight = -glm::normalize(l.direction);
        const float dist = std::abs(glm::dot(-toLight, p - l.position));
        falloff = 1.0f / (l.attenuation.constant + l.attenuation.linear * dist +
                          l.attenuation.quadratic * dist * dist);
    } else {
        const glm::vec3 d = l.position - p;
        const float dist = glm::length(d);
        toLight = d / dist;
        falloff = 1.0f / (l.attenuation.constant + l.attenuation.linear * dist +
                          l.attenuation.quadratic * dist * dist);
        if (l.type == LightType::Spot) {
            const float c = glm::dot(-toLight, glm::normalize(l.direction));
            const float lo = std::cos(glm::radians(l.outerConeDegrees));
            const float hi = std::cos(glm::radians(l.innerConeDegrees));
            falloff *= glm::clamp((c - lo) / std::max(hi - lo, 1e-6f), 0.0f, 1.0f);
        }
    }
    return l.intensity * falloff * std::max(glm::dot(n, toLight), 0.0f);
}

// The state of light `i` at the surface point p (normal n, facing the camera) of the hit
// triangle: 0 = the shadow cannot change this pixel or it is lit, 1 = shadowed where the
// light is strong, 2 = undecidable (weakly lit and occluded, or at the map border).
int lightState(const World& world, const Scene& scene, const LightModel& lm, size_t i,
               const Hit& hit, const glm::vec3& p, const glm::vec3& n) {
    const int object = world.triangles[size_t(hit.triangle)].object;
    // What the light adds to this pixel (0..1 per channel, averaged): the most a shadow
    // can take away. Unlit materials lose a fixed factor wherever a shadow falls.
    const Material& mat = scene.materials[scene.objects[size_t(object)].material];
    const glm::vec3& lc = scene.lights[i].colour;
    const float strength =
        !lm.on      ? 0.0f
        : mat.unlit ? 1.0f
                    : lightStrength(scene.lights[i], p, n) * (lc.r + lc.g + lc.b) / 3.0f *
                          (mat.baseColour.r + mat.baseColour.g + mat.baseColour.b) / 3.0f;
    if (!lm.shadowed || strength <= 0.0f || !scene.objects[size_t(object)].receivesShadows) {
        return 0;
    }
    if (lm.frame.kind == shadow::FrameKind::Cube) {
        // All directions are in the map; depth clamp keeps even the nearest casters.
        const glm::vec3 toLight = lm.eye - p;
        const float dist = glm::length(toLight);
        const bool occluded = world.occluded(p, toLight / dist, 1e-4f, dist - 1e-4f, hit.triangle);
        return !occluded ? 0 : strength >= kVisible ? 1 : 2;
    }
    // Inside the light camera's volume? Outside, the map says nothing (lit).
    const glm::vec4 clip = lm.frame.clipFromWorld() * glm::vec4(p, 1.0f);
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    // Texel borders are in x and y; depth beyond far is simply outside (lit).
    const float edge = std::max(std::abs(ndc.x), std::abs(ndc.y));
    if (clip.w <= 0.0f || edge > 1.02f || std::abs(ndc.z) > 1.0f) {
        return 0;
    }
    if (edge > 0.98f) {
        return 2;
    }
    glm::vec3 dir;
    float tMax;
    const float depth = glm::dot(p - lm.eye, lm.axis);  // along the light's axis
    if (lm.frame.orthographic) {
        dir = -lm.axis;
        tMax = depth - lm.frame.near;
    } else {
        dir = glm::normalize(lm.eye - p);
        // Occluders closer to the light than its near plane are not in the map.
        const float cosine = std::max(glm::dot(-dir, lm.axis), 1e-3f);
        tMax = (depth - lm.frame.near) / cosine;
    }
    const bool occluded = world.occluded(p, dir, 1e-4f, tMax, hit.triangle);
    return !occluded ? 0 : strength >= kVisible ? 1 : 2;
}

}  // namespace

int GeometryShadows::count(PixelClass c) const {
    return int(std::count(classes.begin(), classes.end(), c));
}

GeometryShadows classifyPixels(const Scene& scene, const RenderOptions& options, int stride) {
    World world;
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const Object& obj = scene.objects[o];
        const Mesh& m = scene.meshes[obj.mesh];
        const glm::mat4 w = obj.worldFromModelAt(options.time);
        for (size_t i = 0; i + 2 < m.indices.size(); i += 3) {
            auto at = [&](size_t k) {
                return glm::vec3(w * glm::vec4(m.positions[m.indices[i + k]], 1.0f));
            };
            world.triangles.push_back({at(0), at(1), at(2), int(o)});
        }
        world.casts.push_back(obj.castsShadows);
    }
    const float aspect = float(options.width) / float(options.height);
    const shadow::FitScene fit = shadow::fitScene(scene, options.time, aspect);

    std::vector<LightModel> lights(scene.lights.size());
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& l = scene.lights[i];
        LightModel& lm = lights[i];
        lm.on = lightIsOn(scene, options, i);
        int size = 0;
        lm.frame = shadow::sizedLightCameraFrame(l, options.shadow, scene.camera, fit, size);
        lm.shadowed = lm.on && l.castsShadows && lm.frame.valid && options.shadow.enabled;
        const glm::mat4 worldFromLight = glm::inverse(lm.frame.lightFromWorld);
        lm.eye = glm::vec3(worldFromLight[3]);
        lm.axis = -glm::normalize(glm::vec3(worldFromLight[2]));
    }

    const glm::mat4 worldFromClip = glm::inverse(gnomon::clipFromView(scene.camera, aspect) *
                                                 gnomon::viewFromWorld(scene.camera));

    // One sample: which object the view ray through (px, py) sees and its per-light state.
    struct Sample {
        int object = -1;
        std::vector<int> state;
    };
    auto sample = [&](float px, float py) {
        Sample s;
        const float nx = px / float(options.width) * 2.0f - 1.0f;
        const float ny = 1.0f - py / float(options.height) * 2.0f;
        glm::vec4 a = worldFromClip * glm::vec4(nx, ny, -1.0f, 1.0f);
        glm::vec4 b = worldFromClip * glm::vec4(nx, ny, 1.0f, 1.0f);
        const glm::vec3 o = glm::vec3(a) / a.w;
        const glm::vec3 end = glm::vec3(b) / b.w;
        const glm::vec3 d = glm::normalize(end - o);
        auto hit = world.nearest(o, d, glm::length(end - o));
        if (!hit) return s;
        const Triangle& tri = world.triangles[size_t(hit->triangle)];
        s.object = tri.object;
        const glm::vec3 p = o + d * hit->t;
        glm::vec3 n = glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a));
        if (glm::dot(n, d) > 0.0f) n = -n;  // the side the camera sees
        for (size_t i = 0; i < lights.size(); ++i)
            s.state.push_back(lightState(world, scene, lights[i], i, *hit, p, n));
        return s;
    };

    GeometryShadows out;
    out.width = options.width;
    out.height = options.height;
    out.classes.assign(size_t(options.width) * options.height, PixelClass::Unknown);
    const float r = 2.5f;  // neighbourhood radius in pixels: edges and boundaries are Unknown
    const float offsets[9][2] = {{0, 0},  {-r, -r}, {r, -r}, {-r, r}, {r, r},
                                 {0, -r}, {0, r},   {-r, 0}, {r, 0}};
    for (int y = stride / 2; y < options.height; y += stride) {
        for (int x = stride / 2; x < options.width; x += stride) {
            const Sample centre = sample(x + 0.5f, y + 0.5f);
            PixelClass& cls = out.classes[size_t(y) * options.width + x];
            if (centre.object < 0) {
                cls = PixelClass::Background;
                continue;
            }
            bool consistent = true;
            for (int k = 1; k < 9 && consistent; ++k) {
                const Sample n = sample(x + 0.5f + offsets[k][0], y + 0.5f + offsets[k][1]);
                consistent = n.object == centre.object && n.state == centre.state;
            }
            if (!consistent) continue;
            const auto has = [&](int v) {
                return std::find(centre.state.begin(), centre.state.end(), v) != centre.state.end();
            };
            cls = has(2) ? PixelClass::Unknown : has(1) ? PixelClass::Shadowed : PixelClass::Lit;
        }
    }
    return out;
}

}  // namespace gnomon::test
