// Scene model behaviour: animated transforms, consistency checks with readable messages,
// bounds for shadow fitting.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/SceneUtil.h"

namespace gnomon {

std::uint64_t Revision::next() {
    static std::atomic<std::uint64_t> counter{0};
    return ++counter;
}

glm::mat4 Object::worldFromModelAt(double seconds) const {
    if (spin.degreesPerSecond == 0.0f || seconds == 0.0) return worldFromModel;
    const double degrees = std::fmod(double(spin.degreesPerSecond) * seconds, 360.0);
    glm::mat4 r = glm::translate(glm::mat4(1.0f), spin.pivot);
    r = glm::rotate(r, glm::radians(float(degrees)), glm::normalize(spin.axis));
    r = glm::translate(r, -spin.pivot);
    return r * worldFromModel;
}

namespace {
bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The distance from `from` to the farthest corner of the box [lo, hi].
float farthestCorner(const glm::vec3& lo, const glm::vec3& hi, const glm::vec3& from) {
    float far = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p(corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y,
                          corner & 4 ? hi.z : lo.z);
        far = std::max(far, glm::length(p - from));
    }
    return far;
}
}  // namespace

std::vector<std::string> Scene::validate() const {
    std::vector<std::string> problems = validateContent();
    for (std::string& p : validateLightsAndCamera())
        problems.push_back(std::move(p));
    return problems;
}

std::vector<std::string> Scene::validateContent() const {
    std::vector<std::string> problems;
    auto add = [&](const std::string& s) { problems.push_back("scene '" + name + "': " + s); };
    for (size_t m = 0; m < meshes.size(); ++m) {
        const Mesh& mesh = meshes[m];
        const std::string where = "meshes[" + std::to_string(m) + "] ('" + mesh.name + "')";
        if (mesh.normals.size() != mesh.positions.size()) {
            add(where + " has " + std::to_string(mesh.normals.size()) + " normals for " +
                std::to_string(mesh.positions.size()) + " positions");
        }
        if (!mesh.colours.empty() && mesh.colours.size() != mesh.positions.size()) {
            add(where + " has " + std::to_string(mesh.colours.size()) + " colours for " +
                std::to_string(mesh.positions.size()) + " positions");
        }
        if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()) {
            add(where + " has " + std::to_string(mesh.uvs.size()) + " texture coordinates for " +
                std::to_string(mesh.positions.size()) + " positions");
        }
        if (mesh.indices.size() % 3 != 0) add(where + " index count is not a multiple of 3");
        for (size_t i = 0; i < mesh.indices.size(); ++i) {
            if (mesh.indices[i] >= mesh.positions.size()) {
                add(where + " index " + std::to_string(i) + " = " +
                    std::to_string(mesh.indices[i]) + " is out of range (" +
                    std::to_string(mesh.positions.size()) + " vertices)");
                break;
            }
        }
        for (size_t i = 0; i < mesh.positions.size(); ++i) {
            if (!finite(mesh.positions[i])) {
                add(where + " position " + std::to_string(i) + " is not finite");
                break;
            }
        }
    }
    for (size_t t = 0; t < textures.size(); ++t) {
        const Texture& tex = textures[t];
        if (tex.width <= 0 || tex.height <= 0 ||
            tex.rgba.size() != std::size_t(tex.width) * std::size_t(tex.height) * 4) {
            add("textures[" + std::to_string(t) + "] ('" + tex.name + "') holds " +
                std::to_string(tex.rgba.size()) + " bytes for " + std::to_string(tex.width) + "x" +
                std::to_string(tex.height) + " RGBA texels");
        }
    }
    for (size_t m = 0; m < materials.size(); ++m) {
        const Material& mat = materials[m];
        const std::string where = "materials[" + std::to_string(m) + "] ('" + mat.name + "')";
        if (mat.baseColourTexture >= int(textures.size()) || mat.baseColourTexture < -1) {
            add(where + " refers to a missing texture");
        }
        if (!(mat.alpha >= 0.0f && mat.alpha <= 1.0f) ||
            !(mat.alphaCutoff >= 0.0f && mat.alphaCutoff <= 1.0f)) {
            add(where + " alpha and alpha cutoff must be within 0..1");
        }
    }
    for (size_t o = 0; o < objects.size(); ++o) {
        const std::string where = "objects[" + std::to_string(o) + "] ('" + objects[o].name + "')";
        if (objects[o].mesh >= meshes.size()) add(where + " refers to a missing mesh");
        if (objects[o].material >= materials.size()) add(where + " refers to a missing material");
        if (objects[o].mesh < meshes.size() && objects[o].material < materials.size() &&
            materials[objects[o].material].baseColourTexture >= 0 &&
            meshes[objects[o].mesh].uvs.empty()) {
            add(where + " has a textured material but its mesh has no texture coordinates");
        }
        const Spin& spin = objects[o].spin;
        if (!std::isfinite(spin.degreesPerSecond) ||
            (spin.degreesPerSecond != 0.0f && !(glm::length(spin.axis) > 1e-6f))) {
            add(where + " spins about a zero or non-finite axis");
        }
    }
    return problems;
}

