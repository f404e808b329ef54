#include "render/RayMasks.h"

#include <algorithm>
#include <map>
#include <string>

#include "gl/Caps.h"
#include "gnomon/Error.h"

namespace gnomon::render {

namespace {
// `first` is stored as first / kFirstSplit and first mod kFirstSplit: each part a whole
// number a float holds exactly.
constexpr std::size_t kFirstSplit = 4096;
}  // namespace

RayCaster rayCaster(const Scene& scene, const Object& object, const ShadowOptions& options) {
    RayCaster c;
    if (!object.castsShadows || scene.meshes[object.mesh].indices.empty()) return c;
    const Material& m = scene.materials[object.material];
    float alpha = 0.0f;  // the alpha from which a texel blocks; 0: every texel blocks
    if (m.alphaMode == AlphaMode::Mask) {
        alpha = m.alphaCutoff;
    } else if (m.alphaMode == AlphaMode::Blend) {
        switch (options.blendShadows) {
            case BlendShadows::None:
                return c;
            case BlendShadows::Opaque:
                break;
            case BlendShadows::Coloured:
                alpha = kOpaqueBlendAlpha;
                break;
            case BlendShadows::Dithered:
                alpha = 0.5f;
                break;
        }
    }
    c.casts = true;
    if (!(alpha > 0.0f)) return c;
    const bool textured = m.baseColourTexture >= 0 &&
                          std::size_t(m.baseColourTexture) < scene.textures.size() &&
                          !scene.meshes[object.mesh].uvs.empty();
    // Without a texture the factor alone decides, the same for every texel.
    if (!textured || !(m.alpha > 0.0f)) {
        c.casts = m.alpha >= alpha;
        return c;
    }
    c.filtered = true;
    c.threshold = alpha / m.alpha;
    c.texture = m.baseColourTexture;
    return c;
}

void RayMasks::build(const Scene& scene, const std::vector<RayCaster>& casters,
                     const std::vector<bvh::BvhTriangle>& triangles, int rowTexels) {
    // Each filtered texture's alpha, once, and where it starts.
    std::map<int, std::size_t> first;
    std::vector<std::uint8_t> bytes;
    for (const bvh::BvhTriangle& t : triangles) {
        const RayCaster& c = casters[t.objectIndex()];
        if (!c.filtered || first.count(c.texture)) continue;
        const Texture& tex = scene.textures[std::size_t(c.texture)];
        first[c.texture] = bytes.size();
        for (std::size_t i = 3; i < tex.rgba.size(); i += 4)
            bytes.push_back(tex.rgba[i]);
    }
    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    mAny = !first.empty();
    if (first.empty()) {
        // A row each, as the shader reads them: its reads run for every pixel on a CPU driver,
        // masked off, and stay inside the texture.
        mUvs = gl::Texture::texelRows("shadow-ray uvs", none, 1, rowTexels);
        mAlphas = gl::Texture::display2D("shadow-ray alphas", Image(rowTexels, 1, 4));
        return;
    }
    std::vector<float> uvs(triangles.size() * 12, 0.0f);
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const bvh::BvhTriangle& t = triangles[i];
        const RayCaster& c = casters[t.objectIndex()];
        if (!c.filtered) continue;
        const Object& object = scene.objects[t.objectIndex()];
        const Mesh& mesh = scene.meshes[object.mesh];
        const Material& material = scene.materials[object.material];
        const Texture& tex = scene.textures[std::size_t(c.texture)];
        const std::uint32_t* corner = &mesh.indices[3 * std::size_t(t.primitiveIndex())];
        float* out = &uvs[12 * i];
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 uv = material.uvTransform * glm::vec3(mesh.uvs[corner[k]], 1.0f);
            out[k < 2 ? 2 * k : 4] = uv.x;
            out[k < 2 ? 2 * k + 1 : 5] = uv.y;
        }
        out[6] = c.threshold;
        out[7] = float(int(tex.wrapS) + 3 * int(tex.wrapT) + (tex.nearest ? 9 : 0));
        const std::size_t at = first[c.texture];
        out[8] = float(at / kFirstSplit);
        out[9] = float(at % kFirstSplit);
        out[10] = float(tex.width);
        out[11] = float(tex.height);
    }
    const int maxSize = gl::activeCaps().maxTextureSize;
    const int width = rowTexels;
    const std::size_t texels = (bytes.size() + 3) / 4;
    const std::size_t rows = (texels + std::size_t(width) - 1) / std::size_t(width);
    if (rows > std::size_t(maxSize)) {
        throw Error(ErrorKind::InvalidInput,
                    "shadow-rays: the masked casters' textures hold " +
                        std::to_string(bytes.size()) +
                        " alpha values; this OpenGL driver's textures hold at most " +
                        std::to_string(std::size_t(width) * std::size_t(maxSize) * 4));
    }
    Image packed(width, int(rows), 4);
    std::copy(bytes.begin(), bytes.end(), packed.pixels.begin());
    mUvs = gl::Texture::texelRows("shadow-ray uvs", uvs.data(), triangles.size() * 3, rowTexels);
    mAlphas = gl::Texture::display2D("shadow-ray alphas", packed);
}

}  // namespace gnomon::render
