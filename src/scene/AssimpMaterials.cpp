// assimp materials and their textures: colour, opacity, sides, Blinn-Phong and shading model,
// and the diffuse (or base colour) texture from a file inside the model's folder or embedded.
#include <algorithm>
#include <cstring>
#include <map>

#include <assimp/material.h>

#include "scene/AssimpParts.h"
#include "scene/MeshTopology.h"
#include "scene/TextureDecode.h"

namespace gnomon::assimp_parts {

namespace {

namespace fs = std::filesystem;

TextureWrap wrapOf(aiTextureMapMode mode) {
    switch (mode) {
        case aiTextureMapMode_Clamp:
        case aiTextureMapMode_Decal:
            return TextureWrap::ClampToEdge;
        case aiTextureMapMode_Mirror:
            return TextureWrap::MirroredRepeat;
        default:
            return TextureWrap::Repeat;
    }
}

// The texels of texture `file` (written `name`) into `t`: an embedded image, or a file inside
// the model's folder. Returns why it cannot be used, empty when it can.
std::string textureImage(const Context& cx, const aiString& file, const std::string& name,
                         Texture& t) {
    std::string why;
    if (const aiTexture* embedded = cx.ai.GetEmbeddedTexture(file.C_Str())) {
        if (embedded->mHeight == 0) {  // compressed (PNG, JPEG...): mWidth bytes
            why = decodeTexture(reinterpret_cast<const unsigned char*>(embedded->pcData),
                                embedded->mWidth, t);
        } else if (embedded->mWidth > unsigned(kMaxTextureSide) ||
                   embedded->mHeight > unsigned(kMaxTextureSide)) {
            why = "the embedded image is " + std::to_string(embedded->mWidth) + "x" +
                  std::to_string(embedded->mHeight) + ", outside 1.." +
                  std::to_string(kMaxTextureSide) + " per side";
        } else {  // raw BGRA texels, rows top-down
            t.width = int(embedded->mWidth);
            t.height = int(embedded->mHeight);
            t.rgba.resize(std::size_t(t.width) * std::size_t(t.height) * 4);
            for (std::size_t i = 0; i < std::size_t(t.width) * std::size_t(t.height); ++i) {
                const aiTexel& x = embedded->pcData[i];
                t.rgba[4 * i] = x.r;
                t.rgba[4 * i + 1] = x.g;
                t.rgba[4 * i + 2] = x.b;
                t.rgba[4 * i + 3] = x.a;
            }
        }
    } else if (!name.empty() && name[0] == '*') {
        why = "the embedded image does not exist (" + std::to_string(cx.ai.mNumTextures) +
              " embedded)";
    } else {
        const fs::path rel(name);
        const bool absolute = rel.is_absolute() || (name.size() > 1 && name[1] == ':');
        const bool escapes =
            std::any_of(rel.begin(), rel.end(), [](const fs::path& p) { return p == ".."; });
        fs::path resolved;
        if (name.empty()) {
            why = "the texture names no file";
        } else if (absolute || escapes || !inside(cx.root, (cx.root / rel).string(), resolved)) {
            why =
                "it lies outside the model's folder (textures are read only from inside "
                "it: no absolute paths or .. escapes)";
        } else {
            try {
                const Texture loaded = loadTextureFile(resolved.string());
                t.width = loaded.width;
                t.height = loaded.height;
                t.rgba = loaded.rgba;
            } catch (const Error& e) {
                why = e.what();
            }
        }
    }
    return why;
}

// Textures: one gnomon texture per file (or embedded image) and wrap modes; -1 when the
// material has none of `type` or it cannot be used (with a warning naming `where`).
int readTexture(Context& cx, const aiMaterial& mat, aiTextureType type, const std::string& where) {
    aiString file;
    aiTextureMapping mapping = aiTextureMapping_UV;
    unsigned uvIndex = 0;
    aiTextureMapMode modes[2] = {aiTextureMapMode_Wrap, aiTextureMapMode_Wrap};
    if (mat.GetTexture(type, 0, &file, &mapping, &uvIndex, nullptr, nullptr, modes) != AI_SUCCESS) {
        return -1;
    }
    std::string name = file.C_Str();
    std::replace(name.begin(), name.end(), '\\', '/');
    if (mapping != aiTextureMapping_UV) {
        cx.scene.warnings.push_back(where + ": texture '" + name +
                                    "' is projected (not UV-mapped), which gnomon does not do: "
                                    "drawn untextured");
        return -1;
    }
    if (uvIndex != 0) {
        cx.scene.warnings.push_back(where + ": texture '" + name +
                                    "' uses texture coordinate set " + std::to_string(uvIndex) +
                                    "; gnomon reads set 0 only: drawn untextured");
        return -1;
    }
    const std::string key =
        name + "|" + std::to_string(int(modes[0])) + "|" + std::to_string(int(modes[1]));
    if (auto it = cx.textureOf.find(key); it != cx.textureOf.end()) return it->second;
    Texture t;
    t.name = name;
    const std::string why = textureImage(cx, file, name, t);
    if (!why.empty()) {
        cx.scene.warnings.push_back(where + ": texture '" + name + "' cannot be used (" + why +
                                    "): drawn untextured");
        return cx.textureOf[key] = -1;
    }
    t.wrapS = wrapOf(modes[0]);
    t.wrapT = wrapOf(modes[1]);
    cx.scene.textures.push_back(std::move(t));
    return cx.textureOf[key] = int(cx.scene.textures.size() - 1);
}

// Material `mi`: colour as the file gives it (an OBJ's Kd taken as linear), opacity, sides,
// Blinn-Phong from shininess and the specular colour, the base colour texture.
Material readMaterial(Context& cx, const aiMaterial& mat, unsigned mi) {
    Material g;
    aiString name;
    g.name = mat.Get(AI_MATKEY_NAME, name) == AI_SUCCESS ? std::string(name.C_Str())
                                                         : "materials[" + std::to_string(mi) + "]";
    const std::string where = "material '" + g.name + "'";
    aiColor4D colour;
    if (mat.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == AI_SUCCESS ||
        mat.Get(AI_MATKEY_BASE_COLOR, colour) == AI_SUCCESS) {
        g.baseColour = clampColour({colour.r, colour.g, colour.b});
    }
    float opacity = 1.0f;
    if (mat.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS && opacity < 1.0f) {
        if (!(opacity > 0.0f)) {
            cx.scene.warnings.push_back(where +
                                        " has opacity 0 (what many exporters write for 'not "
                                        "set'): taken as opaque");
        } else {
            g.alphaMode = AlphaMode::Blend;
            g.alpha = std::clamp(opacity, 0.0f, 1.0f);
        }
    }
    int twoSided = 0;
    if (mat.Get(AI_MATKEY_TWOSIDED, twoSided) == AI_SUCCESS) {
        g.doubleSided = twoSided != 0;
        cx.sidedByFile.insert(mi);
    }
    float shininess = 0.0f;
    if (mat.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS && std::isfinite(shininess))
        g.shininess = std::clamp(shininess, 1.0f, 2048.0f);
    aiColor3D specular;
    if (mat.Get(AI_MATKEY_COLOR_SPECULAR, specular) == AI_SUCCESS) {
        float strength = 1.0f;
        mat.Get(AI_MATKEY_SHININESS_STRENGTH, strength);
        const float s = std::max({specular.r, specular.g, specular.b}) * strength;
        g.specular = std::isfinite(s) ? std::clamp(s, 0.0f, 1.0f) : 0.0f;
    }
    int shading = 0;
    if (mat.Get(AI_MATKEY_SHADING_MODEL, shading) == AI_SUCCESS) {
        if (shading == aiShadingMode_NoShading) g.unlit = true;
        if (shading == aiShadingMode_Flat || shading == aiShadingMode_Gouraud)
            g.specular = 0.0f;  // diffuse only (an OBJ's illum 1)
    }
    g.baseColourTexture = readTexture(cx, mat, aiTextureType_DIFFUSE, where);
    if (g.baseColourTexture < 0 && mat.GetTextureCount(aiTextureType_DIFFUSE) == 0)
        g.baseColourTexture = readTexture(cx, mat, aiTextureType_BASE_COLOR, where);
    // Cut-outs: an opacity map that is the diffuse texture's own alpha (an OBJ's map_d
    // naming the map_Kd file) cuts at 0.5; another opacity map is not read.
    aiString diffuseFile, opacityFile;
    if (mat.GetTexture(aiTextureType_OPACITY, 0, &opacityFile) == AI_SUCCESS) {
        mat.GetTexture(aiTextureType_DIFFUSE, 0, &diffuseFile);
        if (g.baseColourTexture >= 0 &&
            std::strcmp(opacityFile.C_Str(), diffuseFile.C_Str()) == 0) {
            if (g.alphaMode == AlphaMode::Opaque) g.alphaMode = AlphaMode::Mask;
        } else {
            cx.scene.warnings.push_back(where + ": opacity map '" +
                                        std::string(opacityFile.C_Str()) + "' is ignored");
        }
    }
    return g;
}

}  // namespace

// glTF says which faces are fronts; most formats assimp reads do not, and modelling tools show
// them double-sided. Culling back faces keeps the picture only on a closed surface wound
// outwards (MeshTopology.h): glmark2's cat, an open shell, lost the near half of its body, and
// a Blender axe wound inwards showed its unlit inside.
void sidesFromTopology(Context& cx) {
    std::map<std::uint32_t, int> winding;  // per mesh, found once
    for (const Object& o : cx.scene.objects) {
        Material& m = cx.scene.materials[o.material];
        if (m.doubleSided || cx.sidedByFile.count(o.material)) continue;
        auto [it, fresh] = winding.emplace(o.mesh, 0);
        if (fresh) it->second = closedWinding(cx.scene.meshes[o.mesh]);
        const bool mirrored = glm::determinant(glm::mat3(o.worldFromModel)) < 0.0f;
        if (it->second * (mirrored ? -1 : 1) <= 0) m.doubleSided = true;
    }
}

void readMaterials(Context& cx) {
    for (unsigned mi = 0; mi < cx.ai.mNumMaterials; ++mi)
        cx.scene.materials.push_back(readMaterial(cx, *cx.ai.mMaterials[mi], mi));
    if (cx.scene.materials.empty()) {
        Material m;
        m.name = "default";
        cx.scene.materials.push_back(m);
    }
}

}  // namespace gnomon::assimp_parts