std::vector<std::string> Scene::validateLightsAndCamera() const {
    std::vector<std::string> problems;
    auto add = [&](const std::string& s) { problems.push_back("scene '" + name + "': " + s); };
    for (size_t l = 0; l < lights.size(); ++l) {
        const Light& light = lights[l];
        // Made only for a problem: the renderer checks the lights every frame, and a light's
        // name would otherwise cost an allocation per light per frame.
        auto where = [&] { return "lights[" + std::to_string(l) + "] ('" + light.name + "')"; };
        if (!finite(light.position) || !finite(light.direction) || !finite(light.colour)) {
            add(where() + " has a non-finite position, direction or colour");
        }
        if (light.type != LightType::Point && glm::length(light.direction) < 1e-6f) {
            add(where() + " has a zero direction");
        }
        const Attenuation& a = light.attenuation;
        if (!(a.constant >= 0.0f && a.linear >= 0.0f && a.quadratic >= 0.0f &&
              a.constant + a.linear + a.quadratic > 0.0f)) {
            add(where() + " attenuation needs c0, c1, c2 >= 0 and not all zero");
        }
        if (!(light.range >= 0.0f) || !std::isfinite(light.range)) {
            add(where() + " range must be >= 0 (0: unlimited)");
        }
        if (light.type == LightType::Spot &&
            !(light.innerConeDegrees >= 0.0f && light.innerConeDegrees <= light.outerConeDegrees &&
              light.outerConeDegrees > 0.0f && light.outerConeDegrees < 90.0f)) {
            add(where() + " spot cone needs 0 <= inner <= outer < 90 degrees");
        }
        if (light.shadowMapSize != 0 && (light.shadowMapSize < 64 || light.shadowMapSize > 8192)) {
            add(where() + " shadow map size " + std::to_string(light.shadowMapSize) +
                " is outside 64..8192 (0: its default)");
        }
        const ShadowCamera& c = light.shadowCamera;
        if (c.policy != ShadowCameraPolicy::Fit && !(c.near > 0.0f && c.far > c.near)) {
            add(where() + " shadow camera needs 0 < near < far");
        }
        if (c.policy == ShadowCameraPolicy::Manual &&
            glm::length(c.target - light.position) < 1e-6f) {
            add(where() + " shadow camera looks at its own position (target == position)");
        }
        if (c.policy == ShadowCameraPolicy::Course &&
            glm::length(camera.centre - light.position) < 1e-6f) {
            add(where() +
                " sits at the view camera's centre, where its course-policy camera looks");
        }
    }
    if (!(camera.near > 0.0f && camera.far > camera.near)) add("camera needs 0 < near < far");
    if (glm::length(camera.centre - camera.eye) < 1e-6f) add("camera eye equals its centre");
    return problems;
}

glm::vec3 sunDirection(float azimuthDegrees, float elevationDegrees) {
    const float az = glm::radians(azimuthDegrees), el = glm::radians(elevationDegrees);
    return -glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
}

