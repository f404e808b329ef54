// What the glTF loader's files share (internal): the accessor reader, the context the
// loading steps pass along, and the steps GltfMaterials.cpp and GltfMeshes.cpp provide.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <tiny_gltf.h>

#include "gnomon/Error.h"
#include "gnomon/Scene.h"

namespace gnomon::gltf {

// Reads accessors with every bound checked (GltfMeshes.cpp); errors name the file.
class Reader {
public:
    Reader(const tinygltf::Model& model, std::string file) : m(model), file(std::move(file)) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw Error(ErrorKind::InvalidInput, file + ": " + what);
    }

    // Element i of an accessor as `components` floats (normalised integers scaled to
    // [0, 1]), with every bound checked.
    std::vector<float> floats(int index, int components, const char* role) const;

    std::vector<std::uint32_t> indices(int index) const;

    std::string name(int accessor) const { return "accessors[" + std::to_string(accessor) + "]"; }

private:
    const tinygltf::Accessor& accessor(int index, const char* role) const;

    // The first element's bytes and the stride, after checking that `count` elements of
    // `elementBytes` fit in the buffer view and the view in its buffer.
    void view(int index, std::size_t elementBytes, const unsigned char*& base,
              std::size_t& stride) const;

    const tinygltf::Model& m;
    std::string file;
};

// What the loading steps share: the parsed model, its reader, the scene being built, and
// what one step leaves for the next.
struct Context {
    Context(const tinygltf::Model& model_, const Reader& read_, Scene& scene_)
        : model(model_), read(read_), scene(scene_) {}

    const tinygltf::Model& model;
    const Reader& read;
    Scene& scene;
    // Textures: a glTF texture (image + sampler) becomes one gnomon texture on first use.
    std::map<int, int> textureOf;
    // texCoordOf: the TEXCOORD_n set each material's texture reads.
    std::vector<int> texCoordOf;
    // The material of primitives without one (glTF's default), after the file's own.
    std::uint32_t defaultMaterial = 0;
    // One gnomon mesh per primitive (and per winding, for mirrored nodes).
    std::map<std::tuple<int, int, bool>, std::uint32_t> meshOf;
    long zeroArea = 0;  // triangles skipped, for one warning at the end
};

// Materials: every material of the file into cx.scene (with the textures they use) and
// cx.texCoordOf, then the default material, cx.defaultMaterial (GltfMaterials.cpp).
void readMaterials(Context& cx);

// The gnomon mesh of primitive `primIndex` of meshes[meshIndex] (winding reversed when
// `flipped`), made on first use; -1 when it draws no triangles (GltfMeshes.cpp).
std::int64_t primitiveMesh(Context& cx, int meshIndex, int primIndex, bool flipped);

// The nodes MSFT_lod names as nodes[n]'s coarser versions, finest first (material LODs
// change no shadow and are not read). A version whose mesh does not split into the same
// primitives is left out with a warning: each primitive's version stands in for it alone
// (GltfMeshes.cpp).
std::vector<int> lodNodes(Context& cx, int n, const tinygltf::Node& node);

// The positions and triangles of primitive `primIndex` of meshes[meshIndex] as a coarser
// version of another mesh (glTF's MSFT_lod), taken into that mesh's model space by `toModel`
// (winding reversed when `flipped`); empty when it draws no triangles (GltfMeshes.cpp).
MeshLod primitiveLod(Context& cx, int meshIndex, int primIndex, bool flipped,
                     const glm::mat4& toModel);

}  // namespace gnomon::gltf
