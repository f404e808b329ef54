#include "render/VisibilityTarget.h"

#include <algorithm>
#include <string>
#include <vector>

#include "gl/Caps.h"

namespace gnomon::render {

namespace {
// One texture's layers (a layer per light, bottom-up rows, `channels` floats a texel) handed
// to `store(cell, texel)` with ShadowVisibility's cell index (top-down rows, lights inner).
template <typename Store>
void readLayers(const gl::Texture& texture, GLenum format, int channels, int width, int height,
                int lights, const Store& store) {
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    std::vector<float> layers(pixels * std::size_t(channels) * std::size_t(lights));
    const std::size_t layerFloats = pixels * std::size_t(channels);
    for (int l = 0; l < lights; ++l) {
        texture.read(0, 0, l, width, height, format, GL_FLOAT, layerFloats * sizeof(float),
                     &layers[std::size_t(l) * layerFloats]);
    }
    for (int l = 0; l < lights; ++l) {
        for (int y = 0; y < height; ++y) {
            const float* src = &layers[(std::size_t(l) * pixels +
                                        std::size_t(height - 1 - y) * std::size_t(width)) *
                                       std::size_t(channels)];
            for (int x = 0; x < width; ++x) {
                const std::size_t cell =
                    (std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(lights) +
                    std::size_t(l);
                store(cell, &src[std::size_t(x) * std::size_t(channels)]);
            }
        }
    }
}
}  // namespace

void VisibilityTarget::clear(int width, int height, int lights, bool withTint,
                             const gl::Texture& depth) {
    const bool images = gl::activeCaps().imageStore;
    const int layers = std::max(1, lights);
    auto fits = [&](const gl::Texture& t) {
        return t && t.width() == width && t.height() == height && t.layers() == layers;
    };
    const bool remade = !fits(mVisibility) || (withTint && !fits(mTint));
    if (!fits(mVisibility)) {
        mVisibility = gl::Texture::array2D("shadow visibility", GL_RGBA32F, width, height, layers);
    }
    const float unset[4] = {1.0f, 0.0f, 0.0f, 0.0f};  // lit, no map, (ES) no object, no ray
    mVisibility.clear(GL_RGBA, unset);
    if (images) {
        if (!mObjects || mObjects.width() != width || mObjects.height() != height) {
            mObjects = gl::Texture::plain2D("shadow visibility objects", GL_R32F, width, height);
        }
        const float none = 0.0f;
        mObjects.clear(GL_RED, &none);
    }
    mWithTint = withTint;
    if (withTint) {
        if (!fits(mTint)) {
            mTint = gl::Texture::array2D("shadow tint", GL_RGBA32F, width, height, layers);
        }
        const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
        mTint.clear(GL_RGBA, white);
    }
    if (!images && (remade || mTargetsDepth != depth.id() || mTargetsTint != withTint ||
                    mLayerTargets.empty())) {
        makeLayerTargets(depth);
    }
}

void VisibilityTarget::makeLayerTargets(const gl::Texture& depth) {
    mLayerTargets.clear();
    for (int layer = 0; layer < mVisibility.layers(); ++layer) {
        gl::Framebuffer fb("shadow visibility layer " + std::to_string(layer));
        fb.attachLayer(GL_COLOR_ATTACHMENT1, mVisibility, layer);
        if (mWithTint) fb.attachLayer(GL_COLOR_ATTACHMENT2, mTint, layer);
        fb.attach(GL_DEPTH_ATTACHMENT, depth);
        fb.drawBuffers(
            {GL_NONE, GL_COLOR_ATTACHMENT1, GLenum(mWithTint ? GL_COLOR_ATTACHMENT2 : GL_NONE)});
        fb.checkComplete();
        mLayerTargets.push_back(std::move(fb));
    }
    mTargetsDepth = depth.id();
    mTargetsTint = mWithTint;
}

void VisibilityTarget::read(int width, int height, int lights, bool drawn,
                            ShadowVisibility& out) const {
    out.width = width;
    out.height = height;
    out.lights = lights;
    const std::size_t cells =
        std::size_t(out.width) * std::size_t(out.height) * std::size_t(lights);
    out.visibility.assign(cells, 1.0f);
    out.texelWorld.assign(cells, 0.0f);
    out.traced.assign(cells, 0);
    // Nothing drawn: no object either, so that a score keeps every pixel (and reads it lit).
    out.object.assign(drawn ? std::size_t(out.width) * std::size_t(out.height) : 0, -1);
    out.tint.assign(mWithTint ? 3 * cells : 0, 1.0f);
    if (lights == 0 || !drawn) return;
    // ES (no object texture): the object in the first layer's third channel.
    const bool es = !mObjects;
    readLayers(mVisibility, GL_RGBA, 4, out.width, out.height, lights,
               [&](std::size_t cell, const float* v) {
                   out.visibility[cell] = v[0];
                   out.texelWorld[cell] = v[1];
                   out.traced[cell] = v[3] > 0.5f ? 1 : 0;
               });
    const int at = es ? 2 : 0;
    readLayers(es ? mVisibility : mObjects, es ? GL_RGBA : GL_RED, es ? 4 : 1, out.width,
               out.height, 1,
               [&](std::size_t pixel, const float* v) { out.object[pixel] = int(v[at]) - 1; });
    if (!mWithTint) return;
    readLayers(mTint, GL_RGBA, 4, out.width, out.height, lights,
               [&](std::size_t cell, const float* v) { std::copy(v, v + 3, &out.tint[3 * cell]); });
}

}  // namespace gnomon::render