// Engines size a sun's map so: Unity's and Unreal's 2048 per map or cascade; at 1024 the real
// scenes' sun views run short of texels (docs/techniques/shadow-maps.md, "Map size"). Area
// lights are fitted as suns are. Spots, and point lights drawn as one frustum, are fitted to
// the part of what the view sees that their one map covers, and run short of texels as suns
// do. A point light drawn as a cube gets 1024 per face (shadow::FramePlan): six faces at 2048
// hold 1.5 times the texels of a 2048² map, and llvmpipe redraws them far slower.
int shadowMapSizeOf(const Light& light) {
    return light.shadowMapSize > 0 ? light.shadowMapSize : kDefaultShadowMapSize;
}

int shadowMapSizeOf(const Light& light, const ShadowOptions& options) {
    return options.mapSize > 0 ? options.mapSize : shadowMapSizeOf(light);
}

int firstCasterMapSize(const Scene& scene, const ShadowOptions& options) {
    for (const Light& l : scene.lights)
        if (l.castsShadows) return shadowMapSizeOf(l, options);
    return options.mapSize > 0 ? options.mapSize : 1024;
}

std::vector<Aabb> meshBounds(const Scene& scene) {
    std::vector<Aabb> boxes(scene.meshes.size());
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        for (const glm::vec3& p : scene.meshes[m].positions)
            boxes[m].extend(p);
    }
    return boxes;
}

Aabb worldBounds(const Scene& scene, const std::vector<Aabb>& meshBoxes, double seconds,
                 bool castersOnly) {
    Aabb box;
    for (const Object& o : scene.objects) {
        if (castersOnly && !o.castsShadows) continue;
        box.extend(meshBoxes[o.mesh].transformed(o.worldFromModelAt(seconds)));
    }
    return box;
}

RenderOptions presetOptions(const Scene& scene, Preset preset) {
    if (preset == Preset::Default) return scene.options;
    if (scene.textbookOptions) return *scene.textbookOptions;
    RenderOptions o = scene.options;
    o.shadow.biasConstant = 0.005f;
    o.shadow.biasDepthAware = 0.0f;
    o.shadow.biasSlope = 0.0f;
    o.shadow.biasUnits = 0.0f;
    o.shadow.normalOffset = 0.0f;
    o.shadow.receiverPlane = false;
    o.shadow.cull = CullMode::None;
    o.shadow.filter = ShadowFilter::None;
    o.shadow.mapFilter = MapFilter::Nearest;
    o.shadow.shadowRays = ShadowRayMode::Off;
    return o;
}

void sceneBounds(const Scene& scene, glm::vec3& lo, glm::vec3& hi) {
    const Aabb box = worldBounds(scene, meshBounds(scene), 0.0, false);
    lo = box.empty() ? glm::vec3(0.0f) : box.min;
    hi = box.empty() ? glm::vec3(0.0f) : box.max;
}

std::size_t triangleCount(const Scene& scene, bool castersOnly) {
    std::size_t triangles = 0;
    for (const Object& o : scene.objects)
        if ((o.castsShadows || !castersOnly) && o.mesh < scene.meshes.size())
            triangles += scene.meshes[o.mesh].indices.size() / 3;
    return triangles;
}

void fitCameraDepth(const Scene& scene, Camera& camera) {
    glm::vec3 lo, hi;
    sceneBounds(scene, lo, hi);
    const float far = farthestCorner(lo, hi, camera.eye);
    if (!(far > 0.0f) || !std::isfinite(far)) return;
    camera.far = 1.05f * far;
    camera.near = camera.far / 2000.0f;
}

void fitShadowCameraDepth(const Scene& scene, const Light& light, ShadowCamera& camera) {
    glm::vec3 lo, hi;
    sceneBounds(scene, lo, hi);
    const float far = farthestCorner(lo, hi, light.position);
    if (!(far > 0.0f) || !std::isfinite(far)) return;
    camera.far = 1.05f * far;
    // The nearest the light comes to the bounds: nothing nearer casts.
    const float nearest = glm::length(glm::clamp(light.position, lo, hi) - light.position);
    camera.near = std::max(0.95f * nearest, camera.far / 2000.0f);
}

