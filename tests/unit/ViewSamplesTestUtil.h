// The scene the view-sample tests fit to (test_view_samples.cpp, test_light_samples.cpp):
// the ground plane y = 0 (|x|, |z| <= 10), seen from above one edge, with a post on it, and
// its depth buffer reduced to (nearest, farthest) per block as the view depth pass does.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "shadow/ShadowMath.h"
#include "shadow/ViewSamples.h"

namespace gnomon::test {

inline Camera groundCamera() {
    Camera c;
    c.eye = {0.0f, 2.0f, 6.0f};
    c.centre = {0.0f, 0.0f, 0.0f};
    c.fovyDegrees = 60.0f;
    c.near = 0.1f;
    c.far = 100.0f;
    return c;
}

// The depth buffer of the ground plane y = 0 (|x|, |z| <= 10) seen by `camera` at `size`,
// reduced to (nearest, farthest) per block as the view depth pass's reduction does.
inline std::vector<glm::vec2> groundRanges(const Camera& camera, const shadow::SampleGrid& grid,
                                           float aspect) {
    const glm::mat4 clip = gnomon::clipFromView(camera, aspect) * gnomon::viewFromWorld(camera);
    const glm::mat4 worldFromClip = glm::inverse(clip);
    std::vector<glm::vec2> ranges(std::size_t(grid.cells.x * grid.cells.y), glm::vec2(1.0f, 0.0f));
    for (int y = 0; y < grid.size.y; ++y) {
        for (int x = 0; x < grid.size.x; ++x) {
            const glm::vec2 ndc((2.0f * x + 1.0f) / grid.size.x - 1.0f,
                                (2.0f * y + 1.0f) / grid.size.y - 1.0f);
            glm::vec4 a = worldFromClip * glm::vec4(ndc, -1.0f, 1.0f);
            glm::vec4 b = worldFromClip * glm::vec4(ndc, 1.0f, 1.0f);
            const glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
            if (!(p0.y > 0.0f && p1.y < 0.0f)) continue;  // the ray misses the ground
            const glm::vec3 hit = p0 + (p1 - p0) * (p0.y / (p0.y - p1.y));
            if (std::abs(hit.x) > 10.0f || std::abs(hit.z) > 10.0f) continue;
            const glm::vec4 c = clip * glm::vec4(hit, 1.0f);
            const float d = 0.5f * c.z / c.w + 0.5f;
            glm::vec2& r = ranges[std::size_t((y / grid.block) * grid.cells.x + x / grid.block)];
            r = glm::vec2(std::min(r.x, d), std::max(r.y, d));
        }
    }
    for (glm::vec2& r : ranges) {
        if (r.x >= 1.0f) r = glm::vec2(1.0f);
    }
    return ranges;
}

// The ground (|x|, |z| <= half) with a post on it, seen by `camera` at 128 x 96 reduced to
// 64-cell rows: `samples` filled from its depth, the fit scene pointing at them.
inline shadow::FitScene groundWithPost(const Camera& camera, shadow::ViewSamples& samples,
                                       float half = 10.0f) {
    const shadow::SampleGrid grid = shadow::sampleGrid(128, 96, 64);
    const float aspect = 4.0f / 3.0f;
    shadow::viewSamples(groundRanges(camera, grid, aspect), grid, camera, aspect, samples);
    shadow::FitScene scene;
    scene.receivers = {Aabb{{-half, 0.0f, -half}, {half, 0.0f, half}}};
    scene.casters = {scene.receivers[0], Aabb{{-0.2f, 0.0f, -0.2f}, {0.2f, 3.0f, 0.2f}}};
    scene.viewKnown = true;
    scene.viewClipFromWorld = gnomon::clipFromView(camera, aspect) * gnomon::viewFromWorld(camera);
    scene.samples = &samples;
    return scene;
}

// A wide spot straight above the ground's centre, its cone reaching far past what the ground
// camera sees.
inline Light wideSpot() {
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0.0f, 10.0f, 0.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.outerConeDegrees = 70.0f;
    return spot;
}

}  // namespace gnomon::test
