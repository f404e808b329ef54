// The loaders' shared last step (ModelFinish.h).
#include "scene/ModelFinish.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "gnomon/Error.h"
#include "scene/SceneUtil.h"

namespace gnomon {
namespace {

// gnomon has no exposure control: photometric intensities (tens of candela at lamp
// scale) would saturate. Keep their ratios and scale them so the brightest point or
// spot light gives 1 at a quarter of the scene's size, and no sun exceeds 1.
void scaleLights(Scene& scene, float radius) {
    float brightest = 0.0f, brightestSun = 0.0f;
    for (const Light& l : scene.lights) {
        (l.type == LightType::Directional ? brightestSun : brightest) =
            std::max(l.type == LightType::Directional ? brightestSun : brightest, l.intensity);
    }
    const float quarter = 0.5f * radius;
    const float pointScale = brightest > 0.0f ? quarter * quarter / brightest : 1.0f;
    const float sunScale = brightestSun > 1.0f ? 1.0f / brightestSun : 1.0f;
    for (Light& l : scene.lights)
        l.intensity *= l.type == LightType::Directional ? sunScale : pointScale;
    if (brightest > 0.0f || sunScale != 1.0f) {
        scene.warnings.push_back("light intensities scaled for display (point and spot x" +
                                 std::to_string(pointScale) + ", directional x" +
                                 std::to_string(sunScale) + ")");
    }
}

// Turns what the file placed (objects, their spins, lights, the file's camera) by `t`.
void turnModel(Scene& scene, const glm::mat4& t) {
    const glm::mat3 r(t);
    for (Object& o : scene.objects) {
        o.worldFromModel = t * o.worldFromModel;
        o.spin.pivot = r * o.spin.pivot;
        o.spin.axis = r * o.spin.axis;
    }
    for (Light& l : scene.lights) {
        l.position = r * l.position;
        l.direction = r * l.direction;
    }
}

void turnCamera(Camera& camera, const glm::mat4& t) {
    const glm::mat3 r(t);
    camera.eye = r * camera.eye;
    camera.centre = r * camera.centre;
    camera.up = r * camera.up;
}

}  // namespace

const char* toString(UpAxis v) {
    switch (v) {
        case UpAxis::Y:
            return "y";
        case UpAxis::Z:
            return "z";
        case UpAxis::X:
            return "x";
    }
    return "?";
}

std::optional<UpAxis> parseUpAxis(const std::string& text) {
    if (text == "y" || text == "Y") return UpAxis::Y;
    if (text == "z" || text == "Z") return UpAxis::Z;
    if (text == "x" || text == "X") return UpAxis::X;
    return std::nullopt;
}

glm::mat4 worldFromUp(UpAxis up) {
    switch (up) {
        case UpAxis::Z:
            return glm::mat4(glm::vec4(1, 0, 0, 0), glm::vec4(0, 0, -1, 0), glm::vec4(0, 1, 0, 0),
                             glm::vec4(0, 0, 0, 1));
        case UpAxis::X:
            return glm::mat4(glm::vec4(0, 1, 0, 0), glm::vec4(-1, 0, 0, 0), glm::vec4(0, 0, 1, 0),
                             glm::vec4(0, 0, 0, 1));
        case UpAxis::Y:
            break;
    }
    return glm::mat4(1.0f);
}

void untextureObjectsWithoutUvs(Scene& scene) {
    std::map<std::uint32_t, std::uint32_t> copyOf;
    for (Object& o : scene.objects) {
        if (scene.materials[o.material].baseColourTexture < 0 || !scene.meshes[o.mesh].uvs.empty())
            continue;
        auto [it, added] = copyOf.try_emplace(o.material, 0u);
        if (added) {
            Material copy = scene.materials[o.material];
            copy.baseColourTexture = -1;
            copy.name += " (untextured)";
            scene.materials.push_back(copy);
            it->second = std::uint32_t(scene.materials.size() - 1);
        }
        o.material = it->second;
    }
}

void addDefaultSun(Scene& scene) {
    if (!scene.lights.empty()) return;
    Light sun;
    sun.name = "default sun";
    sun.type = LightType::Directional;
    sun.direction = defaultSunDirection(scene.camera);
    sun.intensity = 1.0f;
    scene.lights.push_back(sun);
    scene.warnings.push_back(kDefaultSunWarning);
}

// A key light over the camera's right shoulder, as a photographer places one: from behind
// the camera and kDefaultSunTurn to its right, kDefaultSunElevation above the horizon.
// Shadows then fall away from the camera and to the left of their casters, where the camera
// sees them, not hidden behind the casters.
glm::vec3 defaultSunDirection(const Camera& camera) {
    constexpr float kDefaultSunTurn = glm::radians(50.0f);
    constexpr float kDefaultSunElevation = glm::radians(50.0f);
    const glm::vec3 up =
        glm::length(camera.up) > 0.0f ? glm::normalize(camera.up) : glm::vec3(0.0f, 1.0f, 0.0f);
    glm::vec3 back = camera.eye - camera.centre;  // towards the camera, levelled
    back -= up * glm::dot(back, up);
    if (!(glm::length(back) > 1e-6f * glm::length(camera.eye - camera.centre))) {
        return glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));  // looking straight down or up
    }
    back = glm::normalize(back);
    const glm::vec3 right = glm::cross(up, back);
    const glm::vec3 horizontal =
        std::cos(kDefaultSunTurn) * back + std::sin(kDefaultSunTurn) * right;
    const glm::vec3 toSun =
        std::cos(kDefaultSunElevation) * horizontal + std::sin(kDefaultSunElevation) * up;
    return -glm::normalize(toSun);
}

