// assimp meshes into gnomon meshes: positions, normals, vertex colours, texture coordinates and
// triangles (winding flipped for mirrored nodes), validated before and after post-processing.
#include <algorithm>

#include "scene/AssimpParts.h"

namespace gnomon::assimp_parts {

void checkMeshesAsRead(const aiScene& ai, const Fail& fail) {
    // Run before assimp validates the scene: the arrays are checked for being there.
    if (ai.mNumMeshes > 0 && !ai.mMeshes) fail("meshes missing");
    for (unsigned i = 0; i < ai.mNumMeshes; ++i) {
        if (!ai.mMeshes[i]) fail("meshes[" + std::to_string(i) + "] missing");
        const aiMesh& m = *ai.mMeshes[i];
        if ((m.mNumVertices > 0 && !m.mVertices) || (m.mNumFaces > 0 && !m.mFaces))
            fail(meshName(m, i) + " lacks its vertices or faces");
        for (unsigned v = 0; v < m.mNumVertices; ++v) {
            if (!finite(toGlm(m.mVertices[v]))) {
                fail(meshName(m, i) + " vertex " + std::to_string(v) +
                     " has a position that is NaN or infinite");
            }
        }
    }
    // assimp 5.2's PLY importer marks triangle meshes as polygons and lets empty faces
    // through; either makes Triangulate abort the process (an assertion left on in Debian's
    // build). Empty faces are refused, the types taken from the faces.
    for (unsigned i = 0; i < ai.mNumMeshes; ++i) {
        aiMesh& m = *ai.mMeshes[i];
        unsigned types = 0;
        for (unsigned f = 0; f < m.mNumFaces; ++f) {
            if (m.mFaces[f].mNumIndices == 0)
                fail(meshName(m, i) + " face " + std::to_string(f) + " has no vertices");
            types |= unsigned(AI_PRIMITIVE_TYPE_FOR_N_INDICES(m.mFaces[f].mNumIndices));
        }
        m.mPrimitiveTypes = types;
    }
}

void warnMissingNormals(const aiScene& ai, Scene& scene) {
    for (unsigned i = 0; i < ai.mNumMeshes; ++i) {
        const aiMesh& m = *ai.mMeshes[i];
        if ((m.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) && !m.HasNormals()) {
            scene.warnings.push_back(meshName(m, i) +
                                     " has no normals: smooth ones generated (creases above " +
                                     std::to_string(int(kCreaseDegrees)) + " degrees kept)");
        }
    }
}

std::int64_t assimpMesh(Context& cx, unsigned index, bool flipped) {
    const auto key = std::make_pair(index, flipped);
    if (auto it = cx.meshOf.find(key); it != cx.meshOf.end()) return it->second;
    std::int64_t& result = cx.meshOf[key] = -1;
    const aiMesh& m = *cx.ai.mMeshes[index];
    const std::string where = meshName(m, index);
    const bool report = cx.reported.insert(index).second;
    if (!(m.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) {
        if (report) cx.scene.warnings.push_back(where + " draws points or lines only: skipped");
        return result;
    }
    if (m.mMaterialIndex >= cx.scene.materials.size())
        cx.fail(where + " refers to a missing material (" + std::to_string(m.mMaterialIndex) + ")");
    const bool textured = cx.scene.materials[m.mMaterialIndex].baseColourTexture >= 0;
    Mesh mesh;
    mesh.name = m.mName.length > 0 ? m.mName.C_Str() : "meshes[" + std::to_string(index) + "]";
    const unsigned n = m.mNumVertices;
    mesh.positions.resize(n);
    mesh.normals.resize(n);
    for (unsigned v = 0; v < n; ++v) {
        mesh.positions[v] = toGlm(m.mVertices[v]);
        if (!finite(mesh.positions[v]))
            cx.fail(where + " vertex " + std::to_string(v) +
                    " has a position that is NaN or infinite");
        const glm::vec3 nv = m.HasNormals() ? toGlm(m.mNormals[v]) : glm::vec3(0, 1, 0);
        const float len = glm::length(nv);
        mesh.normals[v] = len > 0.0f && std::isfinite(len) ? nv / len : glm::vec3(0, 1, 0);
    }
    if (m.HasVertexColors(0)) {
        mesh.colours.resize(n);
        for (unsigned v = 0; v < n; ++v) {
            const aiColor4D& c = m.mColors[0][v];
            mesh.colours[v] = clampColour({c.r, c.g, c.b});
        }
    }
    if (textured && m.HasTextureCoords(0)) {
        mesh.uvs.resize(n);
        for (unsigned v = 0; v < n; ++v) {
            mesh.uvs[v] = {m.mTextureCoords[0][v].x, m.mTextureCoords[0][v].y};
            if (!std::isfinite(mesh.uvs[v].x) || !std::isfinite(mesh.uvs[v].y)) {
                cx.fail(where + " vertex " + std::to_string(v) +
                        " has texture coordinates that are NaN or infinite");
            }
        }
    } else if (textured && report) {
        cx.scene.warnings.push_back(where +
                                    " has a textured material but no texture coordinates: "
                                    "drawn untextured");
    }
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
        const aiFace& face = m.mFaces[f];
        if (face.mNumIndices != 3) continue;  // a point or line left among triangles
        std::uint32_t v[3] = {face.mIndices[0], face.mIndices[1], face.mIndices[2]};
        for (std::uint32_t i : v) {
            if (i >= n) {
                cx.fail(where + " face " + std::to_string(f) + " refers to vertex " +
                        std::to_string(i) + " but the mesh has " + std::to_string(n) + " vertices");
            }
        }
        if (flipped) std::swap(v[1], v[2]);
        const glm::vec3 a = mesh.positions[v[0]];
        if (!(glm::length(glm::cross(mesh.positions[v[1]] - a, mesh.positions[v[2]] - a)) > 0.0f)) {
            if (report) ++cx.zeroArea;
            continue;
        }
        mesh.indices.insert(mesh.indices.end(), {v[0], v[1], v[2]});
    }
    if (mesh.indices.empty()) return result;
    cx.scene.meshes.push_back(std::move(mesh));
    return result = std::int64_t(cx.scene.meshes.size() - 1);
}

}  // namespace gnomon::assimp_parts
