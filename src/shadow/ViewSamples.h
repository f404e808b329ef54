// What the view actually sees, as world-space points taken from a coarse depth buffer of the
// view camera: the input of sample distribution shadow maps (Lauritzen, Salvi and Lefohn,
// "Sample Distribution Shadow Maps", I3D 2011). Fitted directional light cameras and cascade
// splits follow these points instead of whole objects' boxes, so a map is spent on the part
// of the scene that lands on screen (inside a building, the atrium the camera stands in, not
// the whole model). Pure math: the GL pass that draws the depth lives in render/.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/Aabb.h"
#include "gnomon/Scene.h"

namespace gnomon::shadow {

constexpr std::size_t kSampleChunk = 64;

struct ViewSamples {
    // World position of each covered sample; w: its view depth (distance along the view
    // axis, what cascade splits are measured in).
    std::vector<glm::vec4> points;
    // Per point: true when it is a cell's nearest depth and the next point the same cell's
    // farthest. The view drew pixels of that cell at every depth between (a floor seen at a
    // grazing angle): the segment joining the two holds them, each grown by its pad.
    std::vector<bool> farthestNext;
    float nearest = 0.0f, farthest = 0.0f;  // view-depth range of the points (empty: 0, 0)
    // World distance between neighbouring samples at view depth d is padConstant +
    // padPerDepth * d: how far the surface they stand for may reach beyond a sample.
    float padConstant = 0.0f, padPerDepth = 0.0f;
    // Boxes of kSampleChunk points each (chunk c: points from c * kSampleChunk, with the
    // other end of a cell's pair that starts in it) and the largest pad among them:
    // samplesWithin skips a chunk wholly beyond a light's range at once. viewSamples fills
    // them; samples filled another way have none and are walked point by point.
    std::vector<Aabb> chunks;
    std::vector<float> chunkPads;
    // Filled by samplesWithin for a light at filterApex with range filterReach (0: not): the
    // functions below then take every point as within that range without testing it again.
    glm::vec3 filterApex{0.0f};
    float filterReach = 0.0f;
    // Which filling these points are: viewSamples() gives each a value none had before, so a
    // fit made from them can be kept while it is unchanged (0: never filled by viewSamples).
    std::uint64_t generation = 0;

    bool empty() const { return points.empty(); }
    float pad(float depth) const { return padConstant + padPerDepth * depth; }
};

// The view depth pass draws the view's depth at full size and reduces it to a grid of
// block x block pixel cells, each keeping the nearest and farthest depth it covers. `block`
// makes the grid at most `limit` cells along its longer side; grid() is its size in cells.
struct SampleGrid {
    glm::ivec2 size{1};   // the output's pixels
    int block = 1;        // pixels per cell side
    glm::ivec2 cells{1};  // ceil(size / block)
};
SampleGrid sampleGrid(int width, int height, int limit);

// The points of a reduced depth buffer: `ranges` holds grid.cells.x * grid.cells.y (nearest,
// farthest) window depths in [0, 1], rows bottom-up as OpenGL returns them; (1, 1) is a cell
// with nothing. Each cell gives a point on its centre ray at each of its two depths; its pad
// (one cell's width at that depth) reaches over the whole cell, so every pixel the view
// drew lies within a pad of the points. `aspect`: the output's width / height. Fills `out`
// (keeping its storage: a moving camera does not allocate every frame).
void viewSamples(const std::vector<glm::vec2>& ranges, const SampleGrid& grid, const Camera& camera,
                 float aspect, ViewSamples& out);

// The light-space box (through `lightFromWorld`, a rotation) of the samples whose view depth
// lies in [depthFrom, depthTo], each grown by its pad. Empty when none does.
Aabb samplesInLight(const ViewSamples& samples, const glm::mat4& lightFromWorld, float depthFrom,
                    float depthTo);

// Does some sample lie within `reach` of `apex` (reach <= 0: unbounded, so any sample)? A
// light with a range that holds none lights nothing the view sees and needs no map.
bool anySampleWithin(const ViewSamples& samples, const glm::vec3& apex, float reach);
// Those samples, in their order and with their cells' pairs whole: what a light with a range
// needs of the view. Its fits (a frustum, a cube, faces) each walk the samples, so on a view
// with many small lights they walk this subset instead. Fills `out` keeping its storage.
void samplesWithin(const ViewSamples& samples, const glm::vec3& apex, float reach,
                   ViewSamples& out);

// For fitting one frustum from a point light over what the view sees (instead of a cube):
// the samples' mean direction from `apex`; false when there is none or one lies within its
// pad of the apex. With `reach` > 0 (a light's range), samples wholly farther from the apex
// are left out: they are unlit (here and in the two functions below).
bool samplesDirection(const ViewSamples& samples, const glm::vec3& apex, glm::vec3& direction,
                      float reach = 0.0f);
// The window [lo, hi] in tan units (x / -z, y / -z) of the camera `lightFromWorld` (a
// look-at) that holds every sample with its pad, and the largest depth -z among them. False
// when there is no sample or some sample's pad reaches the camera's plane z = 0 (no window
// holds it). With `limit` (a spot light's cone window), only the samples whose footprint
// overlaps it count (the others get no light to shadow), the window is clipped to it, and
// false also means that none does.
struct SampleWindow {
    glm::vec2 lo{0.0f}, hi{0.0f};
    float farthest = 0.0f;
};
bool samplesWindow(const ViewSamples& samples, const glm::mat4& lightFromWorld,
                   SampleWindow& window, const SampleWindow* limit = nullptr, float reach = 0.0f);

struct LightCameraFrame;

// The faces of a point light's cube at `lightPosition` that hold some pixel the view drew
// (bit f: face f, +X, -X, +Y, -Y, +Z, -Z): a cell's segment between its two depths, grown by
// its pad and by `marginRadians` more (what a lookup reads around its point: filter taps,
// offsets), meets the face's pyramid. The other faces need not be drawn: no lookup reads
// them. All six when a pad or the margin is too wide for the test to stay a bound.
constexpr std::uint8_t kAllCubeFaces = 0x3F;  // bits 0 to 5
std::uint8_t cubeFacesSeen(const ViewSamples& samples, const glm::vec3& lightPosition,
                           float marginRadians, float reach = 0.0f);

// The share (0..1) of a light camera's map that the samples whose view depth lies in
// [depthFrom, depthTo] land on: the map split into cells x cells squares (a cube's faces
// each), a square counted when some sample's footprint (its pad) overlaps it. What
// `--verbose` reports, to show how much of each map the view spends.
float mapShareUsed(const ViewSamples& samples, const LightCameraFrame& frame, int mapSize,
                   float depthFrom, float depthTo, int cells = 64);

}  // namespace gnomon::shadow
