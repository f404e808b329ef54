#include "truth/AlphaRays.h"

#include <algorithm>
#include <cmath>

namespace gnomon::truth {

namespace {

int wrapTexel(int i, int n, TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::ClampToEdge:
            return std::clamp(i, 0, n - 1);
        case TextureWrap::MirroredRepeat: {
            const int period = 2 * n;
            int m = ((i % period) + period) % period;
            return m < n ? m : period - 1 - m;
        }
        case TextureWrap::Repeat:
            break;
    }
    return ((i % n) + n) % n;
}

// sRGB to linear (IEC 61966-2-1), as the renderer's SRGB8_ALPHA8 textures decode.
float decodeSrgb(std::uint8_t value) {
    const float e = float(value) / 255.0f;
    return e <= 0.04045f ? e / 12.92f : std::pow((e + 0.055f) / 1.055f, 2.4f);
}

glm::vec4 texelAt(const Texture& tex, int i, int j) {
    i = wrapTexel(i, tex.width, tex.wrapS);
    j = wrapTexel(j, tex.height, tex.wrapT);
    const std::uint8_t* p =
        &tex.rgba[(std::size_t(j) * std::size_t(tex.width) + std::size_t(i)) * 4];
    return {decodeSrgb(p[0]), decodeSrgb(p[1]), decodeSrgb(p[2]), float(p[3]) / 255.0f};
}

// The texture at `uv`: nearest, or bilinear on decoded values (as GL filters sRGB textures).
glm::vec4 sample(const Texture& tex, const glm::vec2& uv) {
    const float x = uv.x * float(tex.width) - 0.5f, y = uv.y * float(tex.height) - 0.5f;
    if (!std::isfinite(x) || !std::isfinite(y)) return glm::vec4(1.0f);
    if (tex.nearest) {
        const float nx = std::floor(x + 0.5f), ny = std::floor(y + 0.5f);
        return texelAt(tex, int(std::fmod(nx, 1048576.0f)), int(std::fmod(ny, 1048576.0f)));
    }
    const float fx = std::floor(x), fy = std::floor(y);
    const int x0 = int(std::fmod(fx, 1048576.0f)), y0 = int(std::fmod(fy, 1048576.0f));
    const float wx = x - fx, wy = y - fy;
    const glm::vec4 top = glm::mix(texelAt(tex, x0, y0), texelAt(tex, x0 + 1, y0), wx);
    const glm::vec4 bottom = glm::mix(texelAt(tex, x0, y0 + 1), texelAt(tex, x0 + 1, y0 + 1), wx);
    return glm::mix(top, bottom, wy);
}

}  // namespace

glm::vec4 colourAt(const AlphaSurface& a, unsigned prim, float u, float v) {
    glm::vec4 c(a.material->baseColour, a.material->alpha);
    const std::uint32_t* t = &a.mesh->indices[3 * std::size_t(prim)];
    const float w = 1.0f - u - v;
    if (!a.mesh->colours.empty()) {
        const std::vector<glm::vec3>& vc = a.mesh->colours;
        c *= glm::vec4(w * vc[t[0]] + u * vc[t[1]] + v * vc[t[2]], 1.0f);
    }
    if (!a.texture || a.mesh->uvs.empty()) return c;
    const std::vector<glm::vec2>& uvs = a.mesh->uvs;
    const glm::vec2 uv =
        a.material->uvTransform * glm::vec3(w * uvs[t[0]] + u * uvs[t[1]] + v * uvs[t[2]], 1.0f);
    return c * sample(*a.texture, uv);
}

float alphaAt(const AlphaSurface& a, unsigned prim, float u, float v) {
    float alpha = a.material->alpha;
    if (!a.texture || a.mesh->uvs.empty()) return alpha;
    return colourAt(a, prim, u, v).a;
}

glm::vec3 tintThrough(const glm::vec3& c, float alpha) {
    alpha = std::clamp(alpha, 0.0f, 1.0f);
    return (1.0f - alpha) * glm::mix(glm::vec3(1.0f), glm::clamp(c, 0.0f, 1.0f), alpha);
}

bool alphaStops(const AlphaSurface& surface, unsigned object, unsigned prim, float u, float v,
                AlphaState& state) {
    const Material& m = *surface.material;
    if (m.alphaMode == AlphaMode::Mask) return alphaAt(surface, prim, u, v) >= m.alphaCutoff;
    // Blended: opaque to shadow rays under --blend-shadows opaque, else passed through.
    if (!state.viewRay && state.blend == BlendShadows::Opaque) return true;
    if (state.viewRay || state.blend == BlendShadows::None) return false;
    const std::uint64_t key = std::uint64_t(object) << 32 | prim;
    const int n = std::min(state.seenCount, 8);
    if (std::find(state.seen, state.seen + n, key) != state.seen + n) return false;
    state.seen[state.seenCount++ % 8] = key;
    if (state.blend == BlendShadows::Dithered) {
        state.transmission *= 1.0f - std::clamp(alphaAt(surface, prim, u, v), 0.0f, 1.0f);
        return false;
    }
    const glm::vec4 c = colourAt(surface, prim, u, v);
    if (c.a >= kOpaqueBlendAlpha) return true;  // an opaque texel: blocks, as in the depth maps
    state.tint *= tintThrough(glm::vec3(c), c.a);
    return false;
}

}  // namespace gnomon::truth
