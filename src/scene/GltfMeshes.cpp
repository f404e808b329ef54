// glTF accessors and mesh primitives: accessor reads with every bound checked, and each
// triangle primitive (list, strip or fan) into a gnomon mesh with positions, normals (flat
// ones made where missing), COLOR_0 and the material texture's TEXCOORD_n, all validated;
// and the coarser versions MSFT_lod names for a node's primitives.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "scene/GltfParts.h"

namespace gnomon::gltf {

std::vector<float> Reader::floats(int index, int components, const char* role) const {
    const tinygltf::Accessor& a = accessor(index, role);
    const int have = tinygltf::GetNumComponentsInType(std::uint32_t(a.type));
    if (have != components && !(components == 4 && have == 3)) {
        fail(name(index) + " (" + role + ") has " + std::to_string(have) +
             " components, expected " + std::to_string(components));
    }
    std::vector<float> out(std::size_t(a.count) * std::size_t(components), 1.0f);
    const unsigned char* base = nullptr;
    std::size_t stride = 0;
    const int size = tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType));
    if (size <= 0) fail(name(index) + " has an unknown component type");
    view(index, std::size_t(size) * std::size_t(have), base, stride);
    for (std::size_t i = 0; i < a.count; ++i) {
        const unsigned char* e = base + i * stride;
        for (int c = 0; c < have; ++c) {
            float v = 0.0f;
            const unsigned char* p = e + std::size_t(c) * std::size_t(size);
            switch (a.componentType) {
                case TINYGLTF_COMPONENT_TYPE_FLOAT:
                    std::memcpy(&v, p, 4);
                    break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                    v = float(*p) / (a.normalized ? 255.0f : 1.0f);
                    break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                    std::uint16_t u;
                    std::memcpy(&u, p, 2);
                    v = float(u) / (a.normalized ? 65535.0f : 1.0f);
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_BYTE:
                    v = a.normalized ? std::max(float(std::int8_t(*p)) / 127.0f, -1.0f)
                                     : float(std::int8_t(*p));
                    break;
                case TINYGLTF_COMPONENT_TYPE_SHORT: {
                    std::int16_t s;
                    std::memcpy(&s, p, 2);
                    v = a.normalized ? std::max(float(s) / 32767.0f, -1.0f) : float(s);
                    break;
                }
                default:
                    fail(name(index) + " (" + role + ") has a component type gnomon cannot read");
            }
            out[i * std::size_t(components) + std::size_t(c)] = v;
        }
    }
    return out;
}

std::vector<std::uint32_t> Reader::indices(int index) const {
    const tinygltf::Accessor& a = accessor(index, "indices");
    if (a.type != TINYGLTF_TYPE_SCALAR) fail(name(index) + " (indices) is not SCALAR");
    const int size = tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType));
    if (size != 1 && size != 2 && size != 4) {
        fail(name(index) + " (indices) is not of unsigned byte, short or int");
    }
    const unsigned char* base = nullptr;
    std::size_t stride = 0;
    view(index, std::size_t(size), base, stride);
    std::vector<std::uint32_t> out(a.count);
    for (std::size_t i = 0; i < a.count; ++i) {
        const unsigned char* p = base + i * stride;
        std::uint32_t v = 0;
        if (size == 1) v = *p;
        if (size == 2) {
            std::uint16_t u;
            std::memcpy(&u, p, 2);
            v = u;
        }
        if (size == 4) std::memcpy(&v, p, 4);
        out[i] = v;
    }
    return out;
}

const tinygltf::Accessor& Reader::accessor(int index, const char* role) const {
    if (index < 0 || std::size_t(index) >= m.accessors.size()) {
        fail(std::string(role) + " refers to accessors[" + std::to_string(index) +
             "], which does not exist (" + std::to_string(m.accessors.size()) + " accessors)");
    }
    return m.accessors[std::size_t(index)];
}

