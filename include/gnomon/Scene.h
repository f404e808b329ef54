// The scene model (no GL): meshes, materials, objects placing meshes in the world, the view
// camera, lights with their shadow settings, and the options the scene was authored with.
// Built-in scenes reproduce the textbooks' set-ups with their exact numbers.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gnomon/Options.h"

namespace gnomon {

// A coarser version of a mesh that its file gives (glTF's MSFT_lod), in the mesh's model
// space: what shadow passes may draw instead of the mesh (--caster-detail).
struct MeshLod {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;  // triangle list into `positions`
};

struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;    // model space
    std::vector<glm::vec3> normals;      // model space, unit length, one per position
    std::vector<glm::vec3> colours;      // optional per-vertex colour (empty: material colour)
    std::vector<glm::vec2> uvs;          // optional texture coordinates (empty: none)
    std::vector<std::uint32_t> indices;  // triangle list; 3 per triangle
    std::vector<MeshLod> lods;           // the file's coarser versions, finest first (may be none)
};

// How a texture repeats outside [0,1] (glTF sampler wrap modes).
enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };

// A decoded image with its sampling rules. Texel rows run top-down, as in image files; the
// colour channels are sRGB-encoded, alpha is linear.
struct Texture {
    std::string name;
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // width * height * 4 bytes
    TextureWrap wrapS = TextureWrap::Repeat;
    TextureWrap wrapT = TextureWrap::Repeat;
    bool nearest = false;  // magnify and minify without filtering (pixel art); else trilinear
};

// How a material's alpha (base colour alpha times the texture's) is used (glTF alphaMode).
enum class AlphaMode {
    Opaque,  // alpha ignored
    Mask,    // fragments with alpha < alphaCutoff are cut away, in every pass
    Blend,   // blended over what is behind; shadows cast by ShadowOptions::blendShadows
};

struct Material {
    std::string name;
    glm::vec3 baseColour{1.0f};  // linear RGB, 0..1
    float specular = 0.3f;       // strength of the Blinn-Phong highlight, 0..1
    float shininess = 30.0f;     // Blinn-Phong exponent, > 0
    bool unlit = false;          // colour is output as is (times shadow factor), no lighting
    bool doubleSided = false;    // open surface: never culled, lit from either side
    float alpha = 1.0f;          // base colour alpha factor, 0..1
    int baseColourTexture = -1;  // index into Scene::textures; -1: none (needs Mesh::uvs)
    // Texture coordinates used = uvTransform * (u, v, 1) (KHR_texture_transform).
    glm::mat3 uvTransform{1.0f};
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;  // Mask: cut below this alpha
};

// A constant rotation over time about an axis through `pivot`.
struct Spin {
    glm::vec3 axis{0.0f, 1.0f, 0.0f};
    float degreesPerSecond = 0.0f;
    glm::vec3 pivot{0.0f};
};

struct Object {
    std::string name;
    std::uint32_t mesh = 0;      // index into Scene::meshes
    std::uint32_t material = 0;  // index into Scene::materials
    glm::mat4 worldFromModel{1.0f};
    Spin spin;                    // applied after worldFromModel, at RenderOptions::time
    bool castsShadows = true;     // drawn into shadow maps
    bool receivesShadows = true;  // looks up shadow maps in the main pass

    glm::mat4 worldFromModelAt(double seconds) const;
};

enum class Projection { Perspective, Orthographic };

