// glTF materials and their textures: base colour factor and texture (decoded on first use,
// with its sampler and KHR_texture_transform), alpha mode and cutoff, Blinn-Phong from
// roughness and metalness, double-sidedness.
#include <algorithm>
#include <cmath>

#include "scene/GltfParts.h"
#include "scene/TextureDecode.h"

namespace gnomon::gltf {

namespace {

TextureWrap wrap(int w) {
    return w == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE     ? TextureWrap::ClampToEdge
           : w == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT ? TextureWrap::MirroredRepeat
                                                        : TextureWrap::Repeat;
}

// Textures: a glTF texture (image + sampler) becomes one gnomon texture on first use.
int texture(Context& cx, int index, const std::string& where) {
    const tinygltf::Model& model = cx.model;
    const Reader& read = cx.read;
    if (auto it = cx.textureOf.find(index); it != cx.textureOf.end()) return it->second;
    if (index < 0 || std::size_t(index) >= model.textures.size()) {
        read.fail(where + " refers to textures[" + std::to_string(index) +
                  "], which does not exist");
    }
    const tinygltf::Texture& t = model.textures[std::size_t(index)];
    const std::string tname = "textures[" + std::to_string(index) + "]";
    if (t.source < 0 || std::size_t(t.source) >= model.images.size()) {
        read.fail(tname + " has no image gnomon can read (source " + std::to_string(t.source) +
                  ")");
    }
    const tinygltf::Image& image = model.images[std::size_t(t.source)];
    const std::string iname =
        "images[" + std::to_string(t.source) + "]" +
        (image.uri.empty() || image.uri.rfind("data:", 0) == 0 ? "" : " ('" + image.uri + "')");
    Texture g;
    g.name = image.name.empty() ? iname : image.name;
    if (!image.as_is) read.fail(iname + " holds no encoded image data");
    if (const std::string why = decodeTexture(image.image.data(), image.image.size(), g);
        !why.empty()) {
        read.fail(iname + ": " + why);
    }
    if (t.sampler >= 0 && std::size_t(t.sampler) < model.samplers.size()) {
        const tinygltf::Sampler& sm = model.samplers[std::size_t(t.sampler)];
        g.wrapS = wrap(sm.wrapS);
        g.wrapT = wrap(sm.wrapT);
        g.nearest = sm.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
    }
    cx.scene.textures.push_back(std::move(g));
    cx.textureOf[index] = int(cx.scene.textures.size() - 1);
    return cx.textureOf[index];
}

// KHR_texture_transform `x` of material `where`'s base colour texture into g.uvTransform,
// and its texCoord override into `texCoord`.
void textureTransform(const Reader& read, const tinygltf::Value& x, const std::string& where,
                      Material& g, int& texCoord) {
    auto pair = [&](const char* key, glm::vec2 fallback) {
        if (!x.Has(key) || !x.Get(key).IsArray() || x.Get(key).ArrayLen() != 2) return fallback;
        return glm::vec2(float(x.Get(key).Get(0).GetNumberAsDouble()),
                         float(x.Get(key).Get(1).GetNumberAsDouble()));
    };
    const glm::vec2 offset = pair("offset", glm::vec2(0.0f));
    const glm::vec2 scale = pair("scale", glm::vec2(1.0f));
    const float r = x.Has("rotation") ? float(x.Get("rotation").GetNumberAsDouble()) : 0.0f;
    // uv' = T R S uv, rotating counter-clockwise in uv space (the extension's
    // example: offset (0, 1), rotation pi/2, scale 0.5 picks the lower-left
    // quadrant turned clockwise).
    const float c = std::cos(r), sn = std::sin(r);
    const glm::mat3 T(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
    const glm::mat3 R(c, -sn, 0, sn, c, 0, 0, 0, 1);
    const glm::mat3 S(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
    g.uvTransform = T * R * S;
    if (x.Has("texCoord")) texCoord = x.Get("texCoord").GetNumberAsInt();
    bool finiteTransform = true;
    for (int col = 0; col < 3; ++col)
        for (int row = 0; row < 3; ++row)
            finiteTransform = finiteTransform && std::isfinite(g.uvTransform[col][row]);
    if (!finiteTransform) read.fail(where + " has a KHR_texture_transform that is not finite");
}

// Materials: the base colour factor (linear) and texture, alpha, Blinn-Phong from
// roughness and metalness; materials[mi] into cx.scene.materials and cx.texCoordOf.
void readMaterial(Context& cx, std::size_t mi) {
    const Reader& read = cx.read;
    const tinygltf::Material& mat = cx.model.materials[mi];
    const std::string where = "materials[" + std::to_string(mi) + "]";
    Material g;
    g.name = mat.name;
    const auto& pbr = mat.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() >= 3) {
        g.baseColour = glm::vec3(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]),
                                 float(pbr.baseColorFactor[2]));
    }
    if (pbr.baseColorFactor.size() == 4)
        g.alpha = std::clamp(float(pbr.baseColorFactor[3]), 0.0f, 1.0f);
    int texCoord = -1;
    if (pbr.baseColorTexture.index >= 0) {
        g.baseColourTexture = texture(cx, pbr.baseColorTexture.index, where);
        texCoord = pbr.baseColorTexture.texCoord;
        const tinygltf::ExtensionMap& ext = pbr.baseColorTexture.extensions;
        if (auto it = ext.find("KHR_texture_transform"); it != ext.end() && it->second.IsObject()) {
            textureTransform(read, it->second, where, g, texCoord);
        }
    }
    cx.texCoordOf.push_back(texCoord);
    if (mat.alphaMode == "MASK") {
        g.alphaMode = AlphaMode::Mask;
        g.alphaCutoff = std::clamp(float(mat.alphaCutoff), 0.0f, 1.0f);
    } else if (mat.alphaMode == "BLEND") {
        g.alphaMode = AlphaMode::Blend;
    } else if (!mat.alphaMode.empty() && mat.alphaMode != "OPAQUE") {
        read.fail(where + " has alphaMode '" + mat.alphaMode +
                  "' (expected OPAQUE, MASK or BLEND)");
    }
    const float roughness = std::clamp(float(pbr.roughnessFactor), 0.02f, 1.0f);
    g.shininess =
        std::clamp(2.0f / (roughness * roughness * roughness * roughness) - 2.0f, 1.0f, 2048.0f);
    g.specular = 0.04f + 0.5f * float(pbr.metallicFactor) * (1.0f - roughness);
    g.doubleSided = mat.doubleSided;
    cx.scene.materials.push_back(g);
}

}  // namespace

void readMaterials(Context& cx) {
    for (std::size_t mi = 0; mi < cx.model.materials.size(); ++mi)
        readMaterial(cx, mi);
    cx.defaultMaterial = std::uint32_t(cx.scene.materials.size());
    {
        Material m;  // glTF's default: white, fully rough
        m.name = "default";
        m.specular = 0.04f;
        m.shininess = 1.0f;
        cx.scene.materials.push_back(m);
    }
}

}  // namespace gnomon::gltf