void Reader::view(int index, std::size_t elementBytes, const unsigned char*& base,
                  std::size_t& stride) const {
    const tinygltf::Accessor& a = m.accessors[std::size_t(index)];
    if (a.sparse.isSparse) fail(name(index) + " is sparse, which gnomon does not read");
    if (a.bufferView < 0 || std::size_t(a.bufferView) >= m.bufferViews.size()) {
        fail(name(index) + " refers to bufferViews[" + std::to_string(a.bufferView) +
             "], which does not exist");
    }
    const tinygltf::BufferView& v = m.bufferViews[std::size_t(a.bufferView)];
    const std::string vname = "bufferViews[" + std::to_string(a.bufferView) + "]";
    if (v.buffer < 0 || std::size_t(v.buffer) >= m.buffers.size()) {
        fail(vname + " refers to buffers[" + std::to_string(v.buffer) + "], which does not exist");
    }
    const tinygltf::Buffer& b = m.buffers[std::size_t(v.buffer)];
    if (v.byteOffset > b.data.size() || v.byteLength > b.data.size() - v.byteOffset) {
        fail(vname + " (offset " + std::to_string(v.byteOffset) + ", length " +
             std::to_string(v.byteLength) + ") overruns buffers[" + std::to_string(v.buffer) +
             "] of " + std::to_string(b.data.size()) + " bytes (missing or truncated?)");
    }
    stride = v.byteStride ? v.byteStride : elementBytes;
    if (stride < elementBytes) fail(vname + " has a byte stride smaller than its elements");
    const std::size_t need =
        a.count == 0 ? 0 : a.byteOffset + stride * (a.count - 1) + elementBytes;
    if (a.byteOffset > v.byteLength || need > v.byteLength) {
        fail(name(index) + " (" + std::to_string(a.count) + " elements from byte " +
             std::to_string(a.byteOffset) + ") overruns " + vname + " of " +
             std::to_string(v.byteLength) + " bytes");
    }
    base = b.data.data() + v.byteOffset + a.byteOffset;
}

namespace {

// A primitive's vertex data as read: floats per vertex, empty when absent.
struct Attributes {
    std::vector<float> pos, normals, colours, uvs;
};

// POSITION, every coordinate finite.
std::vector<float> readPositions(const Reader& read, const tinygltf::Primitive& p,
                                 const std::string& where) {
    auto attr = p.attributes.find("POSITION");
    if (attr == p.attributes.end()) read.fail(where + " has no POSITION");
    std::vector<float> pos = read.floats(attr->second, 3, "POSITION");
    for (float v : pos) {
        if (!std::isfinite(v))
            read.fail(read.name(attr->second) + " (POSITION) holds NaN or infinity");
    }
    return pos;
}

// The vertices in drawing order: the indices, each checked against `vertices`, or all of
// them in turn when there are none.
std::vector<std::uint32_t> vertexOrder(const Reader& read, const tinygltf::Primitive& p,
                                       const std::string& where, std::size_t vertices) {
    std::vector<std::uint32_t> order;
    if (p.indices >= 0) {
        order = read.indices(p.indices);
        for (std::uint32_t i : order) {
            if (i >= vertices) {
                read.fail(read.name(p.indices) + " holds index " + std::to_string(i) + " but " +
                          where + " has " + std::to_string(vertices) + " vertices");
            }
        }
    } else {
        order.resize(vertices);
        for (std::size_t i = 0; i < vertices; ++i)
            order[i] = std::uint32_t(i);
    }
    return order;
}

// Triangle list (strips and fans converted, keeping each triangle's winding).
std::vector<std::uint32_t> triangleList(int mode, const std::vector<std::uint32_t>& order) {
    std::vector<std::uint32_t> tri;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        tri.assign(order.begin(), order.end() - std::ptrdiff_t(order.size() % 3));
    } else {
        for (std::size_t i = 2; i < order.size(); ++i) {
            if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
                const bool odd = (i % 2) == 1;
                tri.insert(tri.end(), {order[i - 2], odd ? order[i] : order[i - 1],
                                       odd ? order[i - 1] : order[i]});
            } else {
                tri.insert(tri.end(), {order[0], order[i - 1], order[i]});
            }
        }
    }
    return tri;
}

// The material texture's TEXCOORD_n, NORMAL and COLOR_0 into `a`, their counts checked
// against POSITION's.
void readAttributes(Context& cx, const tinygltf::Primitive& p, const std::string& where,
                    std::size_t vertices, Attributes& a) {
    const Reader& read = cx.read;
    auto normalAttr = p.attributes.find("NORMAL");
    auto colourAttr = p.attributes.find("COLOR_0");
    const int texCoord = p.material >= 0 && std::size_t(p.material) < cx.texCoordOf.size()
                             ? cx.texCoordOf[std::size_t(p.material)]
                             : -1;
    if (texCoord >= 0) {
        const std::string set = "TEXCOORD_" + std::to_string(texCoord);
        auto uvAttr = p.attributes.find(set);
        if (uvAttr == p.attributes.end()) {
            cx.scene.warnings.push_back(where + " has a textured material but no " + set +
                                        ": drawn untextured");
        } else {
            a.uvs = read.floats(uvAttr->second, 2, set.c_str());
            if (a.uvs.size() / 2 != vertices)
                read.fail(where + " has a " + set + " count unlike POSITION's");
            for (float v : a.uvs) {
                if (!std::isfinite(v))
                    read.fail(read.name(uvAttr->second) + " (" + set + ") holds NaN or infinity");
            }
        }
    }
    if (normalAttr != p.attributes.end()) a.normals = read.floats(normalAttr->second, 3, "NORMAL");
    if (colourAttr != p.attributes.end()) a.colours = read.floats(colourAttr->second, 4, "COLOR_0");
    if (!a.normals.empty() && a.normals.size() != a.pos.size())
        read.fail(where + " has a NORMAL count unlike POSITION's");
    if (!a.colours.empty() && a.colours.size() / 4 != vertices)
        read.fail(where + " has a COLOR_0 count unlike POSITION's");
}