void frameWithCamera(Scene& scene, const Aabb& bounds) {
    const glm::vec3 centre = bounds.centre();
    const float radius = std::max(bounds.radius(), 1e-6f);
    Camera& cam = scene.camera;
    cam.centre = centre;
    // Three-quarters from above: 31 degrees round from the front, 29 degrees up.
    cam.eye = centre + glm::normalize(glm::vec3(0.6f, 0.65f, 1.0f)) * (2.6f * radius);
    cam.fovyDegrees = 45.0f;
    cam.near = radius * 0.02f;
    cam.far = radius * 6.0f;
    scene.warnings.push_back("no camera: one framing the scene was added");
}

void finishModelScene(Scene& scene, const LoadedModel& loaded) {
    const auto fail = [&](const std::string& what) {
        throw Error(ErrorKind::InvalidInput, loaded.file + ": " + what);
    };
    untextureObjectsWithoutUvs(scene);  // the loaders warned about each: no coordinates
    if (loaded.zeroAreaTriangles > 0) {
        scene.warnings.push_back(std::to_string(loaded.zeroAreaTriangles) +
                                 " zero-area triangles skipped");
    }
    if (scene.objects.empty()) fail("the scene has no triangles to draw");

    // The file's camera is placed in the file's frame, then turned with the model; a camera
    // framing the model is placed once the model stands up.
    const glm::mat4 upright = worldFromUp(loaded.up);
    const std::vector<Aabb> modelBounds = meshBounds(scene);
    if (loaded.placeCamera) {
        loaded.placeCamera(scene.camera, worldBounds(scene, modelBounds, 0.0, false));
        turnCamera(scene.camera, upright);
    }
    if (loaded.up != UpAxis::Y) turnModel(scene, upright);
    // World bounds of what is drawn (as the renderer's fitting sees them).
    const Aabb bounds = worldBounds(scene, modelBounds, 0.0, false);
    if (loaded.photometricLights) scaleLights(scene, std::max(bounds.radius(), 1e-6f));
    if (!loaded.placeCamera) frameWithCamera(scene, bounds);
    addDefaultSun(scene);  // placed for the camera
    scene.options.width = scene.options.height = 512;
    scene.options.shading.output = OutputEncoding::Srgb;

    if (const std::vector<std::string> problems = scene.validate(); !problems.empty()) {
        std::string all;
        for (const std::string& p : problems)
            all += (all.empty() ? "" : "; ") + p;
        fail("the loaded scene is inconsistent: " + all);
    }
}

}  // namespace gnomon