struct Camera {
    glm::vec3 eye{0.0f, 0.0f, 5.0f};
    glm::vec3 centre{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    Projection projection = Projection::Perspective;
    float fovyDegrees = 45.0f;  // perspective vertical field of view
    float aspect = 0.0f;        // width / height; 0 = from the output image
    float near = 1.0f;
    float far = 100.0f;
    float left = -1.0f, right = 1.0f, bottom = -1.0f, top = 1.0f;  // orthographic volume
    bool operator==(const Camera&) const = default;
};

// The camera's clip space from world space, as the renderer draws it for an image of that
// aspect (width / height; Camera::aspect overrides it when set): to place marks over a
// rendered view, or project points as the picture does.
glm::mat4 cameraClipFromWorld(const Camera& camera, float aspect);

enum class LightType {
    Directional,  // parallel rays along `direction`, no falloff
    Spot,         // from `position` along `direction` inside a cone, falls off
    Point,        // from `position` in all directions, falls off
    Area,         // the WebGL tutorial's simplified area light: parallel rays along `direction`
                  // from the plane through `position`, falling off with the distance from
                  // that plane
};

// How a light's shadow camera is placed.
enum class ShadowCameraPolicy {
    Fit,     // holds the visible receivers that casters can shadow, and those casters:
             // orthographic for directional and area lights (squared and texel-snapped),
             // the cone for spots, six cube faces for point lights; no map when nothing
             // visible can be shadowed
    Manual,  // look at `target` with `up`, the projection numbers as given
    Course,  // W. Brown's course text, §12.6: look at the view camera's centre with the view
             // camera's up
};

struct ShadowCamera {
    ShadowCameraPolicy policy = ShadowCameraPolicy::Fit;
    Projection projection = Projection::Perspective;  // Manual/Course; Fit picks per type
    glm::vec3 target{0.0f};                           // Manual look-at point
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovyDegrees = 90.0f;  // perspective
    float aspect = 1.0f;
    float near = 1.0f;
    float far = 100.0f;
    float left = -1.0f, right = 1.0f, bottom = -1.0f, top = 1.0f;  // orthographic
    bool operator==(const ShadowCamera&) const = default;
};

// Distance falloff 1 / (c0 + c1 d + c2 d^2).
struct Attenuation {
    float constant = 1.0f;
    float linear = 0.0f;
    float quadratic = 0.0f;
    bool operator==(const Attenuation&) const = default;
};

struct Light {
    std::string name;
    LightType type = LightType::Point;
    bool enabled = true;
    glm::vec3 position{0.0f};                // world space (spot, point)
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // world space, towards where light goes
    glm::vec3 colour{1.0f};
    float intensity = 1.0f;
    Attenuation attenuation;         // ignored for directional lights
    float innerConeDegrees = 20.0f;  // spot: full intensity inside (half-angle)
    float outerConeDegrees = 30.0f;  // spot: zero outside (half-angle)
    // Point and spot: beyond this distance no light (glTF's range, with its smooth window
    // (1 - (d/range)^4)^2 on top of the attenuation); 0 = unlimited.
    float range = 0.0f;
    bool castsShadows = true;
    // Texels per side (per cube face for point lights), 64..8192; 0: the default
    // (kDefaultShadowMapSize, kDefaultCubeFaceSize for a cube's faces).
    int shadowMapSize = 0;
    ShadowCamera shadowCamera;
    bool operator==(const Light&) const = default;
};

// Light::direction for a sun at `azimuthDegrees` and `elevationDegrees` (as `--sun AZ,EL`):
// the azimuth turns from +z towards +x and names where the light comes from, the elevation
// is above the horizon (the xz plane; +y is up). Unit length, pointing the way the light
// goes: sunDirection(0, 90) = (0, -1, 0), straight down; sunDirection(90, 0) = (-1, 0, 0),
// from +x along the horizon.
glm::vec3 sunDirection(float azimuthDegrees, float elevationDegrees);

// `text` as `count` numbers separated by commas ("4,3,6", as --camera-eye X,Y,Z and --sun
// AZ,EL take them); none when a part is empty, not wholly a number or not finite, or when
// there are more or fewer parts.
std::optional<std::vector<float>> parseNumberList(const std::string& text, std::size_t count);

// The map size of a light that names none: 2048 texels per side for a light drawn into one
// map (directional, area and spot lights, point lights drawn as one frustum), and 1024 per
// face for a point light drawn as a cube (six faces).
inline constexpr int kDefaultShadowMapSize = 2048;
inline constexpr int kDefaultCubeFaceSize = 1024;
// Light::shadowMapSize, or kDefaultShadowMapSize when it is 0 (a cube's faces, when they are
// drawn, take kDefaultCubeFaceSize instead).
int shadowMapSizeOf(const Light& light);
// The size a light's map is drawn at: options.mapSize (--map-size) when set, else its own.
int shadowMapSizeOf(const Light& light, const ShadowOptions& options);

// Names one state of a scene's meshes, materials, textures and objects, so a renderer
// re-reads them (checks, hashes, uploads: work that grows with the scene) only when it
// changed instead of every frame. Every Scene starts with a value no other Scene has had,
// and so does every copy; whoever edits those four in place calls bump(). Lights, camera,
// ambient and options need no bump: they are read every frame.
class Revision {
public:
    Revision() : mValue(next()) {}
    Revision(const Revision&) : mValue(next()) {}
    Revision& operator=(const Revision&) {
        mValue = next();
        return *this;
    }
    void bump() { mValue = next(); }
    std::uint64_t value() const { return mValue; }

private:
    static std::uint64_t next();  // a process-wide counter
    std::uint64_t mValue;
};

struct Scene {
    std::string name;
    std::string description;  // one line
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Object> objects;
    std::vector<Light> lights;
    Camera camera;
    glm::vec3 ambient{0.1f};  // ambient light colour, times the material colour
    RenderOptions options;    // the options the scene was authored with; callers start here
    // The textbook's own settings for this scene, if it comes from one.
    std::optional<RenderOptions> textbookOptions;
    // What a loader ignored or repaired (unsupported extensions, generated normals, skipped
    // triangles, added lights or camera), one sentence each.
    std::vector<std::string> warnings;
    // Bump after editing meshes, materials, textures or objects in place.
    Revision revision;