glm::vec3 coordinateOrigin(const Aabb& worldBox) {
    if (worldBox.empty()) return glm::vec3(0.0f);
    const glm::vec3 c = worldBox.centre();
    const float r = std::max(worldBox.radius(), 1e-30f);
    if (!(glm::length(c) > 4.0f * r) || !std::isfinite(glm::length(c))) return glm::vec3(0.0f);
    const float grid = std::exp2(std::ceil(std::log2(r)));
    return glm::round(c / grid) * grid;
}

glm::vec3 sceneOrigin(const Scene& scene, double seconds) {
    return coordinateOrigin(worldBounds(scene, meshBounds(scene), seconds, false));
}

glm::vec3 relativeTo(const glm::vec3& worldPoint, const glm::vec3& origin) {
    return glm::vec3(glm::dvec3(worldPoint) - glm::dvec3(origin));
}

void makeRelative(Object& object, const glm::vec3& origin) {
    object.worldFromModel = glm::mat4(glm::translate(glm::dmat4(1.0), -glm::dvec3(origin)) *
                                      glm::dmat4(object.worldFromModel));
    object.spin.pivot = relativeTo(object.spin.pivot, origin);
}

void makeRelative(Light& light, const glm::vec3& origin) {
    light.position = relativeTo(light.position, origin);
    light.shadowCamera.target = relativeTo(light.shadowCamera.target, origin);
}

void makeRelative(Camera& camera, const glm::vec3& origin) {
    camera.eye = relativeTo(camera.eye, origin);
    camera.centre = relativeTo(camera.centre, origin);
}

bool lightIsOn(const Scene& scene, const RenderOptions& options, std::size_t index) {
    if (options.lightOnly >= 0) return index == std::size_t(options.lightOnly);
    return scene.lights[index].enabled;
}

void addGround(Scene& scene) {
    const Aabb box = worldBounds(scene, meshBounds(scene), 0.0, false);
    if (box.empty()) return;
    const float r = std::max(box.radius(), 1e-6f);
    const glm::vec3 c = box.centre();
    const float y = box.min.y - 1e-4f * r;  // a hair below: no fighting with bottom faces
    const float h = 5.0f * r;
    Mesh m;
    m.name = "ground";
    m.positions = {
        {c.x - h, y, c.z - h}, {c.x - h, y, c.z + h}, {c.x + h, y, c.z + h}, {c.x + h, y, c.z - h}};
    m.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
    m.indices = {0, 1, 2, 0, 2, 3};
    scene.meshes.push_back(std::move(m));
    Material grey;
    grey.name = "ground";
    grey.baseColour = glm::vec3(0.6f);
    grey.specular = 0.0f;
    scene.materials.push_back(grey);
    Object o;
    o.name = "ground";
    o.mesh = std::uint32_t(scene.meshes.size() - 1);
    o.material = std::uint32_t(scene.materials.size() - 1);
    o.castsShadows = false;
    scene.objects.push_back(o);
    scene.revision.bump();  // an edit in place: a renderer that synced the scene must see it
}

const char* toString(LightType v) {
    switch (v) {
        case LightType::Directional:
            return "directional";
        case LightType::Spot:
            return "spot";
        case LightType::Point:
            return "point";
        case LightType::Area:
            return "area";
    }
    return "?";
}

const char* toString(ShadowCameraPolicy v) {
    switch (v) {
        case ShadowCameraPolicy::Fit:
            return "fit";
        case ShadowCameraPolicy::Manual:
            return "manual";
        case ShadowCameraPolicy::Course:
            return "course";
    }
    return "?";
}

const char* toString(Projection v) {
    switch (v) {
        case Projection::Perspective:
            return "perspective";
        case Projection::Orthographic:
            return "orthographic";
    }
    return "?";
}

}  // namespace gnomon
