// Pure shadow-mapping math (no GL): the light camera of each light, the
// clip -> texture mapping (x, y, z from [-1, 1] to [0, 1]), and texel sizes for normal offset.
// Matrices are named bFromA: `lightFromWorld` takes world points into the light camera's view
// space.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/Aabb.h"
#include "gnomon/Scene.h"
#include "scene/CameraMath.h"
#include "shadow/FrustumClip.h"
#include "shadow/ViewSamples.h"

namespace gnomon::shadow {

enum class FrameKind {
    Perspective,   // one frustum (spot lights; point lights with a manual/course camera)
    Orthographic,  // one box (directional and area lights; textbook cameras)
    Cube,          // six 90-degree frusta around a point light
};

struct LightCameraFrame {
    glm::mat4 lightFromWorld{1.0f};  // view matrix (Cube: a translation to the light)
    glm::mat4 clipFromLight{1.0f};   // its projection (Cube: 90 degrees, aspect 1)
    FrameKind kind = FrameKind::Perspective;
    bool orthographic = false;  // kind == Orthographic
    float near = 1.0f;
    float far = 100.0f;
    // World-space size of one map texel: orthographic: constant; perspective: at distance 1
    // along the view axis (multiply by the distance).
    float texelWorldSize = 0.0f;
    bool valid = true;  // false: nothing to shadow (empty scene bounds)
    // Spot and point lights with a range: how far from the light anything is lit. A caster
    // wholly farther shadows nothing lit (the segment from the light to a lit point lies in
    // the range's sphere), so maps neither reach nor draw past it. 0: unbounded.
    float reach = 0.0f;
    // Cube frames: the faces drawn, bit f for face f; the others hold no pixel the view drew
    // (cubeFacesSeen, ViewSamples.h), and no lookup reads them.
    std::uint8_t faces = kAllCubeFaces;
    bool drawsFace(int face) const { return (faces >> face) & 1u; }

