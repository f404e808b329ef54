// The shadow pass (SPEC S1, S3, S14): one depth-only rendering per shadowed light into a
// layer of a DEPTH_COMPONENT32F texture array (one layer per light; a light's map occupies
// the layer's lower-left mapSize x mapSize texels). A layer is re-rendered only when its
// light camera, the casters or the depth-pass state changed (static maps are kept).
#pragma once

#include <vector>

#include "gl/Objects.h"
#include "gnomon/Options.h"
#include "gnomon/Renderer.h"
#include "render/GpuScene.h"
#include "shadow/ShadowMath.h"

namespace gnomon::render {

struct ShadowedLight {
    int light = 0;  // index into Scene::lights
    int mapSize = 1024;
    shadow::LightCameraFrame frame;
    bool depthClamp = false;  // fitted cameras: casters in front of near still cast
};

class ShadowPass {
public:
    ShadowPass();
    // Renders (or keeps) the map of every light in `lights`; layer i belongs to lights[i].
    // Returns the number of maps actually rendered.
    int render(const GpuScene& scene, const std::vector<ShadowedLight>& lights,
               const ShadowOptions& options);
    const gl::Texture& maps() const { return mMaps; }
    std::size_t bytes() const;
    // Layer i's map as 16-bit grey, top row first (darker = nearer).
    Image16 readBack(int layer, int mapSize) const;

private:
    struct LayerState {
        glm::mat4 clipFromWorld{0.0f};
        int mapSize = 0;
        std::uint64_t sceneRevision = ~0ull;
        CullMode cull = CullMode::Back;
        float slope = -1.0f, units = -1.0f;
        bool depthClamp = false;
        bool operator==(const LayerState&) const = default;
    };
    void allocate(int size, int layers);

    gl::Program mProgram;
    gl::Texture mMaps;
    std::vector<gl::Framebuffer> mFramebuffers;
    std::vector<LayerState> mLayers;
};

}  // namespace gnomon::render
