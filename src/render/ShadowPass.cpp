#include "render/ShadowPass.h"

#include <algorithm>
#include <cstring>

#include "gl/Program.h"

namespace gnomon::render {

ShadowPass::ShadowPass()
    : mProgram(gl::buildProgram("shadow depth", {{GL_VERTEX_SHADER, "depth.vert.glsl"},
                                                 {GL_FRAGMENT_SHADER, "depth.frag.glsl"}})) {}

void ShadowPass::allocate(int size, int layers) {
    mMaps = gl::Texture::array2D("shadow maps", GL_DEPTH_COMPONENT32F, size, size, layers);
    glTextureParameteri(mMaps.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(mMaps.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTextureParameteri(mMaps.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(mMaps.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    mFramebuffers.clear();
    for (int layer = 0; layer < layers; ++layer) {
        gl::Framebuffer fb("shadow map layer " + std::to_string(layer));
        glNamedFramebufferTextureLayer(fb.id(), GL_DEPTH_ATTACHMENT, mMaps.id(), 0, layer);
        glNamedFramebufferDrawBuffer(fb.id(), GL_NONE);
        glNamedFramebufferReadBuffer(fb.id(), GL_NONE);
        fb.checkComplete();
        mFramebuffers.push_back(std::move(fb));
    }
    mLayers.assign(size_t(layers), LayerState{});
}

std::size_t ShadowPass::bytes() const {
    return mMaps ? std::size_t(mMaps.width()) * mMaps.height() * mMaps.layers() * 4 : 0;
}

int ShadowPass::render(const GpuScene& scene, const std::vector<ShadowedLight>& lights,
                       const ShadowOptions& options) {
    if (lights.empty()) return 0;
    int size = 0;
    for (const ShadowedLight& l : lights)
        size = std::max(size, l.mapSize);
    const int layers = int(lights.size());
    if (!mMaps || mMaps.width() != size || mMaps.layers() != layers) allocate(size, layers);

    int rendered = 0;
    bool stateSet = false;
    for (int layer = 0; layer < layers; ++layer) {
        const ShadowedLight& light = lights[size_t(layer)];
        LayerState want{
            light.frame.clipFromWorld(), light.mapSize,     scene.revision(), options.cull,
            options.biasSlope,           options.biasUnits, light.depthClamp};
        if (mLayers[size_t(layer)] == want) continue;  // nothing changed: keep the map
        mLayers[size_t(layer)] = want;
        if (!stateSet) {
            glUseProgram(mProgram.id());
            scene.bind();
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_LESS);
            glDepthMask(GL_TRUE);
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffset(options.biasSlope, options.biasUnits);
            if (options.cull != CullMode::None) {
                glCullFace(options.cull == CullMode::Front ? GL_FRONT : GL_BACK);
            }
            stateSet = true;
        }
        if (light.depthClamp) {
            glEnable(GL_DEPTH_CLAMP);
        } else {
            glDisable(GL_DEPTH_CLAMP);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffers[size_t(layer)].id());
        // Clear the whole layer (clears ignore the viewport) so no stale depth is ever read.
        const float one = 1.0f;
        glClearNamedFramebufferfv(mFramebuffers[size_t(layer)].id(), GL_DEPTH, 0, &one);
        glViewport(0, 0, light.mapSize, light.mapSize);
        const glm::mat4 clipFromWorld = light.frame.clipFromWorld();
        glUniformMatrix4fv(1, 1, GL_FALSE, &clipFromWorld[0][0]);
        bool culling = false;
        glDisable(GL_CULL_FACE);
        for (const DrawItem& item : scene.items()) {
            if (!item.casts) continue;
            const bool wantCull = options.cull != CullMode::None && !item.doubleSided;
            if (wantCull != culling) {
                wantCull ? glEnable(GL_CULL_FACE) : glDisable(GL_CULL_FACE);
                culling = wantCull;
            }
            scene.draw(item);
        }
        ++rendered;
    }
    if (stateSet) {
        glDisable(GL_POLYGON_OFFSET_FILL);
        glDisable(GL_DEPTH_CLAMP);
        glDisable(GL_CULL_FACE);
    }
    return rendered;
}

Image16 ShadowPass::readBack(int layer, int mapSize) const {
    std::vector<float> depth(size_t(mapSize) * mapSize);
    glGetTextureSubImage(mMaps.id(), 0, 0, 0, layer, mapSize, mapSize, 1, GL_DEPTH_COMPONENT,
                         GL_FLOAT, GLsizei(depth.size() * sizeof(float)), depth.data());
    Image16 out;
    out.width = out.height = mapSize;
    out.pixels.resize(depth.size());
    for (int y = 0; y < mapSize; ++y) {
        const float* row = &depth[size_t(mapSize - 1 - y) * mapSize];  // GL rows are bottom-up
        for (int x = 0; x < mapSize; ++x) {
            const float d = std::clamp(row[x], 0.0f, 1.0f);
            out.pixels[size_t(y) * mapSize + x] = std::uint16_t(d * 65535.0f + 0.5f);
        }
    }
    return out;
}

}  // namespace gnomon::render