    glm::mat4 clipFromWorld() const { return clipFromLight * lightFromWorld; }
    // Cube frames: face 0..5 = +X, -X, +Y, -Y, +Z, -Z, oriented as OpenGL samples cube maps.
    glm::mat4 faceClipFromWorld(int face) const;
};

// The view rotation of cube face 0..5 (+X, -X, +Y, -Y, +Z, -Z) such that rendering a face
// with it and sampling the cube map with a direction agree (OpenGL 4.5 spec, table 8.19:
// e.g. +X: the image's right is -Z and its up is -Y).
glm::mat4 cubeFaceRotation(int face);
// Stored depth [0, 1] of a cube map for a world-space offset from the light: the perspective
// depth along the offset's major axis, what the face's depth pass wrote.
float cubeStoredDepth(const glm::vec3& lightToPoint, float near, float far);

// Maps clip-space x, y, z in [-1, 1] (after the divide) to [0, 1] texture coordinates and
// stored depth: textureFromClip * (x, y, z, 1) = (x/2 + 1/2, ...).
glm::mat4 textureFromClip();

// What the Fit policy looks at: world boxes of the shadow casters and of the receivers and,
// when known, the view camera, whose frustum decides which receivers are visible (without it
// every receiver counts). With `samples` (what the view's depth buffer sees), directional
// and area lights cover those points instead of the receivers' boxes.
struct FitScene {
    std::vector<Aabb> casters;
    std::vector<Aabb> receivers;
    bool viewKnown = false;
    glm::mat4 viewClipFromWorld{1.0f};
    const ViewSamples* samples = nullptr;
    bool stabilise = true;  // with viewKnown: square, quantise and snap (see below)
    // The receivers clipped to the view (clipReceivers), when a caller that fits many lights
    // to one view filled them once (visibleFilled); else each fit clips them again.
    std::vector<Aabb> visibleReceivers;
    bool visibleFilled = false;
};
// The receivers' boxes clipped to the view's frustum (all of them when the view is unknown).
void clipReceivers(const FitScene& scene, std::vector<Aabb>& out);

// A stabilised map's extent, kept from one frame of a moving view to the next: an
// orthographic box in its light space, or a perspective window (lo, hi in tan units, zFar
// its far distance; a point light's axis is in `rotation`). While it still holds everything
// the view needs from the map and is at most kHoldSlack times larger on each axis than a
// fresh fit, the map keeps it, so nothing in the map moves or resizes. Refits happen when the
// view leaves it or it grows too loose. An extent kept this way always covers what the view
// sees: only sharpness is traded.
struct HeldExtent {
    bool valid = false;
    glm::mat4 rotation{0.0f};  // world to the light's space, exactly: a turned light refits
    int mapSize = 0;
    glm::vec2 lo{0.0f}, hi{0.0f};
    float zNear = 0.0f, zFar = 0.0f;
};
constexpr float kHoldSlack = 1.25f;

// A spot's or point light's range, where one is set: nothing beyond it is lit (0: unbounded,
// and for every other kind of light).
float lightReach(const Light& light);

// The light camera of `light` for a frame: Manual and Course use the light's numbers; Fit
// holds the visible receivers that casters can shadow, and those casters:
// - directional and area lights: an orthographic box over the receivers' and casters'
//   common extent across the light (with the view's samples: over the samples instead),
//   from the nearest caster to the farthest receiver;
//   when it follows the view it is squared and snapped (size in steps of 1/16 of a power
//   of two, origin and depth on the texel grid) so small camera moves neither change the
//   map nor make its edges shimmer;
// - spot lights: the cone (fovy = 2 x outer angle), near at the nearest caster, far at the
//   farthest receiver inside it; with the view's samples (scene.samples), only the window
//   of the cone they lie in (fit::fitSpot);
// - point lights: six faces reaching the farthest visible receiver, near before the nearest
//   caster along the faces' axes (a face's depth is the largest of |dx|, |dy|, |dz|); with
//   samples that fit within one face's angle, one frustum over them (fit::fitPoint).
// Invalid (no map needed) when no receiver is visible or no caster can shadow one.
// `mapSize` sets texelWorldSize.
// `held` (with a stabilised fit): the extent kept from the previous frame, read and
// updated: a directional or area light's box, a spot's window, a point light's frustum.
LightCameraFrame lightCameraFrame(const Light& light, const Camera& view, const FitScene& scene,
                                  int mapSize, HeldExtent* held = nullptr);
// The frame at the size the light's map is drawn at, which `size` receives:
// shadowMapSizeOf(light, options), except that a light naming no size (and no --map-size) that
// the fit draws as a cube gets kDefaultCubeFaceSize per face (Scene.h), fitted again at it.
// With the view's samples (scene.samples), a cube's `faces` are those the view looks up
// (cubeFacesSeen, widened by cubeLookupReachTexels).
// `wanted` > 0: the size the plan chose for a light naming none (by need, or held to the
// frame's budget: MapSizing.h), in place of the defaults.
LightCameraFrame sizedLightCameraFrame(const Light& light, const ShadowOptions& options,
                                       const Camera& view, const FitScene& scene, int& size,
                                       HeldExtent* held = nullptr, int wanted = 0);
// A point light's face `face` (0..5, as cubeFaceRotation) as a map of its own, a perspective
// frustum over the face's pyramid (widened by what a lookup at its rim reads, from
// cubeLookupReachTexels) narrowed to the view's samples in it and to where casters can shadow
// them (fit::fitPointFace; invalid when none can). What a point light the view sees all
// around gets instead of a cube when view samples exist.
LightCameraFrame pointFaceFrame(const Light& light, int face, const ShadowOptions& options,
                                const FitScene& scene, int mapSize, HeldExtent* held = nullptr);
// How far from its point's own texel, in texels of a cube face, a point light's lookup may
// read under `options` (shaders/cube_lookup.glsl): what the faces a view needs are widened by.
float cubeLookupReachTexels(const ShadowOptions& options);
// The same with one box as every caster and receiver and no view (fit the whole box).
LightCameraFrame lightCameraFrame(const Light& light, const Camera& view,
                                  const Aabb& casterAndReceiverBounds, int mapSize);

// The world boxes Fit looks at for `scene` at `seconds`, seen by its camera at `aspect`.
FitScene fitScene(const Scene& scene, double seconds, float aspect);

// True when `box` cannot cast into any face of a cube frame (beyond its far sphere).
bool outsideCube(const Aabb& box, const LightCameraFrame& cube);

// Cascade split distances along the view direction: count + 1 values from near to
// far, each the blend lambda * log + (1 - lambda) * uniform split ("practical split scheme",
// Zhang et al. 2006, Parallel-Split Shadow Maps).
std::vector<float> cascadeSplits(float near, float far, int count, float lambda);

// A stabilised orthographic camera for the view frustum slice [splitNear, splitFar] of a
// directional light: it encloses the slice's bounding sphere (so its size does not change
// as the view turns) and its origin moves in whole map texels (so the shadow does not
// shimmer as the view moves); depth reaches back to `sceneBounds` so every caster between
// the light and the slice is in the map.
// `stabilise` false: the sphere's exact radius and centre (the shimmering textbook form).
LightCameraFrame cascadeFrame(const glm::vec3& lightDirection, const Camera& view, float aspect,
                              float splitNear, float splitFar, const Aabb& sceneBounds, int mapSize,
                              bool stabilise = true);

// The depth range cascades split when it follows the view's samples and maps are stabilised:
// [nearest, farthest] widened to steps of half an octave (a factor 2^(1/2)), so the splits,
// and which cascade a surface reads, move only now and then as the view moves rather than
// every frame. Finer steps move the splits often enough to flicker more on a moving view,
// for no fewer misclassified pixels.
void stabiliseDepthRange(float& nearest, float& farthest);

// Sample distribution cascades (Lauritzen et al. 2011): how many cascades a view needs whose
// samples span view depths [nearest, farthest]: one per factor of 8 in depth, 1..4.
int autoCascadeCount(float nearest, float farthest);
// The orthographic camera of one cascade of a directional light when `scene` has samples:
// it covers the samples whose view depth lies in [depthFrom, depthTo] (and the casters that
// can shadow them), squared and snapped as the single-map fit is. Invalid when no sample or
// no caster is there.
LightCameraFrame sampledCascadeFrame(const glm::vec3& direction, const FitScene& scene,
                                     float depthFrom, float depthTo, int mapSize,
                                     HeldExtent* held = nullptr);

// `camera` with its near and far planes moved in to the depths `bounds` (world space, all
// that is drawn) spans in its view, where that is nearer than its own: the depth buffer's
// precision goes where the scene is. A perspective depth step grows with distance² / near:
// the glTF camera of assimp's 2CylinderEngine (znear 0.05, zfar 10^6, 1 600 units from a
// 750-unit engine) left surfaces within 3 units of each other to the rounding: jagged
// z-fighting wherever a rod passes through a fin. Nothing lies outside the bounds, so nothing
// more is clipped; a camera inside them keeps its near plane.
Camera depthFitted(const Camera& camera, const Aabb& bounds);

}  // namespace gnomon::shadow
