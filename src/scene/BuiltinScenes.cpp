// The built-in scenes: the textbooks' set-ups with their exact numbers.
// book-*: "the book", K. Matsuda and R. Lea, WebGL Programming Guide, ch. 10, samples Shadow
// and Shadow_highp; course-*: "the course text", W. Brown, Learn Computer Graphics using
// WebGL, §12.6 Shadows, its two-light experiment (its models rebuilt from their numbers);
// tutorial-room*: "the tutorial", the shadow-mapping chapter of the online WebGL tutorial
// that follows its lighting chapter: its sun over a room, with thick (boxes) or thin
// (single quads) walls.
#include <cmath>
#include <functional>

#include <glm/gtc/matrix_transform.hpp>

#include "gnomon/Error.h"
#include "scene/MeshBuilder.h"

namespace gnomon {
namespace {

std::uint32_t addMesh(Scene& s, Mesh m) {
    s.meshes.push_back(std::move(m));
    return std::uint32_t(s.meshes.size() - 1);
}

std::uint32_t addMaterial(Scene& s, Material m) {
    s.materials.push_back(std::move(m));
    return std::uint32_t(s.materials.size() - 1);
}

Object& addObject(Scene& s, const std::string& name, std::uint32_t mesh, std::uint32_t material,
                  const glm::mat4& worldFromModel = glm::mat4(1.0f)) {
    Object o;
    o.name = name;
    o.mesh = mesh;
    o.material = material;
    o.worldFromModel = worldFromModel;
    s.objects.push_back(o);
    return s.objects.back();
}

// WebGL book, Shadow.js / Shadow_highp.js.
// A textbook's way: one constant tolerance and nothing else (the depth pass's remedies off).
RenderOptions textbookSettings(RenderOptions o, DepthFormat format, MapFilter lookup, int boxSize,
                               float tolerance) {
    o.shadow.depthFormat = format;
    o.shadow.mapFilter = lookup;
    o.shadow.filter = boxSize > 1 ? ShadowFilter::Pcf : ShadowFilter::None;
    o.shadow.pcfSize = boxSize;
    o.shadow.biasConstant = tolerance;
    o.shadow.biasDepthAware = 0.0f;
    o.shadow.biasSlope = 0.0f;
    o.shadow.biasUnits = 0.0f;
    o.shadow.normalOffset = 0.0f;
    o.shadow.receiverPlane = false;
    o.shadow.cull = CullMode::None;
    o.shadow.pointMaps = PointMaps::Cube;  // the tutorial's point light is one cube map
    o.shadow.shadowRays = ShadowRayMode::Off;
    return o;
}

Scene bookTriangle(bool highPrecision, const glm::vec3& lightPosition, float lightFar,
                   const std::string& name, const std::string& description) {
    Scene s;
    s.name = name;
    s.description = description;
    Material unlit;
    unlit.name = "vertex colour";
    unlit.unlit = true;
    unlit.doubleSided = true;
    const std::uint32_t mat = addMaterial(s, unlit);

    const glm::vec3 tri[3] = {{-0.8f, 3.5f, 0.0f}, {0.8f, 3.5f, 0.0f}, {0.0f, 3.5f, 1.8f}};
    const glm::vec3 triColour[3] = {{1.0f, 0.5f, 0.0f}, {1.0f, 0.5f, 0.0f}, {1.0f, 0.0f, 0.0f}};
    Object& triangle =
        addObject(s, "triangle", addMesh(s, mesh::triangle("triangle", tri, triColour)), mat);
    triangle.spin = Spin{{0.0f, 1.0f, 0.0f}, 40.0f, {0.0f, 0.0f, 0.0f}};

    Mesh plane = mesh::quad("plane", {3.0f, -1.7f, 2.5f}, {3.0f, -1.7f, -2.5f},
                            {-3.0f, -1.7f, -2.5f}, {-3.0f, -1.7f, 2.5f});
    plane.colours.assign(plane.positions.size(), glm::vec3(1.0f));
    const glm::mat4 tilt =
        glm::rotate(glm::mat4(1.0f), glm::radians(-45.0f), glm::normalize(glm::vec3(0, 1, 1)));
    addObject(s, "plane", addMesh(s, std::move(plane)), mat, tilt);

    Light light;
    light.name = "light";
    light.type = LightType::Point;
    light.position = lightPosition;
    light.shadowMapSize = 2048;  // the shipped code (the text says 1024)
    light.shadowCamera.policy = ShadowCameraPolicy::Manual;
    light.shadowCamera.projection = Projection::Perspective;
    light.shadowCamera.target = glm::vec3(0.0f);
    light.shadowCamera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    light.shadowCamera.fovyDegrees = 70.0f;
    light.shadowCamera.aspect = 1.0f;
    light.shadowCamera.near = 1.0f;
    light.shadowCamera.far = lightFar;
    s.lights.push_back(light);

    s.camera.eye = {0.0f, 7.0f, 9.0f};
    s.camera.centre = {0.0f, 0.0f, 0.0f};
    s.camera.up = {0.0f, 1.0f, 0.0f};
    s.camera.fovyDegrees = 45.0f;
    s.camera.near = 1.0f;
    s.camera.far = 100.0f;
    s.ambient = glm::vec3(0.0f);
    s.options.width = s.options.height = 400;
    s.options.shading.shadowedRule = ShadowedRule::Factor;
    s.options.shading.shadowFactor = 0.7f;
    // Shadow.js: depth in the red channel, LINEAR lookups, 0.005; Shadow_highp.js: packed
    // RGBA (base 256), NEAREST lookups, 0.0015.
    s.textbookOptions =
        highPrecision ? textbookSettings(s.options, DepthFormat::Rgba8Packed256, MapFilter::Nearest,
                                         1, 0.0015f)
                      : textbookSettings(s.options, DepthFormat::R8, MapFilter::Linear, 1, 0.005f);
    return s;
}

// Course text, lesson 12.6: two lights, orthographic light cameras looking at the view
// camera's centre with its up vector; the model drawn at the origin and at (-4, 0, -4).
Scene courseScene(const std::string& name, const std::string& description,
                  const std::function<void(Scene&, const glm::mat4&)>& addModel) {
    Scene s;
    s.name = name;
    s.description = description;
    addModel(s, glm::mat4(1.0f));
    addModel(s, glm::translate(glm::mat4(1.0f), glm::vec3(-4.0f, 0.0f, -4.0f)));
    for (int i = 0; i < 2; ++i) {
        Light light;
        light.name = i == 0 ? "light 0" : "light 1";
        light.type = LightType::Point;
        light.position = {i == 0 ? 3.0f : -3.0f, 0.0f, 5.0f};
        light.attenuation = {1.0f, 0.1f, 0.0f};
        light.shadowMapSize = 512;
        light.shadowCamera.policy = ShadowCameraPolicy::Course;
        light.shadowCamera.projection = Projection::Orthographic;
        light.shadowCamera.left = light.shadowCamera.bottom = -2.0f;
        light.shadowCamera.right = light.shadowCamera.top = 2.0f;
        light.shadowCamera.near = 1.0f;
        light.shadowCamera.far = 20.0f;
        light.shadowCamera.fovyDegrees = 45.0f;  // used when switched to perspective
        light.shadowCamera.aspect = 1.0f;
        s.lights.push_back(light);
    }
    s.camera.eye = {0.0f, 0.0f, 5.0f};
    s.camera.centre = {0.0f, 0.0f, 0.0f};
    s.camera.fovyDegrees = 45.0f;
    s.camera.aspect = 1.0f;
    s.camera.near = 1.0f;
    s.camera.far = 20.0f;
    s.ambient = glm::vec3(0.3f);
    s.options.shading.shadowedRule = ShadowedRule::AmbientOnly;
    // The course demo: a depth texture looked up with LINEAR filtering, tolerance 0.00001.
    s.textbookOptions =
        textbookSettings(s.options, DepthFormat::Depth24, MapFilter::Linear, 1, 0.00001f);
    return s;
}

Material courseMaterial(const std::string& name, const glm::vec3& diffuse) {
    Material m;
    m.name = name;
    m.baseColour = diffuse;
    m.specular = 0.5f;
    m.shininess = 30.0f;
    m.doubleSided = true;
    return m;
}

void addThreePlanes(Scene& s, const glm::mat4& at) {
    if (s.meshes.empty()) {
        s.meshes.push_back(mesh::quad("blue", {-0.5f, 1.25f, 0.5f}, {0.5f, 1.25f, 0.5f},
                                      {0.5f, 1.25f, -0.5f}, {-0.5f, 1.25f, -0.5f}));
        s.meshes.push_back(mesh::quad("green", {-0.5f, -0.5f, 0.5f}, {0.5f, -0.5f, 0.5f},
                                      {0.5f, 0.5f, 0.5f}, {-0.5f, 0.5f, 0.5f}));
        s.meshes.push_back(mesh::quad("red", {-1.0f, -1.0f, 0.0f}, {1.0f, -1.0f, 0.0f},
                                      {1.0f, 1.0f, 0.0f}, {-1.0f, 1.0f, 0.0f}));
        addMaterial(s, courseMaterial("blue", {0.0f, 0.0f, 0.8f}));
        addMaterial(s, courseMaterial("green", {0.0f, 0.8f, 0.0f}));
        addMaterial(s, courseMaterial("red", {0.8f, 0.0f, 0.0f}));
    }
    for (std::uint32_t i = 0; i < 3; ++i)
        addObject(s, s.meshes[i].name, i, i, at);
}

// "Cubes along axes": cube size and offsets measured from the course text's xyz_blocks.obj model.
void addCubes(Scene& s, const glm::mat4& at) {
    const float size = 0.982f;
    if (s.meshes.empty()) {
        s.meshes.push_back(mesh::box("cube", glm::vec3(0.0f), glm::vec3(size)));
        addMaterial(s, courseMaterial("white", glm::vec3(0.8f)));
        addMaterial(s, courseMaterial("x red", {0.64f, 0.15f, 0.109f}));
        addMaterial(s, courseMaterial("y green", {0.311f, 0.64f, 0.347f}));
        addMaterial(s, courseMaterial("z blue", {0.075f, 0.285f, 0.8f}));
        for (Material& m : s.materials)
            m.doubleSided = false;  // closed boxes
    }
    const glm::vec3 offsets[4] = {{0, 0, 0}, {size, 0, 0}, {0, size, 0}, {0, 0, size}};
    const char* names[4] = {"centre cube", "x cube", "y cube", "z cube"};
    for (std::uint32_t i = 0; i < 4; ++i) {
        addObject(s, names[i], 0, i, at * glm::translate(glm::mat4(1.0f), offsets[i]));
    }
}

// The tutorial's lights (its numbers). Its sun direction; the sun's camera eye
// (-9, 27, -18) lies 33.7 units back along it, which is why the tutorial's near 25 / far 40
// enclose the scene; the area light's plane passes through the same point.
const glm::vec3 kSunDirection = glm::normalize(glm::vec3(0.267f, -0.802f, 0.535f));
const glm::vec3 kSunEye{-9.0f, 27.0f, -18.0f};

Light tutorialSun() {
    Light sun;
    sun.name = "sun";
    sun.type = LightType::Directional;
    sun.direction = kSunDirection;
    sun.intensity = 0.75f;
    sun.shadowMapSize = 2048;
    sun.shadowCamera.policy = ShadowCameraPolicy::Fit;
    return sun;
}

// Inverse-square falloff with an intensity, as the tutorial lights its spot, area and point.
Light inverseSquare(const std::string& name, LightType type, const glm::vec3& position,
                    float colour, float intensity) {
    Light l;
    l.name = name;
    l.type = type;
    l.position = position;
    l.colour = glm::vec3(colour);
    l.intensity = intensity;
    l.attenuation = {0.0f, 0.0f, 1.0f};
    l.shadowMapSize = 2048;
    l.shadowCamera.policy = ShadowCameraPolicy::Fit;
    return l;
}

// The room lit by one of the tutorial's light types instead of the fitted sun.
Scene tutorialLight(LightType type, const std::string& name, const std::string& description);

// The tutorial's sun over a room: floor, two walls, boxes (one against a wall).
Scene tutorialRoom(bool thin, const std::string& name, const std::string& description) {
    Scene s;
    s.name = name;
    s.description = description;
    Material floor{"floor", {0.75f, 0.75f, 0.7f}, 0.1f, 16.0f, false, thin};
    Material wall{"wall", {0.7f, 0.72f, 0.8f}, 0.1f, 16.0f, false, thin};
    Material boxMat{"box", {0.85f, 0.45f, 0.25f}, 0.4f, 40.0f, false, false};
    const auto mFloor = addMaterial(s, floor), mWall = addMaterial(s, wall),
               mBox = addMaterial(s, boxMat);
    const float half = 10.0f, height = 6.0f, t = 0.5f;
    if (thin) {
        addObject(s, "floor",
                  addMesh(s, mesh::quad("floor", {-half, 0, -half}, {-half, 0, half},
                                        {half, 0, half}, {half, 0, -half})),
                  mFloor);
        addObject(s, "back wall",
                  addMesh(s, mesh::quad("back wall", {-half, 0, half}, {-half, height, half},
                                        {half, height, half}, {half, 0, half})),
                  mWall);
        addObject(s, "side wall",
                  addMesh(s, mesh::quad("side wall", {half, 0, half}, {half, height, half},
                                        {half, height, -half}, {half, 0, -half})),
                  mWall);
    } else {
        addObject(
            s, "floor",
            addMesh(s, mesh::box("floor", {0, -t / 2, 0}, {2 * half + 2 * t, t, 2 * half + 2 * t})),
            mFloor);
        addObject(s, "back wall",
                  addMesh(s, mesh::box("back wall", {0, height / 2, half + t / 2},
                                       {2 * half + 2 * t, height, t})),
                  mWall);
        addObject(s, "side wall",
                  addMesh(s, mesh::box("side wall", {half + t / 2, height / 2, 0},
                                       {t, height, 2 * half})),
                  mWall);
    }
    addObject(s, "cube", addMesh(s, mesh::box("cube", {-3.0f, 1.0f, -2.0f}, glm::vec3(2.0f))),
              mBox);
    addObject(s, "pillar", addMesh(s, mesh::box("pillar", {4.0f, 2.0f, 5.0f}, {1.0f, 4.0f, 1.0f})),
              mBox);
    addObject(s, "slab on wall",
              addMesh(s, mesh::box("slab on wall", {9.0f, 1.5f, -4.0f}, {2.0f, 3.0f, 2.0f})), mBox);
    addObject(s, "low box",
              addMesh(s, mesh::box("low box", {0.5f, 0.25f, 3.0f}, {3.0f, 0.5f, 1.5f})), mBox);

    s.lights.push_back(tutorialSun());

    // From the side, so the shadows (cast towards +z) lie across the view, not behind boxes.
    s.camera.eye = {-14.0f, 9.0f, -3.0f};
    s.camera.centre = {2.0f, 1.0f, 3.0f};
    s.camera.fovyDegrees = 50.0f;
    s.camera.near = 0.5f;
    s.camera.far = 80.0f;
    s.ambient = glm::vec3(0.1f);
    // The tutorial: depth packed in base 255, one nearest lookup, 0.00575.
    s.textbookOptions =
        textbookSettings(s.options, DepthFormat::Rgba8Packed255, MapFilter::Nearest, 1, 0.00575f);
    return s;
}

Scene tutorialLight(LightType type, const std::string& name, const std::string& description) {
    Scene s = tutorialRoom(false, name, description);
    s.lights.clear();
    switch (type) {
        case LightType::Directional: {
            // The tutorial's own light camera: orthographic from (-9, 27, -18), near 25, far 40.
            Light sun = tutorialSun();
            sun.position = kSunEye;
            sun.shadowCamera.policy = ShadowCameraPolicy::Manual;
            sun.shadowCamera.projection = Projection::Orthographic;
            sun.shadowCamera.target = glm::vec3(0.0f);
            sun.shadowCamera.left = sun.shadowCamera.bottom = -15.0f;
            sun.shadowCamera.right = sun.shadowCamera.top = 15.0f;
            sun.shadowCamera.near = 25.0f;
            sun.shadowCamera.far = 40.0f;
            s.lights.push_back(sun);
            break;
        }
        case LightType::Spot: {
            Light spot =
                inverseSquare("spot", LightType::Spot, {-3.0f, 10.0f, -6.0f}, 0.3f, 300.0f);
            spot.direction = glm::normalize(glm::vec3(0.0f) - spot.position);
            spot.innerConeDegrees = 35.0f;  // the tutorial gives no cone: one that fills the room
            spot.outerConeDegrees = 45.0f;
            s.lights.push_back(spot);
            break;
        }
        case LightType::Area: {
            Light area = inverseSquare("area", LightType::Area, kSunEye, 0.5f, 1000.0f);
            area.direction = kSunDirection;
            s.lights.push_back(area);
            break;
        }
        case LightType::Point: {
            Light point =
                inverseSquare("point", LightType::Point, {0.0f, 3.0f, -1.5f}, 0.3f, 20.0f);
            point.shadowMapSize = 1024;  // per face: six of them
            s.lights.push_back(point);
            break;
        }
    }
    // The tutorial's tolerances: spot 0.025, area 0.005, both with its 5x5 box of lookups;
    // point 0.02 on distance/far, which our perspective cube depth has no single equivalent
    // of: 0.0005 keeps its look at the room's distances.
    const float tolerance = type == LightType::Spot    ? 0.025f
                            : type == LightType::Area  ? 0.005f
                            : type == LightType::Point ? 0.0005f
                                                       : 0.00575f;
    s.textbookOptions = textbookSettings(s.options, DepthFormat::Rgba8Packed255, MapFilter::Nearest,
                                         type == LightType::Directional ? 1 : 5, tolerance);
    return s;
}

// Every light type at once, 16 of them casting shadows into one main pass.
Scene mixedLights(const std::string& name, const std::string& description) {
    Scene s = tutorialRoom(false, name, description);
    s.lights.clear();
    Light sun = tutorialSun();
    sun.intensity = 0.25f;
    sun.colour = {1.0f, 0.95f, 0.8f};
    s.lights.push_back(sun);
    Light area = inverseSquare("area", LightType::Area, kSunEye, 0.2f, 1000.0f);
    area.direction = glm::normalize(glm::vec3(-0.4f, -0.8f, 0.45f));
    s.lights.push_back(area);
    s.lights.push_back(
        inverseSquare("point a", LightType::Point, {0.0f, 3.0f, -1.5f}, 0.25f, 12.0f));
    Light pointB = inverseSquare("point b", LightType::Point, {6.0f, 4.0f, 6.0f}, 0.25f, 12.0f);
    pointB.colour = {0.35f, 0.25f, 0.15f};
    s.lights.push_back(pointB);
    for (int i = 0; i < 12; ++i) {
        const float a = glm::radians(30.0f * float(i));
        const glm::vec3 at{7.0f * std::cos(a), 7.0f, 7.0f * std::sin(a)};
        Light spot = inverseSquare("spot " + std::to_string(i), LightType::Spot, at, 0.2f, 40.0f);
        spot.colour = {0.5f + 0.5f * std::cos(a), 0.5f + 0.5f * std::cos(a + 2.1f),
                       0.5f + 0.5f * std::cos(a + 4.2f)};
        spot.colour *= 0.2f;
        spot.direction = glm::normalize(glm::vec3(0.0f, 0.0f, 0.0f) - at);
        spot.innerConeDegrees = 30.0f;
        spot.outerConeDegrees = 40.0f;
        s.lights.push_back(spot);
    }
    // One size for the 2D maps (they share an array sized to the largest); cubes smaller.
    for (Light& l : s.lights)
        l.shadowMapSize = l.type == LightType::Point ? 512 : 1024;
    return s;
}

struct Builtin {
    const char* name;
    const char* description;
    std::function<Scene(const std::string&, const std::string&)> make;
};

const std::vector<Builtin>& builtins() {
    static const std::vector<Builtin> kScenes = {
        {"book-triangle",
         "WebGL book 'Shadow': spinning triangle over a tilted plane, light at (0, 7, 2)",
         [](const std::string& n, const std::string& d) {
             return bookTriangle(false, {0.0f, 7.0f, 2.0f}, 100.0f, n, d);
         }},
        {"book-triangle-far",
         "WebGL book 'Shadow_highp': the same with the light far away at (0, 40, 2)",
         [](const std::string& n, const std::string& d) {
             return bookTriangle(true, {0.0f, 40.0f, 2.0f}, 200.0f, n, d);
         }},
        {"course-two-lights",
         "course text's experiment: three planes, twice, under two orthographic-shadow lights",
         [](const std::string& n, const std::string& d) {
             return courseScene(n, d, addThreePlanes);
         }},
        {"course-cubes", "course text's experiment with 'cubes along axes' under two lights",
         [](const std::string& n, const std::string& d) { return courseScene(n, d, addCubes); }},
        {"tutorial-room",
         "tutorial's sun (0.267, -0.802, 0.535) over a room with thick walls and floor",
         [](const std::string& n, const std::string& d) { return tutorialRoom(false, n, d); }},
        {"tutorial-room-thin", "the same room with zero-thickness walls and floor (peter-panning)",
         [](const std::string& n, const std::string& d) { return tutorialRoom(true, n, d); }},
        {"tutorial-directional",
         "tutorial's sun with its own light camera: orthographic, eye (-9, 27, -18), near 25, far "
         "40",
         [](const std::string& n, const std::string& d) {
             return tutorialLight(LightType::Directional, n, d);
         }},
        {"tutorial-spot", "tutorial's spot light at (-3, 10, -6), colour 0.3, intensity 300",
         [](const std::string& n, const std::string& d) {
             return tutorialLight(LightType::Spot, n, d);
         }},
        {"tutorial-area",
         "tutorial's area light: parallel rays, inverse-square from its plane, intensity 1000",
         [](const std::string& n, const std::string& d) {
             return tutorialLight(LightType::Area, n, d);
         }},
        {"tutorial-point",
         "tutorial's point light at (0, 3, -1.5): shadowed all around, intensity 20",
         [](const std::string& n, const std::string& d) {
             return tutorialLight(LightType::Point, n, d);
         }},
        {"mixed-lights",
         "every light type at once: sun, area, 2 point and 12 spot lights, all shadowed",
         [](const std::string& n, const std::string& d) { return mixedLights(n, d); }},
    };
    return kScenes;
}

}  // namespace

std::vector<SceneInfo> builtinScenes() {
    std::vector<SceneInfo> out;
    for (const Builtin& b : builtins())
        out.push_back({b.name, b.description});
    return out;
}

Scene builtinScene(const std::string& name) {
    std::string known;
    std::vector<std::string> names;
    for (const Builtin& b : builtins()) {
        if (name == b.name) return b.make(b.name, b.description);
        known += (known.empty() ? "" : ", ") + std::string(b.name);
        names.push_back(b.name);
    }
    const std::string nearest = nearestName(name, names);
    throw Error(ErrorKind::InvalidInput,
                "unknown scene '" + name + "'" +
                    (nearest.empty() ? "" : "; did you mean " + nearest + "?") +
                    " (built-in scenes: " + known + ")");
}

}  // namespace gnomon