glm::vec3 position(const Attributes& a, std::uint32_t i) {
    return glm::vec3(a.pos[3 * i], a.pos[3 * i + 1], a.pos[3 * i + 2]);
}

// With normals: the vertices are kept and shared (normals made unit length).
void sharedVertices(const Attributes& a, std::size_t vertices, Mesh& mesh) {
    const std::vector<float>&normals = a.normals, &colours = a.colours, &uvs = a.uvs;
    mesh.positions.resize(vertices);
    mesh.normals.resize(vertices);
    for (std::uint32_t k = 0; k < vertices; ++k) {
        mesh.positions[k] = position(a, k);
        const glm::vec3 nk(normals[3 * k], normals[3 * k + 1], normals[3 * k + 2]);
        const float len = glm::length(nk);
        mesh.normals[k] = len > 0.0f && std::isfinite(len) ? nk / len : glm::vec3(0, 1, 0);
    }
    if (!colours.empty()) {
        mesh.colours.resize(vertices);
        for (std::uint32_t k = 0; k < vertices; ++k)
            mesh.colours[k] = glm::vec3(colours[4 * k], colours[4 * k + 1], colours[4 * k + 2]);
    }
    if (!uvs.empty()) {
        mesh.uvs.resize(vertices);
        for (std::uint32_t k = 0; k < vertices; ++k)
            mesh.uvs[k] = glm::vec2(uvs[2 * k], uvs[2 * k + 1]);
    }
}

// The triangles of `tri` into `mesh` (winding reversed when `flipped`), zero-area ones
// counted in cx.zeroArea and skipped; `flat`: each triangle gets its own three vertices.
void addTriangles(Context& cx, const Attributes& attrs, const std::vector<std::uint32_t>& tri,
                  bool flipped, bool flat, Mesh& mesh) {
    const std::vector<float>&colours = attrs.colours, &uvs = attrs.uvs;
    for (std::size_t t = 0; t + 2 < tri.size(); t += 3) {
        std::uint32_t v[3] = {tri[t], tri[t + 1], tri[t + 2]};
        if (flipped) std::swap(v[1], v[2]);
        const glm::vec3 a = position(attrs, v[0]), b = position(attrs, v[1]),
                        c = position(attrs, v[2]);
        const glm::vec3 n = glm::cross(b - a, c - a);
        if (!(glm::length(n) > 0.0f)) {
            ++cx.zeroArea;
            continue;
        }
        if (!flat) {
            mesh.indices.insert(mesh.indices.end(), {v[0], v[1], v[2]});
            continue;
        }
        for (std::uint32_t k : v) {
            mesh.positions.push_back(position(attrs, k));
            mesh.normals.push_back(glm::normalize(n));
            if (!colours.empty()) {
                mesh.colours.push_back(
                    glm::vec3(colours[4 * k], colours[4 * k + 1], colours[4 * k + 2]));
            }
            if (!uvs.empty()) mesh.uvs.push_back(glm::vec2(uvs[2 * k], uvs[2 * k + 1]));
            mesh.indices.push_back(std::uint32_t(mesh.indices.size()));
        }
    }
}

}  // namespace

