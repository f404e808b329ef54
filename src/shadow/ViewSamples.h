// What the view actually sees, as world-space points taken from a coarse depth buffer of the
// view camera: the input of sample distribution shadow maps (Lauritzen, Salvi and Lefohn,
// "Sample Distribution Shadow Maps", I3D 2011). Fitted directional light cameras and cascade
// splits follow these points instead of whole objects' boxes, so a map is spent on the part
// of the scene that lands on screen (inside a building, the atrium the camera stands in, not
// the whole model). Pure math: the GL pass that draws the depth lives in render/.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "core/Aabb.h"
#include "gnomon/Scene.h"

namespace gnomon::shadow {

struct ViewSamples {
    // World position of each covered sample; w: its view depth (distance along the view
    // axis, what cascade splits are measured in).
    std::vector<glm::vec4> points;
    float nearest = 0.0f, farthest = 0.0f;  // view-depth range of the points (empty: 0, 0)
    // World distance between neighbouring samples at view depth d is padConstant +
    // padPerDepth * d: how far the surface they stand for may reach beyond a sample.
    float padConstant = 0.0f, padPerDepth = 0.0f;

    bool empty() const { return points.empty(); }
    float pad(float depth) const { return padConstant + padPerDepth * depth; }
};

// The sample grid's size for an output of width x height: the same shape, at most `limit`
// samples along its longer side (never more than the output has pixels), at least 2.
glm::ivec2 sampleGridSize(int width, int height, int limit);

// The clip-space scale that puts the outermost pixel centres of a w x h grid on the edges of
// the view (a pixel centre of an unscaled grid sits half a pixel inside): multiply the view's
// clipFromWorld by it to draw the sample grid, so the grid reaches the view's borders.
glm::mat4 sampleGridScale(glm::ivec2 grid);

// The points of a depth buffer drawn through sampleGridScale(grid) * clip(camera) * view:
// `depth` holds grid.x * grid.y window depths in [0, 1], rows bottom-up as OpenGL returns
// them; 1 (the clear value) is empty. `aspect`: the output's width / height. Fills `out`
// (keeping its storage: a moving camera does not allocate every frame).
void viewSamples(const std::vector<float>& depth, glm::ivec2 grid, const Camera& camera,
                 float aspect, ViewSamples& out);

// The light-space box (through `lightFromWorld`, a rotation) of the samples whose view depth
// lies in [depthFrom, depthTo], each grown by its pad. Empty when none does.
Aabb samplesInLight(const ViewSamples& samples, const glm::mat4& lightFromWorld, float depthFrom,
                    float depthTo);

struct LightCameraFrame;

// The share (0..1) of a light camera's map that the samples whose view depth lies in
// [depthFrom, depthTo] land on: the map split into cells x cells squares (a cube's faces
// each), a square counted when some sample's footprint (its pad) overlaps it. What
// `--verbose` reports, to show how much of each map the view spends.
float mapShareUsed(const ViewSamples& samples, const LightCameraFrame& frame, int mapSize,
                   float depthFrom, float depthTo, int cells = 64);

}  // namespace gnomon::shadow