    // Empty when consistent; otherwise one sentence per problem (index out of range, NaN...).
    std::vector<std::string> validate() const;
    // The two halves of validate(): meshes, textures, materials and objects (what `revision`
    // covers; it reads every vertex), and lights and camera.
    std::vector<std::string> validateContent() const;
    std::vector<std::string> validateLightsAndCamera() const;
};

// The warning a model loader gives when it adds a sun to a model without lights; a caller
// that replaces the lights (`--sun`, a scene file's own) drops it with them.
inline constexpr const char* kDefaultSunWarning = "no lights: a default sun was added";

struct SceneInfo {
    std::string name;
    std::string description;
};

// Names as scene files and the viewer spell them ("directional", "fit", "perspective"...);
// "?" past the last value.
const char* toString(LightType v);
const char* toString(ShadowCameraPolicy v);
const char* toString(Projection v);

// The options a preset gives for `scene`: Default = scene.options; Textbook =
// scene.textbookOptions, or for scenes without them a constant tolerance of 0.005 in stored
// depth and nothing else (no slope, normal offset or depth-aware step, no culling, one
// nearest lookup): the textbooks' method.
RenderOptions presetOptions(const Scene& scene, Preset preset);

// The world box of every object at rest (time 0) into lo and hi; both 0 for an empty scene.
void sceneBounds(const Scene& scene, glm::vec3& lo, glm::vec3& hi);

// Triangles the scene's objects draw (each object its mesh's), or only those of the objects
// that cast shadows: what a shadow pass draws at full detail.
std::size_t triangleCount(const Scene& scene, bool castersOnly = false);

// Sets the camera's near and far planes from the scene's extent seen from its eye: far just
// beyond the farthest corner of sceneBounds(), near 1/2000 of that. For cameras placed
// without planes of their own (the CLI's --camera-eye, a scene file's camera without
// near/far), so a model in millimetres or in kilometres is neither cut away nor clipped
// whole. Leaves the camera as it was for an empty scene.
void fitCameraDepth(const Scene& scene, Camera& camera);

// The same for a manual or course shadow camera, which sits at `light`'s position: far just
// beyond the farthest corner of sceneBounds() from it, near just short of the bounds (1/2000
// of far when the light is inside them), since a perspective map's depth resolution follows
// near / far. For scene files whose shadow-camera leaves the planes out: the defaults 1 and
// 100 would store no depth of a model in millimetres and cut one in kilometres.
void fitShadowCameraDepth(const Scene& scene, const Light& light, ShadowCamera& camera);

// The view edits `gnomon render` takes as --camera-eye X,Y,Z, --camera-target X,Y,Z,
// --camera-fov DEG and --sun AZ,EL, which the web page's address takes as keys of the same
// names: the texts as given, the field of view as the number its flag holds; none: not given.
struct CameraAndSun {
    std::optional<std::string> eye, target, sun;
    std::optional<float> fovDegrees;
};
// Applies them to `scene` as the CLI does: eye, target and field of view replace the camera's;
// a camera moved gets its near and far planes from the scene (fitCameraDepth); eye and target
// given drop a loader's added-camera warning. A sun replaces every light by one directional
// light (sunDirection) and drops the added-sun warning. Throws gnomon::Error (InvalidInput)
// naming the flag: "--camera-eye: expected X,Y,Z such as 4,3,6, got '1,2'".
void placeCameraAndSun(Scene& scene, const CameraAndSun& edits);

// Can the scene's camera see any of its objects in a `width` x `height` image? False when
// their world bounds lie wholly beyond one side of the camera's view volume (behind it, past
// its far plane, off to a side), or lie in front of it but within less than a pixel each
// way (a camera thousands of the scene's sizes away): the picture would hold the background
// only. True whenever some part may show, and for a scene without objects.
bool cameraSeesScene(const Scene& scene, int width, int height);

// The scenes gnomon ships, in a stable order.
std::vector<SceneInfo> builtinScenes();
// A built-in scene by name; throws gnomon::Error listing the known names.
Scene builtinScene(const std::string& name);
// Which model axis points up. glTF is Y-up by its specification; STL, 3DS-era OBJ and CAD
// exports are often Z-up. assimp already turns COLLADA files by their up_axis and 3DS files
// from Z-up, so the axis names the model as assimp hands it over.
enum class UpAxis { Y, Z, X };
const char* toString(UpAxis v);
// "x", "y" or "z" (any case); nullopt for anything else.
std::optional<UpAxis> parseUpAxis(const std::string& text);

// A built-in scene name or a path to a model file; throws gnomon::Error. A model file is
// turned so that `up` becomes +y before its camera and sun are placed; `up` other than Y for
// a built-in scene or a scene file (whose includes carry their own "up") is an error.
Scene loadScene(const std::string& nameOrPath, UpAxis up = UpAxis::Y);
// Adds a grey ground under the scene (a receiver that casts nothing) so models without a
// floor show their shadows: a square ten times the scene's radius wide, facing +y (glTF's
// up) just below the lowest point at options.time 0. Does nothing to an empty scene.
void addGround(Scene& scene);

// The map size of the scene's first shadow-casting light, shadowMapSizeOf (1024 with none; a
// point light drawn as a cube may draw its faces smaller): what gnomon bench reports as the
// scene's map size, and where the viewer's override starts.
int firstCasterMapSize(const Scene& scene, const ShadowOptions& options);

}  // namespace gnomon