std::int64_t primitiveMesh(Context& cx, int meshIndex, int primIndex, bool flipped) {
    const auto key = std::make_tuple(meshIndex, primIndex, flipped);
    if (auto it = cx.meshOf.find(key); it != cx.meshOf.end()) return it->second;
    const tinygltf::Primitive& p =
        cx.model.meshes[std::size_t(meshIndex)].primitives[std::size_t(primIndex)];
    const std::string where =
        "meshes[" + std::to_string(meshIndex) + "].primitives[" + std::to_string(primIndex) + "]";
    if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        p.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        cx.scene.warnings.push_back(where + " draws points or lines: ignored");
        return -1;
    }
    Attributes a;
    a.pos = readPositions(cx.read, p, where);
    const std::size_t vertices = a.pos.size() / 3;
    const std::vector<std::uint32_t> tri =
        triangleList(p.mode, vertexOrder(cx.read, p, where, vertices));
    Mesh mesh;
    mesh.name = cx.model.meshes[std::size_t(meshIndex)].name + "/" + std::to_string(primIndex);
    readAttributes(cx, p, where, vertices, a);
    // Without normals: flat ones, one per triangle (its vertices are split); with them,
    // the vertices are kept and shared.
    const bool flat = a.normals.empty();
    if (flat) cx.scene.warnings.push_back(where + " has no normals: flat ones generated");
    if (!flat) sharedVertices(a, vertices, mesh);
    addTriangles(cx, a, tri, flipped, flat, mesh);
    if (mesh.indices.empty()) return -1;
    cx.scene.meshes.push_back(std::move(mesh));
    cx.meshOf[key] = std::uint32_t(cx.scene.meshes.size() - 1);
    return std::int64_t(cx.scene.meshes.size() - 1);
}

// The nodes MSFT_lod names as nodes[n]'s coarser versions, finest first (material LODs
// change no shadow and are not read). A version whose mesh does not split into the same
// primitives is left out with a warning: each primitive's version stands in for it alone.
std::vector<int> lodNodes(Context& cx, int n, const tinygltf::Node& node) {
    std::vector<int> out;
    auto it = node.extensions.find("MSFT_lod");
    if (it == node.extensions.end() || !it->second.IsObject() || !it->second.Has("ids")) return out;
    const tinygltf::Value& ids = it->second.Get("ids");
    const std::string where = "nodes[" + std::to_string(n) + "] MSFT_lod";
    for (std::size_t i = 0; ids.IsArray() && i < ids.ArrayLen(); ++i) {
        const tinygltf::Value& id = ids.Get(int(i));
        const int lod = id.IsInt()      ? id.Get<int>()
                        : id.IsNumber() ? int(id.GetNumberAsDouble())
                                        : -1;
        if (lod < 0 || std::size_t(lod) >= cx.model.nodes.size() ||
            std::size_t(cx.model.nodes[std::size_t(lod)].mesh) >= cx.model.meshes.size()) {
            cx.read.fail(where + " names nodes[" + std::to_string(lod) +
                         "], which does not exist or has no mesh");
        }
        const std::size_t parts =
            cx.model.meshes[std::size_t(cx.model.nodes[std::size_t(lod)].mesh)].primitives.size();
        if (parts != cx.model.meshes[std::size_t(node.mesh)].primitives.size()) {
            cx.scene.warnings.push_back(where + ": nodes[" + std::to_string(lod) + "]'s mesh has " +
                                        std::to_string(parts) +
                                        " primitives, not the node's: left out");
            continue;
        }
        out.push_back(lod);
    }
    return out;
}

MeshLod primitiveLod(Context& cx, int meshIndex, int primIndex, bool flipped,
                     const glm::mat4& toModel) {
    const tinygltf::Primitive& p =
        cx.model.meshes[std::size_t(meshIndex)].primitives[std::size_t(primIndex)];
    const std::string where =
        "meshes[" + std::to_string(meshIndex) + "].primitives[" + std::to_string(primIndex) + "]";
    MeshLod lod;
    if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        p.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        return lod;
    }
    const std::vector<float> pos = readPositions(cx.read, p, where);
    const std::size_t vertices = pos.size() / 3;
    const std::vector<std::uint32_t> tri =
        triangleList(p.mode, vertexOrder(cx.read, p, where, vertices));
    for (std::size_t v = 0; v < vertices; ++v) {
        const glm::vec4 m = toModel * glm::vec4(pos[3 * v], pos[3 * v + 1], pos[3 * v + 2], 1.0f);
        const glm::vec3 p3 = glm::vec3(m) / m.w;
        if (!std::isfinite(p3.x) || !std::isfinite(p3.y) || !std::isfinite(p3.z)) {
            // A node scaled to nothing has no model space to take the version into.
            cx.scene.warnings.push_back(where + ": an MSFT_lod version that its node's " +
                                        "transform cannot take into the mesh's space: left out");
            return {};
        }
        lod.positions.push_back(p3);
    }
    for (std::size_t t = 0; t + 2 < tri.size(); t += 3) {
        lod.indices.insert(lod.indices.end(), {tri[t], flipped ? tri[t + 2] : tri[t + 1],
                                               flipped ? tri[t + 1] : tri[t + 2]});
    }
    return lod;
}

}  // namespace gnomon::gltf
