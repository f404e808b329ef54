// Debug views (DESIGN: debug views are features): --debug-view shadow-map draws one light's
// maps as grey panels instead of the scene; --debug-view light-frusta draws every shadow
// camera's volume as lines over the scene (cascades and cube volumes included).
#pragma once

#include <array>
#include <map>
#include <vector>

#include "gl/Objects.h"
#include "gnomon/Options.h"
#include "render/ShadowPass.h"

namespace gnomon::render {

class DebugPass {
public:
    // The maps of `light` (an index into Scene::lights) in the bound framebuffer's viewport
    // of width x height; returns false (nothing drawn) when that light has no map.
    bool drawMaps(const ShadowPass& maps, const std::vector<ShadowedLight>& shadowed, int light,
                  int width, int height);
    // Each map's volume as lines, coloured per light, over what the framebuffer holds.
    void drawFrusta(const std::vector<ShadowedLight>& shadowed, const glm::mat4& clipFromWorld);

private:
    const gl::Program& mapsProgram(DepthFormat format);
    std::map<DepthFormat, gl::Program> mMapsPrograms;
    gl::Program mLinesProgram;
    gl::Sampler mRawSampler;
    gl::Texture mCubeView;       // the cube array's faces as a 2D array
    GLuint mCubeViewSource = 0;  // the cube array it views
    gl::VertexArray mEmpty, mLines;
    gl::Buffer mLineBuffer;
    std::vector<glm::vec3> mLineData;  // position, colour per vertex; reused
};

}  // namespace gnomon::render
