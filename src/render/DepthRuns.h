// Depth-only drawing of a list of items in runs, shared by the shadow pass and the view depth
// pass: consecutive items that need the same state (alpha-tested or not, with which base
// colour texture on unit 4; face culling or not) go in one multi-draw.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "render/GpuScene.h"

namespace gnomon::render {

// How an item's faces are culled: none, all its back faces, or only those of its solids
// (DrawItem::closedIndexCount), the rest drawn from both sides.
enum class Cull { None, All, Solids };

// How a shadow pass culls a caster. Only solids may lose faces: an open surface culled from
// the light's side would cast no shadow at all (and one from the other side would not
// either). A solid's material may be double-sided: seen from outside, it casts the same
// shadow. But not a solid whose texture cuts its faces: light let in through a clear texel of
// a front face meets the opaque texels of the back faces (a slab with a partly clear coating
// in assimp's ClearCoatTest, culled, lit the dome behind it). `holdsLight`: the item's box
// might hold the light, which would then see only back faces.
inline Cull casterCull(const DrawItem& item, const ShadowOptions& options, bool holdsLight) {
    const bool solid = item.closedIndexCount > 0 && !holdsLight;
    return options.cull != CullMode::None && solid && !alphaTestedCaster(item, options)
               ? Cull::Solids
               : Cull::None;
}

// Draws `indices` (ascending indices into scene.items()), each `instances` times, as their
// stand-in casters when `standIns`. `alphaTested(item)` and `cull(item)` say what an item
// needs; `useProgram(alphaTested)` binds the plain or alpha-tested program (and sets its
// uniforms) whenever that changes, starting with the plain one. Drawn in two sweeps, the
// culled triangles and then the others; the depth kept is the nearest either way. Face
// culling is off afterwards.
template <typename AlphaTested, typename CullOf, typename UseProgram>
void drawDepthRuns(const GpuScene& scene, std::span<const std::uint32_t> indices, GLsizei instances,
                   bool standIns, const AlphaTested& alphaTested, const CullOf& cull,
                   const UseProgram& useProgram) {
    bool alpha = false;
    GLuint texture = ~0u;
    useProgram(false);
    for (bool culled : {true, false}) {
        culled ? glEnable(GL_CULL_FACE) : glDisable(GL_CULL_FACE);
        std::uint32_t runStart = 0, runLength = 0;
        Part runPart = Part::All;
        for (std::uint32_t index : indices) {
            const DrawItem& item = scene.items()[index];
            const Cull how = cull(item);
            const GLsizei closed = standIns ? item.standInClosedIndexCount : item.closedIndexCount;
            const GLsizei all = standIns ? item.standInIndexCount : item.indexCount;
            // What of the item this sweep draws, if anything.
            Part part = Part::All;
            if (how == Cull::Solids) {
                part = culled ? Part::Closed : Part::Open;
                if ((culled ? closed : all - closed) == 0) continue;
            } else if ((how == Cull::All) != culled) {
                continue;
            }
            const bool wantAlpha = alphaTested(item);
            const bool differs = wantAlpha != alpha || part != runPart ||
                                 (alpha && scene.textureOf(item) != texture);
            if (differs || index != runStart + runLength) {
                scene.drawRange(runStart, runLength, instances, standIns, runPart);
                runStart = index;
                runLength = 0;
                runPart = part;
            }
            if (wantAlpha != alpha) {
                alpha = wantAlpha;
                useProgram(alpha);
            }
            if (alpha && scene.textureOf(item) != texture) {
                texture = scene.textureOf(item);
                gl::bindTexture2D(4, texture);
            }
            ++runLength;
        }
        scene.drawRange(runStart, runLength, instances, standIns, runPart);
    }
    glDisable(GL_CULL_FACE);
}

}  // namespace gnomon::render
