// Depth-only drawing of a list of items in runs, shared by the shadow pass and the view depth
// pass: consecutive items that need the same state (alpha-tested or not, with which base
// colour texture on unit 4; face culling or not) go in one multi-draw.
#pragma once

#include <cstdint>
#include <vector>

#include "render/GpuScene.h"

namespace gnomon::render {

// Draws `indices` (ascending indices into scene.items()), each `instances` times, as their
// stand-in casters when `standIns`.
// `alphaTested(item)` and `culled(item)` say what an item needs; `useProgram(alphaTested)`
// binds the plain or alpha-tested program (and sets its uniforms) whenever that changes,
// starting with the plain one. Face culling is off afterwards.
template <typename AlphaTested, typename Culled, typename UseProgram>
void drawDepthRuns(const GpuScene& scene, const std::vector<std::uint32_t>& indices,
                   GLsizei instances, bool standIns, const AlphaTested& alphaTested,
                   const Culled& culled, const UseProgram& useProgram) {
    bool culling = false, alpha = false;
    GLuint texture = ~0u;
    glDisable(GL_CULL_FACE);
    useProgram(false);
    std::uint32_t runStart = 0, runLength = 0;
    for (std::uint32_t index : indices) {
        const DrawItem& item = scene.items()[index];
        const bool wantAlpha = alphaTested(item);
        const bool wantCull = culled(item);
        const bool differs = wantAlpha != alpha || (alpha && scene.textureOf(item) != texture) ||
                             wantCull != culling;
        if (differs || index != runStart + runLength) {
            scene.drawRange(runStart, runLength, instances, standIns);
            runStart = index;
            runLength = 0;
        }
        if (wantAlpha != alpha) {
            alpha = wantAlpha;
            useProgram(alpha);
        }
        if (alpha && scene.textureOf(item) != texture) {
            texture = scene.textureOf(item);
            glBindTextureUnit(4, texture);
        }
        if (wantCull != culling) {
            wantCull ? glEnable(GL_CULL_FACE) : glDisable(GL_CULL_FACE);
            culling = wantCull;
        }
        ++runLength;
    }
    scene.drawRange(runStart, runLength, instances, standIns);
    glDisable(GL_CULL_FACE);
}

}  // namespace gnomon::render
